/* Every instruction through the host bus, broadcast rules, malformed frames, watchdog and reset cause (homing and
 * resume after power loss: test_homing.c). */
#include "bus_helpers.h"
#include "test_vectors_gen.h"

static void ping_and_timing(void)
{
    rcfw_bus *bus = make_bus(1);
    status_t st[4];
    wr8(bus, 1, RCFW_CT_RETURN_DELAY_TIME, 50); /* 100 us */
    CHECK_EQ(collect(bus, 2000, st, 4), 1);
    send_frame(bus, 1, RCFW_INST_PING, 0, 0); /* 10 bytes = 100 us at 1 Mbaud */
    /* reply starts at 100 + 100 us; 14 bytes take 140 us */
    uint8_t buf[64];
    rcfw_advance_us(bus, 195);
    CHECK_EQ(rcfw_bus_read(bus, buf, sizeof buf), 0);
    CHECK_EQ(rcfw_get_tx_enable(bus, 0), 0);
    rcfw_advance_us(bus, 75);
    CHECK_EQ(rcfw_get_tx_enable(bus, 0), 1);
    CHECK_EQ(rcfw_bus_read(bus, buf, sizeof buf), 7);
    CHECK_EQ(rcfw_bus_pending(bus), 7);
    rcfw_advance_us(bus, 70);
    CHECK_EQ(rcfw_bus_read(bus, buf + 7, sizeof buf - 7), 7);
    CHECK_EQ(rcfw_get_tx_enable(bus, 0), 0);
    const uint8_t expect[] = {0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x07, 0x00, 0x55, 0x00, 0x31, 0x4D,
                              (uint8_t)rcfw_ct_fields[RCFW_CT_FIELD_FIRMWARE_VERSION].def};
    CHECK(memcmp(buf, expect, sizeof expect) == 0);
    /* wrong ID: silence */
    send_frame(bus, 9, RCFW_INST_PING, 0, 0);
    CHECK_EQ(collect(bus, 5000, st, 4), 0);
    rcfw_bus_destroy(bus);
}

static void broadcast_ping_staggered(void)
{
    rcfw_bus *bus = make_bus(3);
    status_t st[4];
    send_frame(bus, RCFW_ID_BROADCAST, RCFW_INST_PING, 0, 0);
    CHECK_EQ(collect(bus, 5000, st, 4), 3);
    CHECK_EQ(st[0].id, 1);
    CHECK_EQ(st[1].id, 2);
    CHECK_EQ(st[2].id, 3);
    CHECK_EQ(st[2].len, 3);
    CHECK_EQ(rcfw_bus_collisions(bus), 0);
    rcfw_bus_destroy(bus);
}

