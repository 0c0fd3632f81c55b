/* The shared request/reply exchanges (protocol/test-vectors.json "exchanges") against the real firmware:
 * every status byte the module sends, error codes included, must match the vector byte for byte. */
#include <stdlib.h>

#include "rcfw_host.h"
#include "test_vectors_gen.h"
#include "tf.h"

static int run_exchange(const tv_exchange *x)
{
    const uint8_t ids[1] = {1}, motors[1] = {4};
    rcfw_bus *bus = rcfw_bus_create(1, ids, motors);
    int failures = 0;
    for (int s = 0; s < x->step_count; s++) {
        const tv_step *st = &x->steps[s];
        rcfw_bus_write(bus, st->request, st->request_len);
        rcfw_advance_us(bus, 5000);
        uint8_t got[1100];
        int n = rcfw_bus_read(bus, got, sizeof got);
        if (n != st->reply_len || memcmp(got, st->reply, (size_t)n) != 0) {
            fprintf(stderr, "%s step %d: reply of %d bytes differs from the vector (%d bytes):", x->name, s, n,
                    st->reply_len);
            for (int i = 0; i < n; i++) {
                fprintf(stderr, " %02X", got[i]);
            }
            fprintf(stderr, "\n");
            failures++;
        }
    }
    CHECK_EQ(rcfw_bus_collisions(bus), 0);
    rcfw_bus_destroy(bus);
    return failures;
}

static void every_exchange_answers_as_the_vector(void)
{
    CHECK(TV_EXCHANGE_COUNT > 20);
    for (int i = 0; i < TV_EXCHANGE_COUNT; i++) {
        CHECK_EQ(run_exchange(&tv_exchanges[i]), 0);
    }
}

int main(void)
{
    TF_RUN(every_exchange_answers_as_the_vector);
    TF_END();
}
