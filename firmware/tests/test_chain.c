/* SYNC READ and BULK READ replies chained back to back: each module answers when the previous one's status
 * packet has ended (plus its return delay), timed on the simulated wire. */
#include <stdlib.h>

#include "bus_helpers.h"

static rcfw_bus *make3(void)
{
    const uint8_t ids[3] = {1, 2, 3}, motors[3] = {4, 2, 3};
    rcfw_bus *bus = rcfw_bus_create(3, ids, motors);
    CHECK(bus != NULL);
    return bus;
}

/* Advance 1 us at a time until the line is idle; returns the microseconds it took (0 if already idle). */
static uint32_t until_idle(rcfw_bus *bus, uint32_t max_us)
{
    uint32_t t = 0;
    while (rcfw_bus_pending(bus) > 0 && t < max_us) {
        rcfw_advance_us(bus, 1);
        t++;
    }
    return t;
}

static void sync_read_replies_follow_each_other(void)
{
    rcfw_bus *bus = make3();
    status_t st[4];
    /* return delay 5 (10 us) everywhere */
    uint8_t rd = 5;
    for (uint8_t id = 1; id <= 3; id++) {
        CHECK_EQ(write_ack(bus, id, RCFW_CT_RETURN_DELAY_TIME, &rd, 1), 0);
    }
    uint8_t q[7] = {(uint8_t)RCFW_CT_PRESENT_POSITION, 0, 8, 0, 3, 1, 2};
    send_frame(bus, RCFW_ID_BROADCAST, RCFW_INST_SYNC_READ, q, 7);
    /* 17-byte instruction, then 3 x (10 us + 19-byte status) at 10 us per byte, nothing idle in between */
    uint32_t t = until_idle(bus, 100000);
    CHECK_EQ(t, 170u + 3u * (10u + 190u));
    CHECK_EQ(collect(bus, 0, st, 4), 3);
    CHECK_EQ(st[0].id, 3);
    CHECK_EQ(st[1].id, 1);
    CHECK_EQ(st[2].id, 2);
    CHECK_EQ(st[2].len, 8);
    CHECK_EQ(rcfw_bus_collisions(bus), 0);
    rcfw_bus_destroy(bus);
}

static void bulk_read_lengths_per_module(void)
{
    rcfw_bus *bus = make3();
    status_t st[4];
    uint8_t q[15] = {2, 0, 0, 2, 0,                                           /* id 2: model number */
                     1, (uint8_t)RCFW_CT_GOAL_POSITION, 0, 16, 0,             /* id 1: 4 goals */
                     3, (uint8_t)RCFW_CT_ID, 0, 1, 0};                        /* id 3: its id */
    send_frame(bus, RCFW_ID_BROADCAST, RCFW_INST_BULK_READ, q, 15);
    uint32_t t = until_idle(bus, 100000);
    CHECK_EQ(t, (10u + 15u) * 10u + (13u + 27u + 12u) * 10u);
    CHECK_EQ(collect(bus, 0, st, 4), 3);
    CHECK_EQ(st[0].id, 2);
    CHECK_EQ(st[0].data[0] | (st[0].data[1] << 8), 0x4D31);
    CHECK_EQ(st[1].id, 1);
    CHECK_EQ(st[1].len, 16);
    CHECK_EQ(st[2].id, 3);
    CHECK_EQ(st[2].data[0], 3);
    CHECK_EQ(rcfw_bus_collisions(bus), 0);
    rcfw_bus_destroy(bus);
}

static void a_missing_module_stops_the_chain_and_a_new_instruction_ends_the_wait(void)
{
    rcfw_bus *bus = make3();
    status_t st[4];
    uint8_t q[7] = {(uint8_t)RCFW_CT_ID, 0, 1, 0, 1, 9, 2}; /* 9 is not on the bus */
    send_frame(bus, RCFW_ID_BROADCAST, RCFW_INST_SYNC_READ, q, 7);
    CHECK_EQ(collect(bus, 5000, st, 4), 1); /* only id 1; id 2 waits for 9 */
    CHECK_EQ(st[0].id, 1);
    send_frame(bus, 3, RCFW_INST_PING, 0, 0);
    CHECK_EQ(collect(bus, 5000, st, 4), 1);
    CHECK_EQ(st[0].id, 3);
    /* a status of id 9 heard later does not wake id 2 any more */
    uint8_t body[2] = {RCFW_INST_STATUS, 0}, out[16];
    uint16_t n = rcfw_frame_build(out, sizeof out, 9, body, 2);
    rcfw_bus_write(bus, out, n);
    CHECK_EQ(collect(bus, 5000, st, 4), 0); /* id 2 stays silent */
    rcfw_bus_destroy(bus);
}

int main(void)
{
    TF_RUN(sync_read_replies_follow_each_other);
    TF_RUN(bulk_read_lengths_per_module);
    TF_RUN(a_missing_module_stops_the_chain_and_a_new_instruction_ends_the_wait);
    TF_END();
}