static void read_write(void)
{
    rcfw_bus *bus = make_bus(1);
    status_t st[2];
    uint8_t p[4] = {0, 0, 3, 0}; /* read 0..2: model number, motor count */
    send_frame(bus, 1, RCFW_INST_READ, p, 4);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK_EQ(st[0].error, 0);
    CHECK_EQ(st[0].len, 3);
    CHECK_EQ(st[0].data[0] | (st[0].data[1] << 8), 0x4D31);
    CHECK_EQ(st[0].data[2], 4); /* motor count */
    uint8_t p6[4] = {6, 0, 3, 0}; /* 6..8: firmware version, id, baud */
    send_frame(bus, 1, RCFW_INST_READ, p6, 4);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK_EQ(st[0].error, 0);
    CHECK_EQ(st[0].data[0], rcfw_ct_fields[RCFW_CT_FIELD_FIRMWARE_VERSION].def);
    CHECK_EQ(st[0].data[1], 1); /* id */
    CHECK_EQ(st[0].data[2], 3); /* baud code */
    /* a read over unmapped bytes (3..5) is an access error, with the requested length of zero bytes (as a
     * ROBOTIS device answers: a master reading the data without looking at the error finds its length) */
    uint8_t gap[4] = {0, 0, 10, 0};
    send_frame(bus, 1, RCFW_INST_READ, gap, 4);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK_EQ(st[0].error, RCFW_ERR_ACCESS);
    CHECK_EQ(st[0].len, 10);
    for (int i = 0; i < 10; i++) {
        CHECK_EQ(st[0].data[i], 0);
    }
    /* longer than the whole table: no reply could carry it, the error alone */
    uint8_t huge[4] = {0, 0, 0x49, 0x01}; /* 329 bytes */
    send_frame(bus, 1, RCFW_INST_READ, huge, 4);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK_EQ(st[0].error, RCFW_ERR_ACCESS);
    CHECK_EQ(st[0].len, 0);
    /* ACTION with nothing registered: instruction error (the e-Manual's error table) */
    send_frame(bus, 1, RCFW_INST_ACTION, 0, 0);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK_EQ(st[0].error, RCFW_ERR_INSTRUCTION);
    /* write and read back a persistent value */
    uint16_t kp = 777;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_KP + 2 * RCFW_CT_KP_STRIDE, &kp, 2), 0);
    CHECK_EQ(peek16(bus, 0, RCFW_CT_KP + 2 * RCFW_CT_KP_STRIDE), 777);
    /* errors: read out of range, bad read length, read-only, unmapped, over the limit */
    uint8_t r1[4] = {0x40, 0x01, 10, 0}; /* 320 + 10 > 328: past the table */
    send_frame(bus, 1, RCFW_INST_READ, r1, 4);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK_EQ(st[0].error, RCFW_ERR_ACCESS);
    send_frame(bus, 1, RCFW_INST_READ, r1, 3);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK_EQ(st[0].error, RCFW_ERR_DATA_LENGTH);
    uint16_t model = 1;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_MODEL_NUMBER, &model, 2), RCFW_ERR_ACCESS);
    CHECK_EQ(peek16(bus, 0, 0), 0x4D31);
    uint8_t x = 5;
    CHECK_EQ(write_ack(bus, 1, 3, &x, 1), RCFW_ERR_ACCESS);
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_PRESENT_POSITION, &x, 1), RCFW_ERR_ACCESS);
    uint8_t id = 253;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_ID, &id, 1), RCFW_ERR_DATA_RANGE);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_ID), 1);
    int16_t pwm = 300;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_GOAL_PWM, &pwm, 2), RCFW_ERR_DATA_RANGE);
    /* a write spanning a good and a read-only field changes nothing */
    uint8_t span[3] = {9, 9, 9}; /* 6 (fw, R), 7 (id), 8 (baud) */
    CHECK_EQ(write_ack(bus, 1, 6, span, 3), RCFW_ERR_ACCESS);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_ID), 1);
    /* write without data */
    uint8_t only_addr[2] = {7, 0};
    send_frame(bus, 1, RCFW_INST_WRITE, only_addr, 2);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK_EQ(st[0].error, RCFW_ERR_DATA_LENGTH);
    /* unknown instruction */
    send_frame(bus, 1, 0x55 + 1, 0, 0);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK_EQ(st[0].error, RCFW_ERR_INSTRUCTION);
    /* changing the ID: the module answers to the new one */
    id = 42;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_ID, &id, 1), 0);
    send_frame(bus, 42, RCFW_INST_PING, 0, 0);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK_EQ(st[0].id, 42);
    rcfw_bus_destroy(bus);
}

static void broadcast_no_reply(void)
{
    rcfw_bus *bus = make_bus(3);
    status_t st[4];
    wr32(bus, RCFW_ID_BROADCAST, RCFW_CT_GOAL_POSITION, 1234);
    CHECK_EQ(collect(bus, 20000, st, 4), 0);
    for (int m = 0; m < 3; m++) {
        CHECK_EQ(peek32(bus, m, RCFW_CT_GOAL_POSITION), 1234);
    }
    uint8_t read[4] = {0, 0, 2, 0};
    send_frame(bus, RCFW_ID_BROADCAST, RCFW_INST_READ, read, 4);
    CHECK_EQ(collect(bus, 20000, st, 4), 0);
    send_frame(bus, RCFW_ID_BROADCAST, RCFW_INST_REBOOT, 0, 0);
    CHECK_EQ(collect(bus, 20000, st, 4), 0);
    for (int m = 0; m < 3; m++) {
        CHECK_EQ(peek8(bus, m, RCFW_CT_RESET_CAUSE), RCFW_CAUSE_SOFTWARE);
    }
    uint8_t fr = 0x02;
    send_frame(bus, RCFW_ID_BROADCAST, RCFW_INST_FACTORY_RESET, &fr, 1);
    CHECK_EQ(collect(bus, 20000, st, 4), 0);
    CHECK_EQ(rcfw_bus_collisions(bus), 0);
    rcfw_bus_destroy(bus);
}

