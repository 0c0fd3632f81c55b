#include <string.h>

#include "internal.h"
#include "rcfw/hal.h"
#include "rcfw/verify.h"

/* ---- little-endian table access ---- */
uint32_t rcfwi_rd_le(const uint8_t *p, uint8_t size)
{
    uint32_t v = 0;
    for (uint8_t i = size; i > 0; i--) {
        v = (v << 8) | p[i - 1u];
    }
    return v;
}
void rcfwi_wr_le(uint8_t *p, uint8_t size, uint32_t v)
{
    for (uint8_t i = 0; i < size; i++) {
        p[i] = (uint8_t)v;
        v >>= 8;
    }
}
#define MA RCFWI_MA

/* The tick ORs every motor's error bits into hardware_error_status: they must mean the same there. */
_Static_assert(RCFW_MERR_OVERCURRENT == RCFW_HWERR_OVERCURRENT && RCFW_MERR_HALL == RCFW_HWERR_HALL &&
                   RCFW_MERR_POT == RCFW_HWERR_POT_MISMATCH && RCFW_MERR_POSITION_LOST == RCFW_HWERR_POSITION_LOST,
               "motor error bits are hardware_error_status bits");

int32_t rcfwi_field_value(const rcfw_ct_field *f, uint32_t raw)
{
    if ((f->flags & RCFW_CT_F_SIGNED) && f->size < 4u) {
        uint32_t sign = 1u << (f->size * 8u - 1u);
        return (int32_t)((raw ^ sign) - sign);
    }
    return (int32_t)raw;
}

static void load_defaults(rcfw_module *m, uint16_t from, uint16_t to, bool keep_id, bool keep_baud)
{
    uint8_t id = m->ct[RCFW_CT_ID], baud = m->ct[RCFW_CT_BAUD_RATE];
    for (uint8_t i = 0; i < RCFW_CT_FIELD_COUNT; i++) {
        const rcfw_ct_field *f = &rcfw_ct_fields[i];
        for (uint8_t k = 0; k < f->count; k++) {
            uint16_t a = (uint16_t)(f->address + k * f->stride);
            if (a >= from && a < to) {
                rcfwi_wr_le(&m->ct[a], f->size, (uint32_t)f->def);
            }
        }
    }
    if (keep_id) {
        m->ct[RCFW_CT_ID] = id;
    }
    if (keep_baud) {
        m->ct[RCFW_CT_BAUD_RATE] = baud;
    }
}

static bool persistent_valid(const rcfw_module *m)
{
    for (uint8_t i = 0; i < RCFW_CT_FIELD_COUNT; i++) {
        const rcfw_ct_field *f = &rcfw_ct_fields[i];
        if (!(f->flags & RCFW_CT_F_PERSISTENT) || !(f->flags & RCFW_CT_F_WRITABLE)) {
            continue;
        }
        for (uint8_t k = 0; k < f->count; k++) {
            uint16_t a = (uint16_t)(f->address + k * f->stride);
            int32_t v = rcfwi_field_value(f, rcfwi_rd_le(&m->ct[a], f->size));
            if (f->size == 4u && !(f->flags & RCFW_CT_F_SIGNED)) {
                if ((uint32_t)v > (uint32_t)f->max) {
                    return false;
                }
            } else if (v < f->min || v > f->max) {
                return false;
            }
        }
    }
    return true;
}

static void set_fixed_identity(rcfw_module *m)
{
    rcfwi_ct_w16(m, RCFW_CT_MODEL_NUMBER, (uint16_t)rcfw_ct_fields[RCFW_CT_FIELD_MODEL_NUMBER].def);
    m->ct[RCFW_CT_FIRMWARE_VERSION] = (uint8_t)rcfw_ct_fields[RCFW_CT_FIELD_FIRMWARE_VERSION].def;
    m->ct[RCFW_CT_MOTOR_COUNT] = m->n_motors;
}

uint32_t rcfw_baud_code_bps(uint8_t code)
{
    static const uint32_t bps[8] = {9600u, 57600u, 115200u, 1000000u, 2000000u, 3000000u, 4000000u, 4500000u};
    return code < 8u ? bps[code] : 1000000u;
}

uint32_t rcfw_module_baud_bps(const rcfw_module *m)
{
    return rcfw_baud_code_bps(m->ct[RCFW_CT_BAUD_RATE]);
}

