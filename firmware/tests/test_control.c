/* Control: Hall decoding, P law, speed limit, current filter and limit, P loop settling. */
#include "bus_helpers.h"
#include "rcfw/motor.h"

static void hall_forward_backward(void)
{
    rcfw_motor m;
    memset(&m, 0, sizeof m);
    rcfw_motor_set_position(&m, 0, 1);
    for (int r = 0; r < 12; r++) {
        CHECK(!rcfw_hall_update(&m, hall_fwd[(r + 1) % 6]));
    }
    CHECK_EQ(m.position, 12);
    for (int r = 12; r > 0; r--) {
        CHECK(!rcfw_hall_update(&m, hall_fwd[(r - 1) % 6]));
    }
    CHECK_EQ(m.position, 0);
    CHECK_EQ(m.hall_errors, 0);
    /* quick reversals near a boundary: every transition counts, nothing is lost */
    for (int k = 0; k < 50; k++) {
        rcfw_hall_update(&m, 3);
        rcfw_hall_update(&m, 1);
    }
    CHECK_EQ(m.position, 0);
    CHECK_EQ(m.hall_errors, 0);
    /* repeating the same state does not count */
    rcfw_hall_update(&m, 1);
    CHECK_EQ(m.position, 0);
}

static void hall_glitches(void)
{
    rcfw_motor m;
    memset(&m, 0, sizeof m);
    rcfw_motor_set_position(&m, 100, 1);
    CHECK(rcfw_hall_update(&m, 0)); /* 000 impossible */
    CHECK(rcfw_hall_update(&m, 7)); /* 111 impossible */
    CHECK_EQ(m.position, 100);
    CHECK_EQ(m.hall_errors, 2);
    CHECK(m.errors & RCFW_MERR_HALL);
    /* back to a valid neighbour: counts normally */
    CHECK(!rcfw_hall_update(&m, 3));
    CHECK_EQ(m.position, 101);
    /* skipped one state forward (3 -> 6): error, counted as +2 */
    CHECK(rcfw_hall_update(&m, 6));
    CHECK_EQ(m.position, 103);
    CHECK_EQ(m.hall_errors, 3);
    /* skipped backward (6 -> 3 is -2) */
    CHECK(rcfw_hall_update(&m, 3));
    CHECK_EQ(m.position, 101);
    /* opposite state (3 -> 4, 3 steps): error, no count */
    CHECK(rcfw_hall_update(&m, 4));
    CHECK_EQ(m.position, 101);
    CHECK_EQ(m.hall_errors, 5);
}

static void p_law(void)
{
    CHECK_EQ(rcfw_p_law(256, 10), 10);
    CHECK_EQ(rcfw_p_law(256, -10), -10);
    CHECK_EQ(rcfw_p_law(128, 3), 1);   /* 1.5 -> 1, toward zero */
    CHECK_EQ(rcfw_p_law(128, -3), -1);
    CHECK_EQ(rcfw_p_law(256, 1000), 255);
    CHECK_EQ(rcfw_p_law(256, -1000), -255);
    CHECK_EQ(rcfw_p_law(65535, 2000000000), 255);
    CHECK_EQ(rcfw_p_law(65535, -2000000000), -255);
    CHECK_EQ(rcfw_p_law(1, 32767), 127);
    CHECK_EQ(rcfw_p_law(0, 5000), 0);
}

static void current_filter(void)
{
    rcfw_motor m;
    memset(&m, 0, sizeof m);
    for (int i = 0; i < 500; i++) {
        rcfw_motor_tick(&m, 1000, 4, 1);
    }
    CHECK(m.cur_ma >= 985 && m.cur_ma <= 1000);
    /* noise +-200 around 1000 averages out */
    for (int i = 0; i < 2000; i++) {
        rcfw_motor_tick(&m, (uint16_t)(i & 1 ? 1200 : 800), 4, 1);
    }
    CHECK(m.cur_ma >= 960 && m.cur_ma <= 1040);
    /* step response time constant ~ 2^k samples */
    memset(&m, 0, sizeof m);
    int n = 0;
    while (m.cur_ma < 632 && n < 1000) {
        rcfw_motor_tick(&m, 1000, 4, 1);
        n++;
    }
    CHECK(n >= 12 && n <= 20);
}