static void sync_write_and_sync_read(void)
{
    rcfw_bus *bus = make_bus(2);
    status_t st[4];
    /* one SYNC WRITE of all four goals of module 1 and two (+2 unused) of module 2 */
    uint8_t p[4 + 2 * 17];
    p[0] = (uint8_t)RCFW_CT_GOAL_POSITION;
    p[1] = 0;
    p[2] = 16;
    p[3] = 0;
    for (int m = 0; m < 2; m++) {
        uint8_t *g = p + 4 + 17 * m;
        g[0] = (uint8_t)(m + 1);
        for (int k = 0; k < 4; k++) {
            int32_t v = (m + 1) * 1000 + k;
            memcpy(g + 1 + 4 * k, &v, 4);
        }
    }
    send_frame(bus, RCFW_ID_BROADCAST, RCFW_INST_SYNC_WRITE, p, sizeof p);
    CHECK_EQ(collect(bus, 2000, st, 4), 0);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_GOAL_POSITION + 3 * 4), 1003);
    CHECK_EQ(peek32(bus, 1, RCFW_CT_GOAL_POSITION + 4), 2001);
    /* torque on everywhere, then one SYNC READ of the feedback block of both modules */
    uint8_t on[4] = {1, 1, 1, 1};
    wr(bus, 1, RCFW_CT_TORQUE_ENABLE, on, 4);
    collect(bus, 2000, st, 4);
    wr(bus, 2, RCFW_CT_TORQUE_ENABLE, on, 2);
    collect(bus, 2000, st, 4);
    rcfw_set_hall(bus, 0, 2, 3); /* module 1 motor 2 one step forward */
    rcfw_advance_us(bus, 200);   /* published to the table at the next tick */
    uint8_t q[6] = {(uint8_t)RCFW_CT_PRESENT_POSITION, 0, 32, 0, 2, 1}; /* order: id 2 then id 1 */
    send_frame(bus, RCFW_ID_BROADCAST, RCFW_INST_SYNC_READ, q, 6);
    CHECK_EQ(collect(bus, 5000, st, 4), 2);
    CHECK_EQ(st[0].id, 2);
    CHECK_EQ(st[1].id, 1);
    CHECK_EQ(st[1].len, 32);
    int32_t pos2;
    memcpy(&pos2, st[1].data + 16, 4);
    CHECK_EQ(pos2, 1);
    int16_t pwm0;
    memcpy(&pwm0, st[1].data + 6, 2);
    CHECK(pwm0 > 0); /* toward goal 1000 (setpoint slewing at the speed limit) */
    CHECK_EQ(rcfw_bus_collisions(bus), 0);
    /* sync write with a ragged length is dropped entirely */
    uint8_t bad[4 + 5 + 3] = {(uint8_t)RCFW_CT_GOAL_POSITION, 0, 4, 0, 1, 9, 9, 9, 9, 2, 9, 9};
    send_frame(bus, RCFW_ID_BROADCAST, RCFW_INST_SYNC_WRITE, bad, sizeof bad);
    rcfw_advance_us(bus, 1000);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_GOAL_POSITION), 1000);
    /* unicast sync read is not valid */
    send_frame(bus, 1, RCFW_INST_SYNC_READ, q, 6);
    CHECK_EQ(collect(bus, 5000, st, 4), 0);
    rcfw_bus_destroy(bus);
}

