/* The two-stage bus watchdog: stage 1 (bus_watchdog) holds every motor where it is and latches bit6 (bus hold);
 * stage 2 (bus_watchdog_off) switches the torque off and latches bit3. Out of a hold only by the host's clear;
 * frames during a hold keep stage 2 away; both stages configurable, bounded and in order. */
#include <stdlib.h>

#include "bus_helpers.h"

#define STATUS RCFW_CT_HARDWARE_ERROR_STATUS

static int status_bits(rcfw_bus *bus) { return peek8(bus, 0, STATUS); }

/* Drops the replies that arrived so far (write_ack expects only its own). */
static void drain(rcfw_bus *bus)
{
    uint8_t buf[256];
    while (rcfw_bus_read(bus, buf, sizeof buf) > 0) {
    }
}

/* One module (ID 1, 4 motors), watchdog stages at stage1_ms / stage2_ms (stage 2 0: single stage; stage 1 over
 * 2 ms), motor 0 driven toward goal, its model (mm, set here) run for run_ms with a frame every 2 ms (the host
 * alive). */
static rcfw_bus *driven(uint16_t stage1_ms, uint16_t stage2_ms, int32_t goal, motor_model *mm, int run_ms)
{
    *mm = (motor_model){0, 0, 4000, 0.01, 3};
    rcfw_bus *bus = make_bus(1);
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_BUS_WATCHDOG_OFF, &stage2_ms, 2), 0);
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_BUS_WATCHDOG, &stage1_ms, 2), 0);
    uint8_t one = 1;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_TORQUE_ENABLE, &one, 1), 0);
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_GOAL_POSITION, &goal, 4), 0);
    for (int t = 0; t < run_ms; t += 2) {
        send_frame(bus, 1, RCFW_INST_PING, 0, 0);
        simulate(bus, 0, 0, mm, 2);
        drain(bus);
    }
    send_frame(bus, 1, RCFW_INST_PING, 0, 0); /* the host's last frame: silence from here on */
    return bus;
}

/* driven(), then silent_ms of silence with the model running: by then the module must be holding. */
static rcfw_bus *holding(uint16_t stage1_ms, uint16_t stage2_ms, int32_t goal, motor_model *mm, int run_ms, int silent_ms)
{
    rcfw_bus *bus = driven(stage1_ms, stage2_ms, goal, mm, run_ms);
    simulate(bus, 0, 0, mm, silent_ms);
    CHECK_EQ(status_bits(bus), RCFW_HWERR_BUS_HOLD);
    drain(bus);
    return bus;
}

static void hold_after_bus_watchdog(void)
{
    motor_model mm;
    rcfw_bus *bus = driven(30, 200, 1000000, &mm, 100); /* far goal: still moving when the host stops */
    simulate(bus, 0, 0, &mm, 29);
    CHECK_EQ(status_bits(bus), 0);
    CHECK(peek32(bus, 0, RCFW_CT_GOAL_POSITION) == 1000000);
    simulate(bus, 0, 0, &mm, 2);
    /* stage 1: holding, not tripped; the motor is still driven */
    CHECK_EQ(status_bits(bus), RCFW_HWERR_BUS_HOLD);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_TORQUE_ENABLE), 1);
    CHECK_EQ(rcfw_get_driver_enable(bus, 0, 0), 1);
    /* its goal is where it was when the hold began, not the host's */
    int32_t held = peek32(bus, 0, RCFW_CT_GOAL_POSITION);
    CHECK(held > 0 && held < 1000000);
    CHECK(abs(held - rcfw_get_position(bus, 0, 0)) < 40);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_PRESENT_SETPOINT), held); /* not the setpoint that led the motor */
    simulate(bus, 0, 0, &mm, 100);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_GOAL_POSITION), held);
    CHECK(abs(rcfw_get_position(bus, 0, 0) - held) < 40); /* stopped and held there by the P loop */
    CHECK(abs(rcfw_get_pwm(bus, 0, 0)) < 60);
    CHECK_EQ(status_bits(bus), RCFW_HWERR_BUS_HOLD);
    rcfw_bus_destroy(bus);
}