static rcfw_bus *one_module(void)
{
    const uint8_t ids[1] = {1}, motors[1] = {4};
    rcfw_bus *bus = rcfw_bus_create(1, ids, motors);
    CHECK(bus != NULL);
    return bus;
}

/* A persistent parameter can only be written with torque off (access error otherwise): off, write, on. */
static void tune16(rcfw_bus *bus, uint16_t addr, uint16_t v)
{
    wr8(bus, 1, RCFW_CT_TORQUE_ENABLE, 0);
    wr16(bus, 1, addr, v);
    CHECK_EQ(peek16(bus, 0, addr), v);
    wr8(bus, 1, RCFW_CT_TORQUE_ENABLE, 1);
    rcfw_advance_us(bus, 200);
}

static void speed_limit(void)
{
    rcfw_bus *bus = one_module();
    wr16(bus, 1, RCFW_CT_SPEED_LIMIT, 1000); /* counts/s */
    wr8(bus, 1, RCFW_CT_TORQUE_ENABLE, 1);
    wr32(bus, 1, RCFW_CT_GOAL_POSITION, 100000);
    rcfw_advance_us(bus, 500000);
    int32_t sp = peek32(bus, 0, RCFW_CT_PRESENT_SETPOINT);
    CHECK(sp >= 498 && sp <= 502);
    /* fractional speeds accumulate: 7 counts/s for 1 s */
    tune16(bus, RCFW_CT_SPEED_LIMIT, 7);
    int32_t sp0 = peek32(bus, 0, RCFW_CT_PRESENT_SETPOINT);
    rcfw_advance_us(bus, 1000000);
    int32_t d = peek32(bus, 0, RCFW_CT_PRESENT_SETPOINT) - sp0;
    CHECK(d >= 6 && d <= 8);
    /* goal behind: moves back down, stops exactly at the goal */
    tune16(bus, RCFW_CT_SPEED_LIMIT, 5000);
    wr32(bus, 1, RCFW_CT_GOAL_POSITION, -50);
    rcfw_advance_us(bus, 300000);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_PRESENT_SETPOINT), -50);
    /* 0 = unlimited */
    tune16(bus, RCFW_CT_SPEED_LIMIT, 0);
    wr32(bus, 1, RCFW_CT_GOAL_POSITION, 77777);
    rcfw_advance_us(bus, 200);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_PRESENT_SETPOINT), 77777);
    /* position limits clamp a goal set before them; a goal beyond them is refused (data limit) */
    wr8(bus, 1, RCFW_CT_TORQUE_ENABLE, 0);
    wr32(bus, 1, RCFW_CT_POSITION_MAX, 5000);
    wr8(bus, 1, RCFW_CT_TORQUE_ENABLE, 1);
    rcfw_advance_us(bus, 200);
    status_t drain[16];
    (void)collect(bus, 2000, drain, 16); /* the replies of the writes above */
    int32_t beyond = 5001;
    CHECK_EQ(write_ack(bus, 1, RCFW_CT_GOAL_POSITION, &beyond, 4), RCFW_ERR_DATA_LIMIT);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_GOAL_POSITION), 77777);
    CHECK_EQ(peek32(bus, 0, RCFW_CT_PRESENT_SETPOINT), 5000);
    rcfw_bus_destroy(bus);
}