bool rcfw_pot_to_position(const rcfw_module *m, uint8_t motor, uint16_t raw, int32_t *pos)
{
    uint8_t n = rcfwi_ct8(m, MA(POT_CAL_COUNT, motor));
    if (n < 2u || n > 8u) {
        return false;
    }
    int32_t pos0 = rcfwi_ct32(m, MA(POT_CAL_POS0, motor));
    int32_t step = rcfwi_ct32(m, MA(POT_CAL_STEP, motor));
    uint16_t base = MA(POT_CAL_RAW0, motor);
    int32_t best = 0;
    uint32_t best_dist = 0xFFFFFFFFu;
    for (uint8_t i = 0; i + 1u < n; i++) {
        int32_t r0 = rcfwi_ct16(m, (uint16_t)(base + 2u * i));
        int32_t r1 = rcfwi_ct16(m, (uint16_t)(base + 2u * i + 2u));
        int32_t r = raw;
        bool inside = (r0 <= r && r <= r1) || (r1 <= r && r <= r0);
        if (inside && r0 != r1) {
            int64_t p = (int64_t)pos0 + (int64_t)i * step + ((int64_t)(r - r0) * step) / (r1 - r0);
            *pos = (int32_t)p;
            return true;
        }
        /* outside every segment: nearest end point */
        uint32_t d0 = (uint32_t)(r > r0 ? r - r0 : r0 - r);
        uint32_t d1 = (uint32_t)(r > r1 ? r - r1 : r1 - r);
        if (d0 < best_dist) {
            best_dist = d0;
            best = (int32_t)((int64_t)pos0 + (int64_t)i * step);
        }
        if (d1 < best_dist) {
            best_dist = d1;
            best = (int32_t)((int64_t)pos0 + (int64_t)(i + 1) * step);
        }
    }
    *pos = best;
    return true;
}

void rcfwi_apply_params(rcfw_module *m)
{
    uint8_t hw = m->ct[RCFW_CT_HARDWARE_ERROR_STATUS];
    bool holding = (hw & RCFW_HWERR_BUS_HOLD) != 0u;
    const uint32_t per_ms = RCFW_CONTROL_RATE_HZ / 1000u;
    m->ema_k = m->ct[RCFW_CT_CURRENT_FILTER_SHIFT];
    m->limit_step = m->ct[RCFW_CT_CURRENT_LIMIT_STEP];
    m->wd_limit_ticks = (uint32_t)rcfwi_ct16(m, RCFW_CT_BUS_WATCHDOG) * per_ms;
    uint32_t off = (uint32_t)rcfwi_ct16(m, RCFW_CT_BUS_WATCHDOG_OFF) * per_ms;
    m->wd_off_ticks = off != 0u ? off : m->wd_limit_ticks; /* 0: no hold stage, torque off at stage 1's time */
    for (uint8_t i = 0; i < m->n_motors; i++) {
        rcfw_motor *mo = &m->motor[i];
        mo->kp = rcfwi_ct16(m, MA(KP, i));
        mo->step_q16 = rcfw_slew_step_q16(rcfwi_ct16(m, MA(SPEED_LIMIT, i)), RCFW_CONTROL_RATE_HZ);
        mo->current_limit = rcfwi_ct16(m, MA(CURRENT_LIMIT, i));
        mo->mode = holding ? RCFW_MODE_POSITION : rcfwi_ct8(m, MA(CONTROL_MODE, i));
        if (!holding) { /* a hold keeps the goal it froze (not even clamped: that would be a move) */
            int32_t g = rcfwi_ct32(m, MA(GOAL_POSITION, i));
            int32_t lo = rcfwi_ct32(m, MA(POSITION_MIN, i)), hi = rcfwi_ct32(m, MA(POSITION_MAX, i));
            mo->goal = g < lo ? lo : (g > hi ? hi : g);
        }
        mo->goal_pwm = (int16_t)rcfwi_ct16(m, MA(GOAL_PWM, i));
        mo->enabled = (uint8_t)(rcfwi_ct8(m, MA(TORQUE_ENABLE, i)) && !(hw & RCFW_HWERR_BUS_WATCHDOG));
    }
}

static void publish(rcfw_module *m, uint8_t i)
{
    const rcfw_motor *mo = &m->motor[i];
    rcfwi_ct_w32(m, MA(PRESENT_POSITION, i), mo->position);
    rcfwi_ct_w16(m, MA(PRESENT_CURRENT, i), mo->cur_ma);
    rcfwi_ct_w16(m, MA(PRESENT_PWM, i), (uint16_t)mo->pwm);
    rcfwi_ct_w16(m, MA(HALL_ERROR_COUNT, i), mo->hall_errors);
    m->ct[MA(MOTOR_ERROR, i)] = mo->errors;
    rcfwi_ct_w32(m, MA(PRESENT_SETPOINT, i), mo->setpoint);
}

void rcfw_module_publish(rcfw_module *m)
{
    for (uint8_t i = 0; i < m->n_motors; i++) {
        publish(m, i);
    }
}