static void torque_off_after_the_second_stage(void)
{
    motor_model mm;
    rcfw_bus *bus = driven(30, 200, 1000000, &mm, 50);
    rcfw_advance_us(bus, 199800);
    CHECK_EQ(status_bits(bus), RCFW_HWERR_BUS_HOLD);
    CHECK_EQ(rcfw_get_driver_enable(bus, 0, 0), 1);
    rcfw_advance_us(bus, 400);
    CHECK_EQ(status_bits(bus), RCFW_HWERR_BUS_HOLD | RCFW_HWERR_BUS_WATCHDOG);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_TORQUE_ENABLE), 0);
    CHECK_EQ(rcfw_get_driver_enable(bus, 0, 0), 0);
    CHECK_EQ(rcfw_get_pwm(bus, 0, 0), 0);
    /* as a single-stage trip: torque refused until the host clears */
    drain(bus);
    uint8_t one = 1, zero = 0;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_TORQUE_ENABLE, &one, 1), RCFW_ERR_ALERT | RCFW_ERR_RESULT_FAIL);
    CHECK_EQ(write_ack(bus, 1, STATUS, &zero, 1), 0);
    CHECK_EQ(status_bits(bus), 0);
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_TORQUE_ENABLE, &one, 1), 0);
    rcfw_bus_destroy(bus);
}

static void no_motion_out_of_hold_before_the_acknowledgement(void)
{
    motor_model mm;
    rcfw_bus *bus = holding(20, 500, 300, &mm, 200, 25); /* arrived at 300 */
    int32_t held = peek32(bus, 0, RCFW_CT_GOAL_POSITION);
    /* the host is back: every write that would move a motor is refused, whatever carries it */
    int32_t far = 5000;
    int16_t pwm = 100;
    uint8_t one = 1;
    const uint8_t refused = RCFW_ERR_ALERT | RCFW_ERR_RESULT_FAIL;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_GOAL_POSITION, &far, 4), refused);
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_GOAL_PWM, &pwm, 2), refused);
    CHECK_EQ(write_ack(bus, 1, (uint16_t)(RCFW_CT_TORQUE_ENABLE + 1u), &one, 1), refused);
    uint8_t goals[16] = {0};
    memcpy(goals, &far, 4);
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_GOAL_POSITION, goals, 16), refused);
    const uint8_t sync[] = {(uint8_t)RCFW_CT_GOAL_POSITION, (uint8_t)(RCFW_CT_GOAL_POSITION >> 8), 4, 0,
                            1, 0x88, 0x13, 0, 0}; /* SYNC WRITE goal 5000: no reply to refuse it */
    send_frame(bus, RCFW_ID_BROADCAST, RCFW_INST_SYNC_WRITE, sync, sizeof sync);
    uint8_t reg[6] = {(uint8_t)RCFW_CT_GOAL_POSITION, (uint8_t)(RCFW_CT_GOAL_POSITION >> 8), 0x88, 0x13, 0, 0};
    send_frame(bus, 1, RCFW_INST_REG_WRITE, reg, sizeof reg);
    simulate(bus, 0, 0, &mm, 50);
    drain(bus);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_GOAL_POSITION), held);
    CHECK(abs(rcfw_get_position(bus, 0, 0) - held) < 10);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_TORQUE_ENABLE + 1), 0);
    /* frames kept coming: stage 2 did not come */
    CHECK_EQ(status_bits(bus), RCFW_HWERR_BUS_HOLD);
    /* the acknowledgement: the bit clears, the motor stays where it held until a new goal comes */
    uint8_t zero = 0;
    CHECK_EQ(write_ack(bus, 1, STATUS, &zero, 1), 0);
    CHECK_EQ(status_bits(bus), 0);
    simulate(bus, 0, 0, &mm, 10);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_GOAL_POSITION), held);
    CHECK(abs(rcfw_get_position(bus, 0, 0) - held) < 10);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_PRESENT_SETPOINT), held);
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_GOAL_POSITION, &far, 4), 0);
    simulate(bus, 0, 0, &mm, 5);
    CHECK(peek32(bus, 0, RCFW_CT_PRESENT_SETPOINT) > held);
    rcfw_bus_destroy(bus);
}