static void p_loop_settles(void)
{
    rcfw_bus *bus = one_module();
    motor_model mm = {0.0, 0.0, 2740.0, 0.0047, 6}; /* 1226 S: 27,400 rpm = 2,740 counts/s */
    rcfw_set_hall(bus, 0, 0, model_hall(&mm));
    wr16(bus, 1, RCFW_CT_KP, 8 * 256);
    wr16(bus, 1, RCFW_CT_SPEED_LIMIT, 2000);
    wr8(bus, 1, RCFW_CT_TORQUE_ENABLE, 1);
    wr32(bus, 1, RCFW_CT_GOAL_POSITION, 1200);
    simulate(bus, 0, 0, &mm, 1500);
    int32_t pos = rcfw_get_position(bus, 0, 0);
    CHECK(pos >= 1199 && pos <= 1201);
    CHECK(mm.pos > 1198.0 && mm.pos < 1202.0);
    int pwm = rcfw_get_pwm(bus, 0, 0);
    CHECK(pwm > -20 && pwm < 20);
    CHECK_EQ(peek16(bus, 0, RCFW_CT_HALL_ERROR_COUNT), 0);
    /* and back, past zero */
    wr32(bus, 1, RCFW_CT_GOAL_POSITION, -600);
    simulate(bus, 0, 0, &mm, 1500);
    pos = rcfw_get_position(bus, 0, 0);
    CHECK(pos >= -601 && pos <= -599);
    CHECK_EQ(peek16(bus, 0, RCFW_CT_HALL_ERROR_COUNT), 0);
    rcfw_bus_destroy(bus);
}

static void current_limit_engages_and_releases(void)
{
    rcfw_bus *bus = one_module();
    wr16(bus, 1, RCFW_CT_CURRENT_LIMIT, 1000);
    wr16(bus, 1, RCFW_CT_SPEED_LIMIT, 0);
    wr8(bus, 1, RCFW_CT_TORQUE_ENABLE, 1);
    wr32(bus, 1, RCFW_CT_GOAL_POSITION, 100000);
    rcfw_advance_us(bus, 1000);
    CHECK_EQ(rcfw_get_pwm(bus, 0, 0), 255);
    /* stalled motor: current far above the limit */
    rcfw_set_current_raw(bus, 0, 0, 3000);
    rcfw_advance_us(bus, 1000); /* 10 periods: filter crosses the limit after a few */
    int p1 = rcfw_get_pwm(bus, 0, 0);
    CHECK(p1 < 255 && p1 > 240);
    rcfw_advance_us(bus, 10000); /* 100 more periods, one step each */
    int p2 = rcfw_get_pwm(bus, 0, 0);
    CHECK_EQ(p1 - p2, 100);
    CHECK(peek8(bus, 0, RCFW_CT_MOTOR_ERROR) & RCFW_MERR_OVERCURRENT);
    CHECK(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS) & RCFW_HWERR_OVERCURRENT);
    rcfw_advance_us(bus, 30000);
    CHECK_EQ(rcfw_get_pwm(bus, 0, 0), 0); /* stepped all the way down */
    /* PWM proportional current model: current follows PWM; settles around the limit */
    for (int t = 0; t < 2000; t++) {
        int pwm = rcfw_get_pwm(bus, 0, 0);
        rcfw_set_current_raw(bus, 0, 0, (uint16_t)(pwm < 0 ? -pwm : pwm) * 12u); /* 255 -> 3060 */
        rcfw_advance_us(bus, 100);
    }
    int ma = peek16(bus, 0, RCFW_CT_PRESENT_CURRENT);
    CHECK(ma > 850 && ma < 1150);
    int held = rcfw_get_pwm(bus, 0, 0);
    CHECK(held > 60 && held < 100); /* ~1000/12 */
    /* released: current drops, P loop takes over again and ramps back to full */
    rcfw_set_current_raw(bus, 0, 0, 100);
    rcfw_advance_us(bus, 40000);
    CHECK_EQ(rcfw_get_pwm(bus, 0, 0), 255);
    /* limit 0 disables */
    tune16(bus, RCFW_CT_CURRENT_LIMIT, 0);
    rcfw_set_current_raw(bus, 0, 0, 4095);
    rcfw_advance_us(bus, 10000);
    CHECK_EQ(rcfw_get_pwm(bus, 0, 0), 255);
    rcfw_bus_destroy(bus);
}

