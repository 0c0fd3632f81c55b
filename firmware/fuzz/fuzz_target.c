/* libFuzzer target: arbitrary bytes through the frame parser of a module on the host bus,
 * plus every decoded frame re-injected as a valid frame (fixed CRC) so control-table writes,
 * sync read/write and factory reset are exercised beyond the CRC check.
 * Layout of the input: byte 0 selects how much time passes between chunks; the rest is
 * split at 0xA5 0x5A markers into chunks written to the bus. */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "rcfw/frame.h"
#include "rcfw/module.h"
#include "decoder_invariants.h"
#include "rcfw_host.h"

static void check_invariants(rcfw_bus *bus)
{
    for (int32_t m = 0; m < 2; m++) {
        for (int32_t k = 0; k < (m == 0 ? 4 : 2); k++) {
            int32_t pwm = rcfw_get_pwm(bus, m, k);
            if (pwm > 255 || pwm < -255) {
                __builtin_trap();
            }
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const uint8_t ids[2] = {1, 2};
    static const uint8_t motors[2] = {4, 2};
    rcfw_bus *bus = rcfw_bus_create(2, ids, motors);
    if (!bus || size == 0) {
        rcfw_bus_destroy(bus);
        return 0;
    }
    rcfw_check_decoder_invariants(data, size);
    uint32_t step_us = (uint32_t)(data[0] & 0x0F) * 20u;
    size_t start = 1;
    uint8_t frame[1100];
    uint8_t rx[4096];
    for (size_t i = 1; i <= size; i++) {
        int end = i == size || (i + 1 < size && data[i] == 0xA5 && data[i + 1] == 0x5A);
        if (!end) {
            continue;
        }
        size_t n = i - start;
        /* raw bytes */
        rcfw_bus_write(bus, data + start, (int32_t)n);
        /* the same bytes as the body of a valid frame: id = first byte */
        if (n >= 2 && n < 1000) {
            uint16_t fl = rcfw_frame_build(frame, sizeof frame, data[start], data + start + 1, (uint16_t)(n - 1));
            if (fl) {
                rcfw_bus_write(bus, frame, fl);
            }
        }
        rcfw_advance_us(bus, step_us);
        (void)rcfw_bus_read(bus, rx, sizeof rx);
        check_invariants(bus);
        start = i + 2;
        i++;
    }
    rcfw_advance_us(bus, 300);
    (void)rcfw_bus_read(bus, rx, sizeof rx);
    check_invariants(bus);
    rcfw_bus_destroy(bus);
    return 0;
}
