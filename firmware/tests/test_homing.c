/* Homing through the bus: homing and resume after power loss, and the home request per motor (shared test vectors). */
#include "bus_helpers.h"
#include "test_vectors_gen.h"

static void homing_and_resume(void)
{
    rcfw_bus *bus = make_bus(1);
    /* non-linear pot of motor 0: 5 points, 1000 counts apart */
    const uint16_t raw[5] = {100, 300, 1000, 1500, 3900};
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_POT_CAL_RAW0, raw, sizeof raw), 0);
    int32_t pos0 = -2000, step = 1000;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_POT_CAL_POS0, &pos0, 4), 0);
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_POT_CAL_STEP, &step, 4), 0);
    uint8_t n = 5;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_POT_CAL_COUNT, &n, 1), 0);
    /* no position record: homed from the pot. 650 lies half way in 300..1000 */
    uint8_t zeros[0x80] = {0};
    rcfw_fram_poke(bus, 0, RCFW_FRAM_RUNTIME_A, zeros, sizeof zeros);
    rcfw_set_pot_raw(bus, 0, 0, 650);
    rcfw_power_cycle(bus, 0);
    CHECK_EQ(rcfw_get_position(bus, 0, 0), -2000 + 1000 + 500);
    CHECK(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS) & RCFW_HWERR_POSITION_LOST);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_RESET_CAUSE), RCFW_CAUSE_POWER_ON);
    /* beyond the table: clamps to the end point */
    rcfw_fram_poke(bus, 0, RCFW_FRAM_RUNTIME_A, zeros, sizeof zeros);
    rcfw_set_pot_raw(bus, 0, 0, 4000);
    rcfw_power_cycle(bus, 0);
    CHECK_EQ(rcfw_get_position(bus, 0, 0), 2000);
    /* move, then lose power: position and goal resume from FRAM, pot agrees -> no mismatch */
    uint8_t zero = 0;
    write_ack(bus, 1, RCFW_CT_HARDWARE_ERROR_STATUS, &zero, 1);
    uint8_t h = 1;
    rcfw_set_hall(bus, 0, 0, h);
    for (int i = 1; i <= 12; i++) {
        rcfw_set_hall(bus, 0, 0, hall_fwd[i % 6]);
    }
    wr32(bus, 1, RCFW_CT_GOAL_POSITION, 2500);
    status_t st[2];
    collect(bus, 2000, st, 2);
    CHECK_EQ(rcfw_get_position(bus, 0, 0), 2012);
    rcfw_power_cycle(bus, 0);
    CHECK_EQ(rcfw_get_position(bus, 0, 0), 2012);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_GOAL_POSITION), 2500);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS), 0);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_TORQUE_ENABLE), 0);
    CHECK_EQ(peek16(bus, 0, RCFW_CT_POT_CAL_RAW0 + 8), 3900);
    /* pot disagrees with the stored position by more than the tolerance -> mismatch flagged */
    rcfw_set_pot_raw(bus, 0, 0, 300); /* -1000 */
    rcfw_reset(bus, 0, RCFW_RESET_BROWN_OUT);
    CHECK_EQ(rcfw_get_position(bus, 0, 0), 2012);
    CHECK(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS) & RCFW_HWERR_POT_MISMATCH);
    CHECK(peek8(bus, 0, RCFW_CT_MOTOR_ERROR) & RCFW_MERR_POT);
    send_frame(bus, 1, RCFW_INST_PING, 0, 0);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK(st[0].error & RCFW_ERR_ALERT);
    /* host-requested homing: motor 1 is not calibrated -> refused, nothing changes */
    uint8_t req = 0x03;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_HOME_REQUEST, &req, 1), RCFW_ERR_ALERT | RCFW_ERR_RESULT_FAIL);
    CHECK_EQ(rcfw_get_position(bus, 0, 0), 2012);
    req = 0x01;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_HOME_REQUEST, &req, 1), 0); /* alert gone: mismatch cleared */
    CHECK_EQ(rcfw_get_position(bus, 0, 0), -1000);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_GOAL_POSITION), -1000);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_HOME_REQUEST), 0);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS) & (RCFW_HWERR_POT_MISMATCH | RCFW_HWERR_POSITION_LOST), 0);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_MOTOR_ERROR) & RCFW_MERR_POT, 0);
    rcfw_power_cycle(bus, 0); /* the homed position was saved at once */
    CHECK_EQ(rcfw_get_position(bus, 0, 0), -1000);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS) & RCFW_HWERR_POT_MISMATCH, 0);
    rcfw_bus_destroy(bus);
}

