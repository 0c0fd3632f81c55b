/* Boundary cases that mutation testing (firmware/tools/mutate.py) showed no other test pinned down: frame length
 * bounds, slew rounding, the current-limit cap's recovery rate, the watchdog period, wrap-around of the FRAM sequence
 * number and the receiver's abandon timeout. Expected values are derived by hand in the comments. */
#include "bus_helpers.h"
#include "rcfw/crc16.h"
#include "rcfw/motor.h"

static rcfw_rx_result feed_header_and_length(rcfw_parser *p, uint16_t len)
{
    const uint8_t head[] = {0xFF, 0xFF, 0xFD, 0x00, 0x01, (uint8_t)len, (uint8_t)(len >> 8)};
    rcfw_rx_result r = RCFW_RX_MORE;
    rcfw_parser_reset(p);
    for (size_t i = 0; i < sizeof head; i++) {
        r = rcfw_parser_feed(p, head[i]);
    }
    return r;
}

static void frame_length_bounds(void)
{
    static rcfw_parser p;
    /* LEN counts instruction + parameters + CRC: at least 3 bytes. */
    CHECK_EQ(feed_header_and_length(&p, 2), RCFW_RX_BAD_LEN);
    CHECK_EQ(feed_header_and_length(&p, 3), RCFW_RX_MORE);
    /* ID + LEN(2) + LEN bytes must fit the receive buffer of RCFW_RX_MAX bytes. */
    CHECK_EQ(feed_header_and_length(&p, RCFW_RX_MAX - 3u), RCFW_RX_MORE);
    CHECK_EQ(feed_header_and_length(&p, RCFW_RX_MAX - 2u), RCFW_RX_BAD_LEN);
    CHECK_EQ(feed_header_and_length(&p, 0xFFFFu), RCFW_RX_BAD_LEN);
}

static void slew_step_rounds_to_nearest(void)
{
    /* step = speed * 2^16 / rate, rounded: 2 * 65536 / 3 = 43690.67 -> 43691; 1 * 65536 / 3 = 21845.33 -> 21845;
     * 1000 * 65536 / 10000 = 6553.6 -> 6554. */
    CHECK_EQ(rcfw_slew_step_q16(2, 3), 43691u);
    CHECK_EQ(rcfw_slew_step_q16(1, 3), 21845u);
    CHECK_EQ(rcfw_slew_step_q16(1000, 10000), 6554u);
}

static void cap_recovers_one_step_per_tick(void)
{
    /* After a current-limit episode the PWM cap grows by `step` per tick: from 100 with step 1, ten ticks give 110. */
    rcfw_motor m;
    memset(&m, 0, sizeof m);
    m.enabled = 1;
    m.mode = RCFW_MODE_POSITION;
    m.kp = 65535;
    m.goal = 100000;
    m.current_limit = 1000;
    m.cap = 100;
    m.pwm = 100;
    for (int t = 0; t < 10; t++) {
        rcfw_motor_tick(&m, 0, 4, 1);
    }
    CHECK_EQ(m.pwm, 110);
    CHECK_EQ(m.cap, 110);
}

static void watchdog_trips_at_its_period(void)
{
    /* 30 ms watchdog at a 10 kHz control rate: 300 ticks of silence after the last addressed frame. */
    const uint8_t ids[1] = {1}, motors[1] = {1};
    rcfw_bus *bus = rcfw_bus_create(1, ids, motors);
    status_t st[2];
    wr16(bus, 1, RCFW_CT_BUS_WATCHDOG, 30);
    wr8(bus, 1, RCFW_CT_TORQUE_ENABLE, 1);
    wr32(bus, 1, RCFW_CT_GOAL_POSITION, 5000);
    collect(bus, 1000, st, 2);
    send_frame(bus, 1, RCFW_INST_PING, 0, 0);
    rcfw_advance_us(bus, 29800);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS) & RCFW_HWERR_BUS_WATCHDOG, 0);
    CHECK_EQ(rcfw_get_driver_enable(bus, 0, 0), 1);
    rcfw_advance_us(bus, 400);
    CHECK(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS) & RCFW_HWERR_BUS_WATCHDOG);
    CHECK_EQ(rcfw_get_driver_enable(bus, 0, 0), 0);
    rcfw_bus_destroy(bus);
}

/* Rewrites a parameter slot's sequence number and its CRC (header 8 bytes: magic, length, sequence; then data; CRC). */
static void set_slot_sequence(rcfw_bus *bus, uint16_t base, uint32_t seq)
{
    uint8_t slot[8 + RCFW_CT_PERSISTENT_END + 2];
    rcfw_fram_peek(bus, 0, base, slot, 8);
    uint16_t len = (uint16_t)(slot[2] | (slot[3] << 8));
    CHECK(len <= RCFW_CT_PERSISTENT_END);
    rcfw_fram_peek(bus, 0, base, slot, (uint16_t)(8u + len));
    memcpy(slot + 4, &seq, 4);
    uint16_t crc = rcfw_crc16(0, slot, (size_t)8u + len);
    slot[8u + len] = (uint8_t)crc;
    slot[9u + len] = (uint8_t)(crc >> 8);
    rcfw_fram_poke(bus, 0, base, slot, (uint16_t)(10u + len));
}