static void reboot_and_factory_reset(void)
{
    rcfw_bus *bus = make_bus(1);
    status_t st[2];
    CHECK_EQ(peek8(bus, 0, RCFW_CT_RESET_CAUSE), RCFW_CAUSE_POWER_ON);
    uint16_t kp = 1000;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_KP, &kp, 2), 0);
    uint8_t id = 5, baud = 4;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_ID, &id, 1), 0);
    send_frame(bus, 5, RCFW_INST_REBOOT, 0, 0);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK_EQ(st[0].error, 0);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_RESET_CAUSE), RCFW_CAUSE_SOFTWARE);
    CHECK_EQ(peek16(bus, 0, RCFW_CT_KP), 1000);
    /* baud change: the module follows after its reply */
    CHECK_EQ(write_ack(bus, 5, RCFW_CT_BAUD_RATE, &baud, 1), 0);
    rcfw_advance_us(bus, 1000);
    send_frame(bus, 5, RCFW_INST_PING, 0, 0);
    CHECK_EQ(collect(bus, 2000, st, 2), 0);
    rcfw_bus_set_baud(bus, 2000000);
    send_frame(bus, 5, RCFW_INST_PING, 0, 0);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    /* factory reset keeping ID and baud */
    uint8_t mode = 0x02;
    send_frame(bus, 5, RCFW_INST_FACTORY_RESET, &mode, 1);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK_EQ(st[0].error, 0);
    CHECK_EQ(peek16(bus, 0, RCFW_CT_KP), 256);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_ID), 5);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_BAUD_RATE), 4);
    /* bad mode */
    mode = 0x07;
    send_frame(bus, 5, RCFW_INST_FACTORY_RESET, &mode, 1);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK_EQ(st[0].error, RCFW_ERR_DATA_RANGE);
    /* full reset: back to ID 1 at 1 Mbaud */
    mode = 0xFF;
    send_frame(bus, 5, RCFW_INST_FACTORY_RESET, &mode, 1);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    rcfw_bus_set_baud(bus, 1000000);
    send_frame(bus, 1, RCFW_INST_PING, 0, 0);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    /* reset causes from the port */
    rcfw_reset(bus, 0, RCFW_RESET_BROWN_OUT);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_RESET_CAUSE), RCFW_CAUSE_BROWN_OUT);
    uint8_t zero = 0;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_RESET_CAUSE, &zero, 1), 0);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_RESET_CAUSE), 0);
    rcfw_bus_destroy(bus);
}

static void malformed_frames_have_no_effect(void)
{
    rcfw_bus *bus = make_bus(1);
    status_t st[2];
    uint8_t before[RCFW_CT_SIZE], after[RCFW_CT_SIZE];
    rcfw_advance_us(bus, 1000);
    rcfw_peek_table(bus, 0, 0, before, RCFW_CT_SIZE);
    for (int i = 0; i < TV_COUNT; i++) {
        if (tv_vectors[i].valid) {
            continue;
        }
        rcfw_bus_write(bus, tv_vectors[i].frame, tv_vectors[i].frame_len);
        CHECK_EQ(collect(bus, 3000, st, 2), 0); /* 3 ms: parser timeout clears truncated frames */
    }
    /* a write with a single corrupted byte */
    uint8_t frame[32], body[8] = {RCFW_INST_WRITE, (uint8_t)RCFW_CT_ID, 0, 77};
    uint16_t n = rcfw_frame_build(frame, sizeof frame, 1, body, 4);
    for (int i = 0; i < n; i++) {
        uint8_t c[32];
        memcpy(c, frame, n);
        c[i] ^= 0x10;
        rcfw_bus_write(bus, c, n);
        collect(bus, 3000, st, 2);
        CHECK_EQ(peek8(bus, 0, RCFW_CT_ID), 1);
    }
    /* oversized frame: length beyond the buffer, then a normal ping is still answered */
    uint8_t big[1200];
    memset(big, 0x11, sizeof big);
    big[0] = 0xFF, big[1] = 0xFF, big[2] = 0xFD, big[3] = 0, big[4] = 1, big[5] = 0xB0, big[6] = 0x04;
    rcfw_bus_write(bus, big, sizeof big);
    rcfw_advance_us(bus, 15000); /* 1200 bytes = 12 ms on the line at 1 Mbaud */
    rcfw_peek_table(bus, 0, 0, after, RCFW_CT_SIZE);
    CHECK(memcmp(before, after, RCFW_CT_PERSISTENT_END) == 0);
    CHECK(memcmp(before + RCFW_CT_TORQUE_ENABLE, after + RCFW_CT_TORQUE_ENABLE, 24) == 0);
    send_frame(bus, 1, RCFW_INST_PING, 0, 0);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    rcfw_bus_destroy(bus);
}