/* Per-motor persistent field of motor m (all share one stride). */
#define MOTOR_FIELD(field, m) ((uint16_t)(RCFW_CT_##field + (m) * RCFW_CT_##field##_STRIDE))

/* Linear 3-point pot calibration of motor m: raw 1000/2000/3000 at pos0, pos0 + 1000, pos0 + 2000. */
static void calibrate(rcfw_bus *bus, uint8_t id, int m, int32_t pos0)
{
    const uint16_t raw[3] = {1000, 2000, 3000};
    int32_t step = 1000;
    uint8_t n = 3;
    CHECK_EQ(write_ack(bus, id, MOTOR_FIELD(POT_CAL_RAW0, m), raw, sizeof raw) & 0x7F, 0);
    CHECK_EQ(write_ack(bus, id, MOTOR_FIELD(POT_CAL_POS0, m), &pos0, 4) & 0x7F, 0);
    CHECK_EQ(write_ack(bus, id, MOTOR_FIELD(POT_CAL_STEP, m), &step, 4) & 0x7F, 0);
    CHECK_EQ(write_ack(bus, id, MOTOR_FIELD(POT_CAL_COUNT, m), &n, 1) & 0x7F, 0);
}

/* Turn a motor forward by n Hall counts (its Hall state must be hall_fwd[0] = the power-on state). */
static void turn_forward(rcfw_bus *bus, int module, int motor, int n)
{
    for (int i = 1; i <= n; i++) {
        rcfw_set_hall(bus, module, motor, hall_fwd[i % 6]);
    }
}

static const tv_vector *vector(const char *name)
{
    for (int i = 0; i < TV_COUNT; i++) {
        if (strcmp(tv_vectors[i].name, name) == 0) {
            return &tv_vectors[i];
        }
    }
    CHECK(!"test vector missing");
    return NULL;
}

/* Status packets the bus carried in the next us, raw. */
static int raw_reply(rcfw_bus *bus, uint32_t us, uint8_t *buf, int cap)
{
    rcfw_advance_us(bus, us);
    return rcfw_bus_read(bus, buf, cap);
}

static void home_request_homes_only_the_chosen_motors(void)
{
    rcfw_bus *bus = make_bus(1);
    calibrate(bus, 1, 0, -1000);
    calibrate(bus, 1, 1, 0);
    calibrate(bus, 1, 2, 5000);
    /* a commissioned module with a position record: positions and goals of its own */
    turn_forward(bus, 0, 1, 12);
    wr32(bus, 1, MOTOR_FIELD(GOAL_POSITION, 0), 77);
    status_t st[2];
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    wr32(bus, 1, MOTOR_FIELD(GOAL_POSITION, 1), 300);
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    rcfw_set_pot_raw(bus, 0, 0, 1500); /* -1000 + 500 */
    rcfw_set_pot_raw(bus, 0, 1, 1500); /* 500: within the mismatch tolerance of its position 12 */
    rcfw_set_pot_raw(bus, 0, 2, 2999); /* 5000 + 1999 */
    rcfw_advance_us(bus, 1000);
    CHECK_EQ(rcfw_get_position(bus, 0, 1), 12);

    /* the shared test vector: home motors 0 and 2 of ID 1 */
    const tv_vector *v = vector("write_home_request_motors_0_2_id1");
    if (v) {
        rcfw_bus_write(bus, v->frame, v->frame_len);
    }
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    CHECK_EQ(st[0].error, 0);
    CHECK_EQ(rcfw_get_position(bus, 0, 0), -500);
    CHECK_EQ(peek32(bus, 0, MOTOR_FIELD(GOAL_POSITION, 0)), -500);
    CHECK_EQ(peek32(bus, 0, MOTOR_FIELD(PRESENT_SETPOINT, 0)), -500);
    CHECK_EQ(rcfw_get_position(bus, 0, 2), 6999);
    CHECK_EQ(peek32(bus, 0, MOTOR_FIELD(GOAL_POSITION, 2)), 6999);
    CHECK_EQ(peek32(bus, 0, MOTOR_FIELD(PRESENT_SETPOINT, 2)), 6999);
    CHECK_EQ(peek16(bus, 0, MOTOR_FIELD(POT_RAW, 2)), 2999);
    /* motors 1 and 3 were not asked: untouched although motor 1 is calibrated */
    CHECK_EQ(rcfw_get_position(bus, 0, 1), 12);
    CHECK_EQ(peek32(bus, 0, MOTOR_FIELD(GOAL_POSITION, 1)), 300);
    CHECK_EQ(rcfw_get_position(bus, 0, 3), 0);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_HOME_REQUEST), 0);

    /* goal = setpoint = position: turning the drive on does not move the motor */
    uint8_t on = 1, off = 0;
    CHECK_EQ(write_ack(bus, 1, MOTOR_FIELD(TORQUE_ENABLE, 2), &on, 1), 0);
    rcfw_advance_us(bus, 5000);
    CHECK_EQ(rcfw_get_driver_enable(bus, 0, 2), 1);
    CHECK_EQ(rcfw_get_pwm(bus, 0, 2), 0);
    CHECK_EQ(write_ack(bus, 1, MOTOR_FIELD(TORQUE_ENABLE, 2), &off, 1), 0);

    /* the homed positions were saved before the reply: a reset right away keeps them */
    rcfw_reset(bus, 0, RCFW_RESET_BROWN_OUT);
    CHECK_EQ(rcfw_get_position(bus, 0, 0), -500);
    CHECK_EQ(rcfw_get_position(bus, 0, 2), 6999);
    CHECK_EQ(peek32(bus, 0, MOTOR_FIELD(GOAL_POSITION, 2)), 6999);
    CHECK_EQ(rcfw_get_position(bus, 0, 1), 12);
    CHECK_EQ(peek32(bus, 0, MOTOR_FIELD(GOAL_POSITION, 1)), 300);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS), 0);
    rcfw_bus_destroy(bus);
}

