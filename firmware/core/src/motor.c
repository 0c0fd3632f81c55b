#include "rcfw/motor.h"

#include <stdint.h>

/* a - b saturated to int32 (positions may span the whole int32 range) */
static int32_t sat_sub(int32_t a, int32_t b)
{
    int64_t d = (int64_t)a - b;
    return d > INT32_MAX ? INT32_MAX : (d < INT32_MIN ? INT32_MIN : (int32_t)d);
}

/* position +- n with wrap-around instead of undefined overflow */
static int32_t wrap_add(int32_t a, int32_t n)
{
    return (int32_t)((uint32_t)a + (uint32_t)n);
}

static const int8_t hall_seq_index[8] = {-1, 0, 2, 1, 4, 5, 3, -1};

int8_t rcfw_hall_index(uint8_t state)
{
    return hall_seq_index[state & 7u];
}

bool rcfw_hall_update(rcfw_motor *m, uint8_t state)
{
    int8_t idx = hall_seq_index[state & 7u];
    if (idx < 0) {
        if (m->hall_errors != 0xFFFFu) {
            m->hall_errors++;
        }
        m->errors |= RCFW_MERR_HALL;
        return true;
    }
    if (m->hall_idx > 5u) {
        m->hall_idx = (uint8_t)idx;
        return false;
    }
    int8_t d = (int8_t)(idx - (int8_t)m->hall_idx);
    if (d < 0) {
        d = (int8_t)(d + 6);
    }
    m->hall_idx = (uint8_t)idx;
    switch (d) {
    case 0:
        return false;
    case 1:
        m->position = wrap_add(m->position, 1);
        return false;
    case 5:
        m->position = wrap_add(m->position, -1);
        return false;
    default:
        /* skipped state(s): 2 or 4 steps are taken as two counts in the shorter direction,
         * 3 is ambiguous (no count). Either way it is an error. */
        if (d == 2) {
            m->position = wrap_add(m->position, 2);
        } else if (d == 4) {
            m->position = wrap_add(m->position, -2);
        }
        if (m->hall_errors != 0xFFFFu) {
            m->hall_errors++;
        }
        m->errors |= RCFW_MERR_HALL;
        return true;
    }
}

void rcfw_motor_set_position(rcfw_motor *m, int32_t pos, uint8_t hall_state)
{
    m->position = pos;
    int8_t idx = hall_seq_index[hall_state & 7u];
    m->hall_idx = idx < 0 ? 0xFFu : (uint8_t)idx;
    m->setpoint = pos;
    m->slew_acc = 0;
}

int16_t rcfw_p_law(uint16_t kp, int32_t err)
{
    if (err > 32767) {
        err = 32767;
    } else if (err < -32767) {
        err = -32767;
    }
    int32_t prod = (int32_t)kp * err; /* |prod| <= 65535 * 32767 < 2^31 */
    int32_t out = prod >= 0 ? (prod >> 8) : -((-prod) >> 8);
    if (out > RCFW_PWM_MAX) {
        out = RCFW_PWM_MAX;
    } else if (out < -RCFW_PWM_MAX) {
        out = -RCFW_PWM_MAX;
    }
    return (int16_t)out;
}

uint32_t rcfw_slew_step_q16(uint16_t speed, uint32_t rate_hz)
{
    return (((uint32_t)speed << 16) + rate_hz / 2u) / rate_hz;
}

static void slew(rcfw_motor *m)
{
    int32_t diff = sat_sub(m->goal, m->setpoint);
    if (diff == 0) {
        m->slew_acc = 0;
        return;
    }
    if (m->step_q16 == 0u) {
        m->setpoint = m->goal;
        m->slew_acc = 0;
        return;
    }
    m->slew_acc += m->step_q16;
    uint32_t whole = m->slew_acc >> 16;
    m->slew_acc &= 0xFFFFu;
    uint32_t mag = diff > 0 ? (uint32_t)diff : (uint32_t)0 - (uint32_t)diff;
    if (whole >= mag) {
        m->setpoint = m->goal;
        m->slew_acc = 0;
    } else if (diff > 0) {
        m->setpoint += (int32_t)whole; /* whole < mag: cannot pass the goal */
    } else {
        m->setpoint -= (int32_t)whole;
    }
}

int16_t rcfw_motor_tick(rcfw_motor *m, uint16_t current_raw, uint8_t k, uint8_t step)
{
    m->cur_sum = m->cur_sum - (m->cur_sum >> k) + current_raw;
    m->cur_ma = (uint16_t)(m->cur_sum >> k);

    if (!m->enabled) {
        m->setpoint = m->position;
        m->slew_acc = 0;
        m->cap = RCFW_PWM_MAX;
        m->pwm = 0;
        return 0;
    }
    int16_t out;
    if (m->mode == RCFW_MODE_PWM) {
        out = m->goal_pwm;
    } else {
        slew(m);
        out = rcfw_p_law(m->kp, sat_sub(m->setpoint, m->position));
    }
    uint8_t mag = (uint8_t)(out < 0 ? -out : out);
    if (m->current_limit != 0u && m->cur_ma > m->current_limit) {
        /* override: step the magnitude down from what is applied now */
        uint8_t now = (uint8_t)(m->pwm < 0 ? -m->pwm : m->pwm);
        uint8_t c = m->cap < now ? m->cap : now;
        m->cap = c > step ? (uint8_t)(c - step) : 0u;
        m->errors |= RCFW_MERR_OVERCURRENT;
        /* keep the direction of the last applied PWM while limiting */
        int16_t dir = m->pwm != 0 ? m->pwm : out;
        m->pwm = (int16_t)(dir < 0 ? -(int16_t)m->cap : (int16_t)m->cap);
        return m->pwm;
    }
    if (m->cap < RCFW_PWM_MAX) {
        uint16_t c = (uint16_t)m->cap + step;
        m->cap = c > RCFW_PWM_MAX ? RCFW_PWM_MAX : (uint8_t)c;
    }
    if (mag > m->cap) {
        mag = m->cap;
    }
    m->pwm = (int16_t)(out < 0 ? -(int16_t)mag : (int16_t)mag);
    return m->pwm;
}