static void clear_instruction_acknowledges_a_hold_too(void)
{
    motor_model mm;
    rcfw_bus *bus = holding(10, 100, 300, &mm, 50, 15);
    const uint8_t clear[5] = {0x02, 0x44, 0x58, 0x4C, 0x22};
    send_frame(bus, 1, RCFW_INST_CLEAR, clear, 5);
    rcfw_advance_us(bus, 100);
    CHECK_EQ(status_bits(bus), 0);
    rcfw_bus_destroy(bus);
}

static void frames_during_a_hold_keep_stage_two_away(void)
{
    motor_model mm;
    rcfw_bus *bus = holding(30, 100, 300, &mm, 50, 35);
    /* 500 ms of frames, 60 ms apart: each one longer than stage 1, the whole far longer than stage 2 */
    for (int i = 0; i < 9; i++) {
        send_frame(bus, 1, RCFW_INST_PING, 0, 0);
        simulate(bus, 0, 0, &mm, 60);
        drain(bus);
    }
    CHECK_EQ(status_bits(bus), RCFW_HWERR_BUS_HOLD); /* still holding (only the host's clear ends it), not off */
    CHECK_EQ(rcfw_get_driver_enable(bus, 0, 0), 1);
    /* a frame for another module is not the host talking to this one */
    send_frame(bus, 1, RCFW_INST_PING, 0, 0);
    rcfw_advance_us(bus, 60000);
    send_frame(bus, 7, RCFW_INST_PING, 0, 0);
    rcfw_advance_us(bus, 39800);
    CHECK_EQ(status_bits(bus) & RCFW_HWERR_BUS_WATCHDOG, 0);
    rcfw_advance_us(bus, 400);
    CHECK(status_bits(bus) & RCFW_HWERR_BUS_WATCHDOG);
    CHECK_EQ(rcfw_get_driver_enable(bus, 0, 0), 0);
    rcfw_bus_destroy(bus);
}

static void stage_two_zero_is_the_single_stage_watchdog(void)
{
    motor_model mm;
    rcfw_bus *bus = driven(30, 0, 300, &mm, 50);
    rcfw_advance_us(bus, 29800);
    CHECK_EQ(status_bits(bus), 0);
    rcfw_advance_us(bus, 400);
    CHECK_EQ(status_bits(bus), RCFW_HWERR_BUS_WATCHDOG); /* no hold: torque off at once, as before */
    CHECK_EQ(rcfw_get_driver_enable(bus, 0, 0), 0);
    rcfw_bus_destroy(bus);
}

static void both_stages_are_configurable(void)
{
    const uint16_t stages[3][2] = {{5, 8}, {10, 60}, {250, 1000}};
    for (int k = 0; k < 3; k++) {
        motor_model mm;
        rcfw_bus *bus = driven(stages[k][0], stages[k][1], 300, &mm, 20);
        rcfw_advance_us(bus, stages[k][0] * 1000u - 200u);
        CHECK_EQ(status_bits(bus), 0);
        rcfw_advance_us(bus, 400);
        CHECK_EQ(status_bits(bus), RCFW_HWERR_BUS_HOLD);
        rcfw_advance_us(bus, (stages[k][1] - stages[k][0]) * 1000u - 400u);
        CHECK_EQ(status_bits(bus), RCFW_HWERR_BUS_HOLD);
        rcfw_advance_us(bus, 400);
        CHECK_EQ(status_bits(bus), RCFW_HWERR_BUS_HOLD | RCFW_HWERR_BUS_WATCHDOG);
        rcfw_bus_destroy(bus);
    }
}

static int table_write16(rcfw_bus *bus, uint16_t addr, uint16_t v)
{
    uint8_t b[2] = {(uint8_t)v, (uint8_t)(v >> 8)};
    return rcfw_table_write(bus, 0, addr, b, 2);
}