static void home_request_clears_mismatch_and_position_lost_per_motor(void)
{
    rcfw_bus *bus = make_bus(1);
    calibrate(bus, 1, 0, 0);
    calibrate(bus, 1, 1, 0);
    calibrate(bus, 1, 2, 0);
    /* pot mismatch on motor 1 only: its joint was turned while the module was off */
    rcfw_set_pot_raw(bus, 0, 0, 1000);
    rcfw_set_pot_raw(bus, 0, 1, 2500); /* 1500 counts from the saved 0; tolerance 1000 */
    rcfw_set_pot_raw(bus, 0, 2, 1000);
    rcfw_power_cycle(bus, 0);
    CHECK_EQ(rcfw_get_position(bus, 0, 1), 0);
    CHECK_EQ(peek8(bus, 0, MOTOR_FIELD(MOTOR_ERROR, 0)), 0);
    CHECK_EQ(peek8(bus, 0, MOTOR_FIELD(MOTOR_ERROR, 1)), RCFW_MERR_POT);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS), RCFW_HWERR_POT_MISMATCH);
    uint8_t req = 0x02;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_HOME_REQUEST, &req, 1), 0); /* no alert left */
    CHECK_EQ(rcfw_get_position(bus, 0, 1), 1500);
    CHECK_EQ(peek8(bus, 0, MOTOR_FIELD(MOTOR_ERROR, 1)), 0);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS), 0);
    rcfw_power_cycle(bus, 0);
    CHECK_EQ(rcfw_get_position(bus, 0, 1), 1500);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS), 0);

    /* no position record: every motor is position-lost until it is homed (motor 3 has no pot) */
    uint8_t zeros[0x80] = {0};
    rcfw_fram_poke(bus, 0, RCFW_FRAM_RUNTIME_A, zeros, sizeof zeros);
    rcfw_power_cycle(bus, 0);
    for (int m = 0; m < 4; m++) {
        CHECK_EQ(peek8(bus, 0, MOTOR_FIELD(MOTOR_ERROR, m)), RCFW_MERR_POSITION_LOST);
    }
    CHECK_EQ(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS), RCFW_HWERR_POSITION_LOST);
    req = 0x07;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_HOME_REQUEST, &req, 1), RCFW_ERR_ALERT); /* motor 3 still lost */
    for (int m = 0; m < 3; m++) {
        CHECK_EQ(peek8(bus, 0, MOTOR_FIELD(MOTOR_ERROR, m)), 0);
    }
    CHECK_EQ(peek8(bus, 0, MOTOR_FIELD(MOTOR_ERROR, 3)), RCFW_MERR_POSITION_LOST);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS), RCFW_HWERR_POSITION_LOST);
    /* other latched errors stay: a Hall glitch on motor 0, then homing motor 3 once calibrated */
    rcfw_set_hall(bus, 0, 0, 7);
    rcfw_set_hall(bus, 0, 0, 1);
    calibrate(bus, 1, 3, 0);
    rcfw_set_pot_raw(bus, 0, 3, 1000);
    req = 0x08;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_HOME_REQUEST, &req, 1), RCFW_ERR_ALERT);
    CHECK_EQ(peek8(bus, 0, MOTOR_FIELD(MOTOR_ERROR, 3)), 0);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS), RCFW_HWERR_HALL);
    rcfw_bus_destroy(bus);
}