static void fram_sequence_wraps(void)
{
    /* Two parameter copies with sequence numbers 0xFFFFFFFF and 0 (the counter wrapped): 0 is the newer one. */
    const uint8_t ids[1] = {1}, motors[1] = {1};
    rcfw_bus *bus = rcfw_bus_create(1, ids, motors);
    uint16_t newest = write_kp_twice_newest_slot(bus); /* kp 500, then 600 */
    uint16_t older = newest == RCFW_FRAM_PARAMS_A ? RCFW_FRAM_PARAMS_B : RCFW_FRAM_PARAMS_A;
    set_slot_sequence(bus, older, 0xFFFFFFFFu);
    set_slot_sequence(bus, newest, 0u);
    rcfw_power_cycle(bus, 0);
    CHECK_EQ(peek16(bus, 0, RCFW_CT_KP), 600);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS) & RCFW_HWERR_PARAMS_LOST, 0);
    rcfw_bus_destroy(bus);
}

static void truncated_frame_is_abandoned_after_silence(void)
{
    /* A ping cut before its CRC, then silence longer than the receive timeout (RCFW_RX_TIMEOUT_TICKS at 10 kHz):
     * the partial frame is dropped and the next ping is answered. Without the timeout the next ping's first two bytes
     * would complete the partial frame as its CRC, and the rest of that ping would be lost. */
    const uint8_t ids[1] = {1}, motors[1] = {1};
    rcfw_bus *bus = rcfw_bus_create(1, ids, motors);
    status_t st[2];
    const uint8_t partial[] = {0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x03, 0x00, 0x01}; /* a ping to ID 1 without its CRC */
    rcfw_bus_write(bus, partial, sizeof partial);
    rcfw_advance_us(bus, RCFW_RX_TIMEOUT_TICKS * (1000000u / RCFW_CONTROL_RATE_HZ) + 1000u);
    send_frame(bus, 1, RCFW_INST_PING, 0, 0);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK_EQ(st[0].id, 1);
    CHECK_EQ(st[0].error, 0);
    rcfw_bus_destroy(bus);
}

static void stored_goal_is_clamped_to_narrowed_position_limits(void)
{
    /* A goal stored while the limits were wide is clamped when they narrow: with position_min -100 and position_max
     * 100 counts, a stored goal of -100000 drives to -100 and one of +100000 to 100. (A new goal beyond the limits is
     * refused with a data limit error; test_exchanges covers that.) */
    const uint8_t ids[1] = {1}, motors[1] = {1};
    const int32_t goals[2] = {-100000, 100000}, expected[2] = {-100, 100};
    for (int k = 0; k < 2; k++) {
        rcfw_bus *bus = rcfw_bus_create(1, ids, motors);
        wr16(bus, 1, RCFW_CT_SPEED_LIMIT, 0);
        wr32(bus, 1, RCFW_CT_GOAL_POSITION, (uint32_t)goals[k]);
        wr32(bus, 1, RCFW_CT_POSITION_MIN, (uint32_t)-100);
        wr32(bus, 1, RCFW_CT_POSITION_MAX, 100);
        wr8(bus, 1, RCFW_CT_TORQUE_ENABLE, 1);
        rcfw_advance_us(bus, 1000);
        CHECK_EQ((int32_t)peek32(bus, 0, RCFW_CT_PRESENT_SETPOINT), expected[k]);
        rcfw_bus_destroy(bus);
    }
}

static void latched_watchdog_keeps_torque_off_whatever_writes_it(void)
{
    /* After a watchdog trip, torque enable written by SYNC WRITE (no status reply to refuse it) must not drive. */
    const uint8_t ids[1] = {1}, motors[1] = {1};
    rcfw_bus *bus = rcfw_bus_create(1, ids, motors);
    wr16(bus, 1, RCFW_CT_BUS_WATCHDOG, 10);
    wr8(bus, 1, RCFW_CT_TORQUE_ENABLE, 1);
    wr32(bus, 1, RCFW_CT_GOAL_POSITION, 5000);
    rcfw_advance_us(bus, 20000);
    CHECK(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS) & RCFW_HWERR_BUS_WATCHDOG);
    const uint8_t p[] = {(uint8_t)RCFW_CT_TORQUE_ENABLE, (uint8_t)(RCFW_CT_TORQUE_ENABLE >> 8), 1, 0, 1, 1};
    send_frame(bus, RCFW_ID_BROADCAST, RCFW_INST_SYNC_WRITE, p, sizeof p);
    rcfw_advance_us(bus, 1000);
    CHECK_EQ(rcfw_get_driver_enable(bus, 0, 0), 0);
    CHECK_EQ(rcfw_get_pwm(bus, 0, 0), 0);
    rcfw_bus_destroy(bus);
}

int main(void)
{
    TF_RUN(frame_length_bounds);
    TF_RUN(slew_step_rounds_to_nearest);
    TF_RUN(cap_recovers_one_step_per_tick);
    TF_RUN(watchdog_trips_at_its_period);
    TF_RUN(fram_sequence_wraps);
    TF_RUN(truncated_frame_is_abandoned_after_silence);
    TF_RUN(stored_goal_is_clamped_to_narrowed_position_limits);
    TF_RUN(latched_watchdog_keeps_torque_off_whatever_writes_it);
    TF_END();
}