/* The limit acts on the moving average, not on one sample: a single spike far over the limit (cautery noise, an ADC
 * glitch) must not trip it, while a sustained over-current must, as soon as the exponential average
 * a_n = a_0 + (x - a_0)(1 - (1 - 2^-k)^n) crosses the limit. With a_0 = 500, x = 3000, limit 1000 and k = 4 that is
 * n = 4 (a_3 = 940, a_4 = 1069); integer truncation may delay it by one sample. */
static void current_spike_is_filtered_sustained_overcurrent_trips(void)
{
    rcfw_bus *bus = one_module();
    CHECK_EQ(peek8(bus, 0, RCFW_CT_CURRENT_FILTER_SHIFT), 4);
    wr16(bus, 1, RCFW_CT_CURRENT_LIMIT, 1000); /* persistent parameters: written while torque is off */
    wr16(bus, 1, RCFW_CT_SPEED_LIMIT, 0);
    wr8(bus, 1, RCFW_CT_TORQUE_ENABLE, 1);
    wr32(bus, 1, RCFW_CT_GOAL_POSITION, 100000);
    rcfw_set_current_raw(bus, 0, 0, 500);
    rcfw_advance_us(bus, 30000); /* 300 periods: the average settles at 500 */
    CHECK_EQ(rcfw_get_pwm(bus, 0, 0), 255);
    CHECK_EQ(peek16(bus, 0, RCFW_CT_PRESENT_CURRENT), 500);

    rcfw_set_current_raw(bus, 0, 0, 4095); /* one sample at full scale */
    rcfw_advance_us(bus, 100);
    CHECK_EQ(rcfw_get_pwm(bus, 0, 0), 255);
    rcfw_set_current_raw(bus, 0, 0, 500);
    for (int t = 0; t < 50; t++) {
        rcfw_advance_us(bus, 100);
        CHECK_EQ(rcfw_get_pwm(bus, 0, 0), 255);
    }
    CHECK_EQ(peek8(bus, 0, RCFW_CT_MOTOR_ERROR) & RCFW_MERR_OVERCURRENT, 0);

    rcfw_advance_us(bus, 30000); /* back to a settled 500 */
    rcfw_set_current_raw(bus, 0, 0, 3000);
    int n = 0;
    while (rcfw_get_pwm(bus, 0, 0) == 255 && n < 100) {
        rcfw_advance_us(bus, 100);
        n++;
    }
    CHECK(n >= 4 && n <= 5);
    CHECK(peek8(bus, 0, RCFW_CT_MOTOR_ERROR) & RCFW_MERR_OVERCURRENT);
    rcfw_bus_destroy(bus);
}

static void pwm_mode(void)
{
    rcfw_bus *bus = one_module();
    wr8(bus, 1, RCFW_CT_CONTROL_MODE + RCFW_CT_CONTROL_MODE_STRIDE, 1);
    wr8(bus, 1, RCFW_CT_TORQUE_ENABLE + 1, 1);
    wr16(bus, 1, RCFW_CT_GOAL_PWM + 2, (uint16_t)-123);
    rcfw_advance_us(bus, 300);
    CHECK_EQ(rcfw_get_pwm(bus, 0, 1), -123);
    CHECK_EQ(rcfw_get_driver_enable(bus, 0, 1), 1);
    CHECK_EQ(rcfw_get_driver_enable(bus, 0, 0), 0);
    CHECK_EQ((int16_t)peek16(bus, 0, RCFW_CT_PRESENT_PWM + RCFW_CT_PRESENT_PWM_STRIDE), -123);
    rcfw_bus_destroy(bus);
}

int main(void)
{
    TF_RUN(hall_forward_backward);
    TF_RUN(hall_glitches);
    TF_RUN(p_law);
    TF_RUN(current_filter);
    TF_RUN(speed_limit);
    TF_RUN(p_loop_settles);
    TF_RUN(current_limit_engages_and_releases);
    TF_RUN(current_spike_is_filtered_sustained_overcurrent_trips);
    TF_RUN(pwm_mode);
    TF_END();
}