static void home_request_refused_changes_nothing(void)
{
    rcfw_bus *bus = make_bus(2); /* module 1: 4 motors, module 2: 2 motors */
    calibrate(bus, 1, 0, 0);
    calibrate(bus, 2, 0, 0);
    calibrate(bus, 2, 1, 0);
    turn_forward(bus, 0, 0, 6);
    wr32(bus, 1, RCFW_CT_GOAL_POSITION, 40);
    status_t st[2];
    CHECK_EQ(collect(bus, 2000, st, 2), 1);
    rcfw_set_pot_raw(bus, 0, 0, 2500);
    rcfw_set_pot_raw(bus, 0, 1, 2500);
    rcfw_advance_us(bus, 2000);
    uint8_t before[RCFW_CT_SIZE], after[RCFW_CT_SIZE], fram_before[RCFW_FRAM_USED], fram_after[RCFW_FRAM_USED];
    rcfw_peek_table(bus, 0, 0, before, RCFW_CT_SIZE);
    rcfw_fram_peek(bus, 0, 0, fram_before, RCFW_FRAM_USED);

    /* motor 1 has no pot calibration: the whole request is refused, motor 0 included */
    uint8_t req = 0x03;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_HOME_REQUEST, &req, 1), RCFW_ERR_RESULT_FAIL);
    /* bits beyond the 4 motors: out of range */
    req = 0x11;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_HOME_REQUEST, &req, 1), RCFW_ERR_DATA_RANGE);
    /* the reply is exactly the shared refusal vector */
    const tv_vector *v = vector("status_result_fail_home_refused");
    req = 0x02;
    wr(bus, 1, RCFW_CT_HOME_REQUEST, &req, 1);
    uint8_t buf[64];
    int n = raw_reply(bus, 2000, buf, sizeof buf);
    if (v) {
        CHECK_EQ(n, v->frame_len);
        CHECK(n == v->frame_len && memcmp(buf, v->frame, (size_t)n) == 0);
    }
    rcfw_advance_us(bus, 2000);
    rcfw_peek_table(bus, 0, 0, after, RCFW_CT_SIZE);
    rcfw_fram_peek(bus, 0, 0, fram_after, RCFW_FRAM_USED);
    CHECK(memcmp(before, after, RCFW_CT_SIZE) == 0);
    CHECK(memcmp(fram_before, fram_after, RCFW_FRAM_USED) == 0);
    CHECK_EQ(rcfw_get_position(bus, 0, 0), 6);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_GOAL_POSITION), 40);

    /* a motor the module does not have (module 2 drives 2) */
    req = 0x04;
    CHECK_EQ(write_ack(bus, 2, RCFW_CT_HOME_REQUEST, &req, 1), RCFW_ERR_RESULT_FAIL);

    /* torque on: refused, the motor keeps its coordinates; torque off: homed */
    uint8_t on = 1, off = 0;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_TORQUE_ENABLE, &on, 1), 0);
    req = 0x01;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_HOME_REQUEST, &req, 1), RCFW_ERR_RESULT_FAIL);
    CHECK_EQ(rcfw_get_position(bus, 0, 0), 6);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_GOAL_POSITION), 40);
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_TORQUE_ENABLE, &off, 1), 0);
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_HOME_REQUEST, &req, 1), 0);
    CHECK_EQ(rcfw_get_position(bus, 0, 0), 1500);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_GOAL_POSITION), 1500);
    rcfw_bus_destroy(bus);
}

int main(void)
{
    TF_RUN(homing_and_resume);
    TF_RUN(home_request_homes_only_the_chosen_motors);
    TF_RUN(home_request_clears_mismatch_and_position_lost_per_motor);
    TF_RUN(home_request_refused_changes_nothing);
    TF_END();
}