void rcfwi_runtime_image(const rcfw_module *m, uint8_t *img)
{
    memset(img, 0, RCFW_RUNTIME_LEN);
    for (uint8_t i = 0; i < m->n_motors; i++) {
        rcfwi_wr_le(img + 8u * i, 4, (uint32_t)m->motor[i].position);
        rcfwi_wr_le(img + 8u * i + 4u, 4, (uint32_t)rcfwi_ct32(m, MA(GOAL_POSITION, i)));
    }
}

void rcfwi_save_params(rcfw_module *m)
{
    if (!rcfw_store_save(&m->params, m->port, m->ct)) {
        m->stats.fram_errors++;
    }
}

void rcfw_module_init(rcfw_module *m, struct rcfw_port *port, uint8_t n_motors, uint8_t reset_cause)
{
    RCFW_ASSERT(n_motors >= 1u && n_motors <= RCFW_CT_MAX_MOTORS);
    memset(m, 0, sizeof *m);
    m->port = port;
    m->n_motors = n_motors;
    rcfw_parser_reset(&m->rx);
    rcfw_store_init(&m->params, RCFW_FRAM_PARAMS_A, RCFW_FRAM_PARAMS_B, RCFW_PARAMS_MAGIC, RCFW_CT_PERSISTENT_END);
    rcfw_store_init(&m->runtime, RCFW_FRAM_RUNTIME_A, RCFW_FRAM_RUNTIME_B, RCFW_RUNTIME_MAGIC, RCFW_RUNTIME_LEN);

    load_defaults(m, RCFW_CT_VOLATILE_START, RCFW_CT_VOLATILE_END, false, false);
    uint8_t hw = 0;
    if (!rcfw_store_load(&m->params, port, m->ct) || !persistent_valid(m)) {
        load_defaults(m, RCFW_CT_PERSISTENT_START, RCFW_CT_PERSISTENT_END, false, false);
        set_fixed_identity(m);
        hw |= RCFW_HWERR_PARAMS_LOST;
        rcfwi_save_params(m);
    }
    set_fixed_identity(m);

    uint8_t img[RCFW_RUNTIME_LEN];
    bool have_runtime = rcfw_store_load(&m->runtime, port, img);
    uint16_t tol = rcfwi_ct16(m, RCFW_CT_POT_MISMATCH_TOLERANCE);
    for (uint8_t i = 0; i < n_motors; i++) {
        rcfw_motor *mo = &m->motor[i];
        mo->cap = RCFW_PWM_MAX;
        uint8_t hall = rcfw_hal_hall_read(port, i);
        m->hall_last[i] = hall;
        uint16_t pot = rcfw_hal_adc_pot(port, i);
        rcfwi_ct_w16(m, MA(POT_RAW, i), pot);
        int32_t pot_pos = 0;
        bool calibrated = rcfw_pot_to_position(m, i, pot, &pot_pos);
        int32_t pos, goal;
        if (have_runtime) {
            pos = (int32_t)rcfwi_rd_le(img + 8u * i, 4);
            goal = (int32_t)rcfwi_rd_le(img + 8u * i + 4u, 4);
            if (calibrated) {
                int64_t d = (int64_t)pos - pot_pos;
                if (d > (int64_t)tol || d < -(int64_t)tol) {
                    mo->errors |= RCFW_MERR_POT;
                }
            }
        } else {
            pos = calibrated ? pot_pos : 0;
            goal = pos;
            mo->errors |= RCFW_MERR_POSITION_LOST; /* until the host homes it (home_request) or clears */
        }
        rcfw_motor_set_position(mo, pos, hall);
        rcfwi_ct_w32(m, MA(GOAL_POSITION, i), goal);
        rcfw_hal_pwm_set(port, i, 0);
        rcfw_hal_bridge_enable(port, i, false);
    }
    m->ct[RCFW_CT_RESET_CAUSE] = reset_cause;
    m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] = hw;
    for (uint8_t i = 0; i < n_motors; i++) {
        m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] |= m->motor[i].errors;
    }
    rcfwi_apply_params(m);
    rcfw_module_publish(m);
    rcfwi_runtime_image(m, m->runtime_saved);
    if (!have_runtime && !rcfw_store_save(&m->runtime, port, m->runtime_saved)) {
        m->stats.fram_errors++;
    }
    rcfw_hal_uart_set_baud(port, rcfw_module_baud_bps(m));
}

/* Bus watchdog stage 2: every motor off, bit3 latched. */
static void trip_watchdog(rcfw_module *m)
{
    m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] |= RCFW_HWERR_BUS_WATCHDOG;
    for (uint8_t i = 0; i < m->n_motors; i++) {
        m->ct[MA(TORQUE_ENABLE, i)] = 0;
        m->motor[i].enabled = 0;
        rcfw_hal_pwm_set(m->port, i, 0);
        rcfw_hal_bridge_enable(m->port, i, false);
    }
}