static void watchdog_stops_and_latches(void)
{
    rcfw_bus *bus = make_bus(1);
    status_t st[2];
    wr16(bus, 1, RCFW_CT_BUS_WATCHDOG, 50);
    wr8(bus, 1, RCFW_CT_TORQUE_ENABLE, 1);
    wr32(bus, 1, RCFW_CT_GOAL_POSITION, 5000);
    collect(bus, 1000, st, 2);
    /* frames addressed to the module keep it alive */
    for (int i = 0; i < 10; i++) {
        send_frame(bus, 1, RCFW_INST_PING, 0, 0);
        collect(bus, 40000, st, 2);
    }
    /* frames for another ID do not */
    CHECK_EQ(rcfw_get_pwm(bus, 0, 0), 255);
    for (int i = 0; i < 3; i++) {
        send_frame(bus, 7, RCFW_INST_PING, 0, 0);
        rcfw_advance_us(bus, 20000);
    }
    CHECK_EQ(rcfw_get_pwm(bus, 0, 0), 0);
    CHECK_EQ(rcfw_get_driver_enable(bus, 0, 0), 0);
    CHECK(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS) & RCFW_HWERR_BUS_WATCHDOG);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_TORQUE_ENABLE), 0);
    /* latched: status carries the alert bit; torque enable refused until cleared */
    uint8_t one = 1, zero = 0;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_TORQUE_ENABLE, &one, 1), RCFW_ERR_ALERT | RCFW_ERR_RESULT_FAIL);
    rcfw_advance_us(bus, 100000);
    CHECK(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS) & RCFW_HWERR_BUS_WATCHDOG);
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_HARDWARE_ERROR_STATUS, &zero, 1), 0);
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_TORQUE_ENABLE, &one, 1), 0);
    rcfw_advance_us(bus, 1000);
    CHECK(rcfw_get_pwm(bus, 0, 0) > 0);
    CHECK_EQ(rcfw_get_driver_enable(bus, 0, 0), 1);
    /* writing a non-zero error status is refused */
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_HARDWARE_ERROR_STATUS, &one, 1), RCFW_ERR_DATA_RANGE);
    rcfw_bus_destroy(bus);
}

/* pot_raw is the pot's latest reading within 1 ms while running, not only the one taken at reset or homing */
static void pot_raw_follows_the_pot_while_running(void)
{
    rcfw_bus *bus = make_bus(1);
    rcfw_set_pot_raw(bus, 0, 0, 1234);
    rcfw_set_pot_raw(bus, 0, 1, 2345);
    rcfw_advance_us(bus, 1100);
    CHECK_EQ(peek16(bus, 0, RCFW_CT_POT_RAW), 1234);
    CHECK_EQ(peek16(bus, 0, RCFW_CT_POT_RAW + 2), 2345);
    rcfw_set_pot_raw(bus, 0, 0, 0); /* an open wiper */
    rcfw_advance_us(bus, 1100);
    CHECK_EQ(peek16(bus, 0, RCFW_CT_POT_RAW), 0);
    rcfw_bus_destroy(bus);
}

int main(void)
{
    _Static_assert(RCFW_RESET_BROWN_OUT == RCFW_CAUSE_BROWN_OUT && RCFW_RESET_LOCKUP == RCFW_CAUSE_LOCKUP,
                   "host reset causes match the core");
    TF_RUN(ping_and_timing);
    TF_RUN(broadcast_ping_staggered);
    TF_RUN(read_write);
    TF_RUN(broadcast_no_reply);
    TF_RUN(sync_write_and_sync_read);
    TF_RUN(reboot_and_factory_reset);
    TF_RUN(malformed_frames_have_no_effect);
    TF_RUN(watchdog_stops_and_latches);
    TF_RUN(pot_raw_follows_the_pot_while_running);
    TF_END();
}