static void both_stages_are_bounded_and_in_order(void)
{
    rcfw_bus *bus = make_bus(1);
    const rcfw_ct_field *off = &rcfw_ct_fields[RCFW_CT_FIELD_BUS_WATCHDOG_OFF];
    CHECK_EQ(off->min, 0);
    CHECK_EQ(off->max, rcfw_ct_fields[RCFW_CT_FIELD_BUS_WATCHDOG].max);
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG_OFF, (uint16_t)(off->max + 1)), RCFW_ERR_DATA_RANGE);
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG, 30), 0);
    /* stage 2 must come after stage 1 (as the write leaves them): data limit error, nothing changes */
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG_OFF, 30), RCFW_ERR_DATA_LIMIT);
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG_OFF, 29), RCFW_ERR_DATA_LIMIT);
    CHECK_EQ(peek16(bus, 0, RCFW_CT_BUS_WATCHDOG_OFF), 0);
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG_OFF, 31), 0);
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG, 31), RCFW_ERR_DATA_LIMIT);
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG, 60000), RCFW_ERR_DATA_LIMIT);
    CHECK_EQ(peek16(bus, 0, RCFW_CT_BUS_WATCHDOG), 30);
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG, 20), 0);
    /* 0 is allowed for either: stage 2 0 = single stage, stage 1 0 = watchdog off (both stages) */
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG, 0), 0);
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG_OFF, 0), 0);
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG, 60000), 0);
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG_OFF, 60000), RCFW_ERR_DATA_LIMIT);
    rcfw_bus_destroy(bus);
}

static void watchdog_off_switches_off_both_stages(void)
{
    rcfw_bus *bus = make_bus(1);
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG_OFF, 100), 0);
    uint8_t one = 1;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_TORQUE_ENABLE, &one, 1), 0);
    rcfw_advance_us(bus, 300000);
    CHECK_EQ(status_bits(bus), 0);
    CHECK_EQ(rcfw_get_driver_enable(bus, 0, 0), 1);
    rcfw_bus_destroy(bus);
}

static void a_pwm_mode_motor_holds_its_position(void)
{
    rcfw_bus *bus = make_bus(1);
    uint8_t mode = 1, one = 1;
    int16_t pwm = 120;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_CONTROL_MODE, &mode, 1), 0);
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG_OFF, 100), 0);
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG, 10), 0);
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_GOAL_PWM, &pwm, 2), 0);
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_TORQUE_ENABLE, &one, 1), 0);
    rcfw_advance_us(bus, 5000);
    CHECK_EQ(rcfw_get_pwm(bus, 0, 0), 120);
    rcfw_advance_us(bus, 10000); /* the model does not move: the held position is the present one, PWM 0 */
    CHECK_EQ(status_bits(bus), RCFW_HWERR_BUS_HOLD);
    CHECK_EQ(rcfw_get_pwm(bus, 0, 0), 0);
    CHECK_EQ(peek16(bus, 0, RCFW_CT_GOAL_PWM), 0);
    /* pushed away, it is driven back (position loop, whatever its mode), also after a write during the hold has
     * re-read the parameters */
    for (int k = 0; k < 30; k++) {
        rcfw_set_hall(bus, 0, 0, hall_fwd[(k + 1) % 6]);
    }
    rcfw_advance_us(bus, 200);
    CHECK(rcfw_get_pwm(bus, 0, 0) < 0);
    CHECK_EQ(table_write16(bus, RCFW_CT_BUS_WATCHDOG, 10), 0);
    rcfw_advance_us(bus, 200);
    CHECK(rcfw_get_pwm(bus, 0, 0) < 0);
    /* acknowledged: PWM mode again, with goal_pwm 0 until the host writes a new one */
    uint8_t zero = 0;
    CHECK_EQ(write_ack(bus, 1, STATUS, &zero, 1), 0);
    rcfw_advance_us(bus, 200);
    CHECK_EQ(rcfw_get_pwm(bus, 0, 0), 0);
    rcfw_bus_destroy(bus);
}

int main(void)
{
    TF_RUN(hold_after_bus_watchdog);
    TF_RUN(torque_off_after_the_second_stage);
    TF_RUN(no_motion_out_of_hold_before_the_acknowledgement);
    TF_RUN(clear_instruction_acknowledges_a_hold_too);
    TF_RUN(frames_during_a_hold_keep_stage_two_away);
    TF_RUN(stage_two_zero_is_the_single_stage_watchdog);
    TF_RUN(both_stages_are_configurable);
    TF_RUN(both_stages_are_bounded_and_in_order);
    TF_RUN(watchdog_off_switches_off_both_stages);
    TF_RUN(a_pwm_mode_motor_holds_its_position);
    TF_END();
}