/* Bus watchdog stage 1: every motor holds where it is now. Its goal and speed-limited setpoint become its present
 * position, in position mode whatever its control_mode, its goal_pwm 0; the table's goals follow, so the host reads
 * the held goals and, once it clears bit6, the motors stay there until it writes new ones. Driven motors stay driven
 * (current limit as usual); bit6 latched. */
static void enter_hold(rcfw_module *m)
{
    for (uint8_t i = 0; i < m->n_motors; i++) {
        rcfw_motor *mo = &m->motor[i];
        mo->goal = mo->position;
        mo->setpoint = mo->position;
        mo->slew_acc = 0;
        mo->mode = RCFW_MODE_POSITION;
        mo->goal_pwm = 0;
        rcfwi_ct_w32(m, MA(GOAL_POSITION, i), mo->position);
        rcfwi_ct_w16(m, MA(GOAL_PWM, i), 0);
    }
    m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] |= RCFW_HWERR_BUS_HOLD;
}

/* One control period of the bus watchdog (bus_watchdog 0: off; stopped once stage 2 has tripped). A frame addressed
 * to the module restarts the count (wd_ticks = 0), also during a hold, which only the host's clear ends. */
static void watchdog_tick(rcfw_module *m)
{
    uint8_t hw = m->ct[RCFW_CT_HARDWARE_ERROR_STATUS];
    if (m->wd_limit_ticks == 0u || (hw & RCFW_HWERR_BUS_WATCHDOG)) {
        return;
    }
    uint32_t silent = ++m->wd_ticks;
    if (silent >= m->wd_off_ticks) {
        trip_watchdog(m);
    } else if (silent >= m->wd_limit_ticks && !(hw & RCFW_HWERR_BUS_HOLD)) {
        enter_hold(m);
    }
}

void rcfw_module_hall_edge(rcfw_module *m, uint8_t motor)
{
    RCFW_ASSERT(motor < m->n_motors);
    uint8_t s = rcfw_hal_hall_read(m->port, motor);
    if (s != m->hall_last[motor]) {
        m->hall_last[motor] = s;
        (void)rcfw_hall_update(&m->motor[motor], s);
    }
}

void rcfw_module_tick(rcfw_module *m)
{
    for (uint8_t i = 0; i < m->n_motors; i++) {
        rcfw_motor *mo = &m->motor[i];
        uint8_t s = rcfw_hal_hall_read(m->port, i);
        if (s != m->hall_last[i]) {
            m->hall_last[i] = s;
            (void)rcfw_hall_update(mo, s);
        }
        int16_t pwm = rcfw_motor_tick(mo, rcfw_hal_adc_current(m->port, i), m->ema_k, m->limit_step);
        rcfw_hal_pwm_set(m->port, i, pwm);
        rcfw_hal_bridge_enable(m->port, i, mo->enabled != 0u);
        m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] |= mo->errors; /* MERR bits are HWERR bits */
    }
    watchdog_tick(m);
    if (m->rx.in_frame && ++m->rx_idle_ticks >= RCFW_RX_TIMEOUT_TICKS) {
        rcfw_parser_reset(&m->rx);
        m->stats.rx_bad_len++;
    }
    if (++m->runtime_div >= RCFW_RUNTIME_SAVE_TICKS) {
        m->runtime_div = 0;
        m->runtime_due = 1;
    }
}

void rcfw_module_poll(rcfw_module *m)
{
    if (m->runtime_due) {
        m->runtime_due = 0;
        /* pot_raw follows the pots every 1 ms while running (the host compares them with the positions), sampled
         * here rather than in the control tick: each is a blocking ADC conversion */
        for (uint8_t i = 0; i < m->n_motors; i++) {
            rcfwi_ct_w16(m, MA(POT_RAW, i), rcfw_hal_adc_pot(m->port, i));
        }
        uint8_t img[RCFW_RUNTIME_LEN];
        rcfwi_runtime_image(m, img);
        if (memcmp(img, m->runtime_saved, RCFW_RUNTIME_LEN) != 0) {
            if (rcfw_store_save(&m->runtime, m->port, img)) {
                memcpy(m->runtime_saved, img, RCFW_RUNTIME_LEN);
            } else {
                m->stats.fram_errors++;
            }
        }
    }
    if (m->baud_pending) {
        m->baud_pending = 0;
        rcfw_hal_uart_set_baud(m->port, rcfw_module_baud_bps(m));
    }
}

bool rcfw_module_take_reboot(rcfw_module *m)
{
    bool r = m->reboot_pending != 0u;
    m->reboot_pending = 0;
    return r;
}

void rcfwi_factory_reset(rcfw_module *m, uint8_t mode)
{
    load_defaults(m, RCFW_CT_PERSISTENT_START, RCFW_CT_PERSISTENT_END, mode != 0xFFu, mode == 0x02u);
    set_fixed_identity(m);
    rcfwi_save_params(m);
    m->reboot_pending = 1;
}
