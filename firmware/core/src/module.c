#include "rcfw/module.h"

#include <string.h>

#include "rcfw/hal.h"
#include "rcfw/verify.h"

/* ---- little-endian table access ---- */
static uint32_t rd_u(const uint8_t *p, uint8_t size)
{
    uint32_t v = 0;
    for (uint8_t i = size; i > 0; i--) {
        v = (v << 8) | p[i - 1u];
    }
    return v;
}
static void wr_u(uint8_t *p, uint8_t size, uint32_t v)
{
    for (uint8_t i = 0; i < size; i++) {
        p[i] = (uint8_t)v;
        v >>= 8;
    }
}
static inline uint8_t ct8(const rcfw_module *m, uint16_t a) { return m->ct[a]; }
static inline uint16_t ct16(const rcfw_module *m, uint16_t a) { return (uint16_t)(m->ct[a] | (m->ct[a + 1u] << 8)); }
static inline int32_t ct32(const rcfw_module *m, uint16_t a) { return (int32_t)rd_u(&m->ct[a], 4); }
static inline void ct_w16(rcfw_module *m, uint16_t a, uint16_t v)
{
    m->ct[a] = (uint8_t)v;
    m->ct[a + 1u] = (uint8_t)(v >> 8);
}
static inline void ct_w32(rcfw_module *m, uint16_t a, int32_t v)
{
    uint32_t u = (uint32_t)v;
    m->ct[a] = (uint8_t)u;
    m->ct[a + 1u] = (uint8_t)(u >> 8);
    m->ct[a + 2u] = (uint8_t)(u >> 16);
    m->ct[a + 3u] = (uint8_t)(u >> 24);
}
#define MA(field, i) ((uint16_t)(RCFW_CT_##field + (i) * RCFW_CT_##field##_STRIDE))

/* The tick ORs every motor's error bits into hardware_error_status: they must mean the same there. */
_Static_assert(RCFW_MERR_OVERCURRENT == RCFW_HWERR_OVERCURRENT && RCFW_MERR_HALL == RCFW_HWERR_HALL &&
                   RCFW_MERR_POT == RCFW_HWERR_POT_MISMATCH && RCFW_MERR_POSITION_LOST == RCFW_HWERR_POSITION_LOST,
               "motor error bits are hardware_error_status bits");

static int32_t field_value(const rcfw_ct_field *f, uint32_t raw)
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
                wr_u(&m->ct[a], f->size, (uint32_t)f->def);
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
            int32_t v = field_value(f, rd_u(&m->ct[a], f->size));
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
    ct_w16(m, RCFW_CT_MODEL_NUMBER, (uint16_t)rcfw_ct_fields[RCFW_CT_FIELD_MODEL_NUMBER].def);
    m->ct[RCFW_CT_FIRMWARE_VERSION] = RCFW_FIRMWARE_VERSION;
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
    uint8_t n = ct8(m, MA(POT_CAL_COUNT, motor));
    if (n < 2u || n > 8u) {
        return false;
    }
    int32_t pos0 = ct32(m, MA(POT_CAL_POS0, motor));
    int32_t step = ct32(m, MA(POT_CAL_STEP, motor));
    uint16_t base = MA(POT_CAL_RAW0, motor);
    int32_t best = 0;
    uint32_t best_dist = 0xFFFFFFFFu;
    for (uint8_t i = 0; i + 1u < n; i++) {
        int32_t r0 = ct16(m, (uint16_t)(base + 2u * i));
        int32_t r1 = ct16(m, (uint16_t)(base + 2u * i + 2u));
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

static void apply_params(rcfw_module *m)
{
    uint8_t hw = m->ct[RCFW_CT_HARDWARE_ERROR_STATUS];
    m->ema_k = m->ct[RCFW_CT_CURRENT_FILTER_SHIFT];
    m->limit_step = m->ct[RCFW_CT_CURRENT_LIMIT_STEP];
    m->wd_limit_ticks = (uint32_t)ct16(m, RCFW_CT_BUS_WATCHDOG) * (RCFW_CONTROL_RATE_HZ / 1000u);
    for (uint8_t i = 0; i < m->n_motors; i++) {
        rcfw_motor *mo = &m->motor[i];
        mo->kp = ct16(m, MA(KP, i));
        mo->step_q16 = rcfw_slew_step_q16(ct16(m, MA(SPEED_LIMIT, i)), RCFW_CONTROL_RATE_HZ);
        mo->current_limit = ct16(m, MA(CURRENT_LIMIT, i));
        mo->mode = ct8(m, MA(CONTROL_MODE, i));
        int32_t g = ct32(m, MA(GOAL_POSITION, i));
        int32_t lo = ct32(m, MA(POSITION_MIN, i)), hi = ct32(m, MA(POSITION_MAX, i));
        mo->goal = g < lo ? lo : (g > hi ? hi : g);
        mo->goal_pwm = (int16_t)ct16(m, MA(GOAL_PWM, i));
        mo->enabled = (uint8_t)(ct8(m, MA(TORQUE_ENABLE, i)) && !(hw & RCFW_HWERR_BUS_WATCHDOG));
    }
}

static void publish(rcfw_module *m, uint8_t i)
{
    const rcfw_motor *mo = &m->motor[i];
    ct_w32(m, MA(PRESENT_POSITION, i), mo->position);
    ct_w16(m, MA(PRESENT_CURRENT, i), mo->cur_ma);
    ct_w16(m, MA(PRESENT_PWM, i), (uint16_t)mo->pwm);
    ct_w16(m, MA(HALL_ERROR_COUNT, i), mo->hall_errors);
    m->ct[MA(MOTOR_ERROR, i)] = mo->errors;
    ct_w32(m, MA(PRESENT_SETPOINT, i), mo->setpoint);
}

void rcfw_module_publish(rcfw_module *m)
{
    for (uint8_t i = 0; i < m->n_motors; i++) {
        publish(m, i);
    }
}

static void runtime_image(const rcfw_module *m, uint8_t *img)
{
    memset(img, 0, RCFW_RUNTIME_LEN);
    for (uint8_t i = 0; i < m->n_motors; i++) {
        wr_u(img + 8u * i, 4, (uint32_t)m->motor[i].position);
        wr_u(img + 8u * i + 4u, 4, (uint32_t)ct32(m, MA(GOAL_POSITION, i)));
    }
}

static void save_params(rcfw_module *m)
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
        save_params(m);
    }
    set_fixed_identity(m);

    uint8_t img[RCFW_RUNTIME_LEN];
    bool have_runtime = rcfw_store_load(&m->runtime, port, img);
    uint16_t tol = ct16(m, RCFW_CT_POT_MISMATCH_TOLERANCE);
    for (uint8_t i = 0; i < n_motors; i++) {
        rcfw_motor *mo = &m->motor[i];
        mo->cap = RCFW_PWM_MAX;
        uint8_t hall = rcfw_hal_hall_read(port, i);
        m->hall_last[i] = hall;
        uint16_t pot = rcfw_hal_adc_pot(port, i);
        ct_w16(m, MA(POT_RAW, i), pot);
        int32_t pot_pos = 0;
        bool calibrated = rcfw_pot_to_position(m, i, pot, &pot_pos);
        int32_t pos, goal;
        if (have_runtime) {
            pos = (int32_t)rd_u(img + 8u * i, 4);
            goal = (int32_t)rd_u(img + 8u * i + 4u, 4);
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
        ct_w32(m, MA(GOAL_POSITION, i), goal);
        rcfw_hal_pwm_set(port, i, 0);
        rcfw_hal_bridge_enable(port, i, false);
    }
    m->ct[RCFW_CT_RESET_CAUSE] = reset_cause;
    m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] = hw;
    for (uint8_t i = 0; i < n_motors; i++) {
        m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] |= m->motor[i].errors;
    }
    apply_params(m);
    rcfw_module_publish(m);
    runtime_image(m, m->runtime_saved);
    if (!have_runtime && !rcfw_store_save(&m->runtime, port, m->runtime_saved)) {
        m->stats.fram_errors++;
    }
    rcfw_hal_uart_set_baud(port, rcfw_module_baud_bps(m));
}

static void trip_watchdog(rcfw_module *m)
{
    m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] |= RCFW_HWERR_BUS_WATCHDOG;
    for (uint8_t i = 0; i < m->n_motors; i++) {
        m->ct[MA(TORQUE_ENABLE, i)] = 0;
        m->motor[i].enabled = 0;
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
    if (m->wd_limit_ticks != 0u && !(m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] & RCFW_HWERR_BUS_WATCHDOG)) {
        if (++m->wd_ticks >= m->wd_limit_ticks) {
            trip_watchdog(m);
            for (uint8_t i = 0; i < m->n_motors; i++) {
                rcfw_hal_pwm_set(m->port, i, 0);
                rcfw_hal_bridge_enable(m->port, i, false);
            }
        }
    }
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
        uint8_t img[RCFW_RUNTIME_LEN];
        runtime_image(m, img);
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

/* A write being validated: bytes addr..end-1 become data. */
typedef struct {
    uint16_t addr;
    uint16_t end;
    const uint8_t *data;
} pending_write;

/* Byte a of the table as it will be once the pending write is applied. */
static uint8_t ct8_after(const rcfw_module *m, const pending_write *w, uint16_t a)
{
    return a >= w->addr && a < w->end ? w->data[a - w->addr] : m->ct[a];
}

/* A home_request of mask is allowed if every requested motor exists, has a pot calibration and is not
 * driven (judged on the table as the same write leaves it). A driven motor is refused rather than
 * re-homed under power: its new coordinates would turn the host's next goal (still in the old ones)
 * into a sudden move. */
static bool home_allowed(const rcfw_module *m, const pending_write *w, uint8_t mask)
{
    for (uint8_t i = 0; i < RCFW_CT_MAX_MOTORS; i++) {
        if (!((mask >> i) & 1u)) {
            continue;
        }
        if (i >= m->n_motors || ct8_after(m, w, MA(POT_CAL_COUNT, i)) < 2u ||
            ct8_after(m, w, MA(TORQUE_ENABLE, i)) != 0u) {
            return false;
        }
    }
    return true;
}

/* Recompute the module's pot-mismatch and position-lost bits from the motors (other bits stay latched). */
static void refresh_position_errors(rcfw_module *m)
{
    const uint8_t bits = RCFW_HWERR_POT_MISMATCH | RCFW_HWERR_POSITION_LOST;
    uint8_t still = 0;
    for (uint8_t i = 0; i < m->n_motors; i++) {
        still |= m->motor[i].errors & bits;
        m->ct[MA(MOTOR_ERROR, i)] = m->motor[i].errors;
    }
    m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] = (uint8_t)((m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] & ~bits) | still);
}

/* Home the motors in mask from their pots now (home_allowed() passed): position, setpoint and goal
 * become the pot position, so nothing moves when torque comes on; the record is saved before the reply. */
static void home_from_pots(rcfw_module *m, uint8_t mask)
{
    for (uint8_t i = 0; i < m->n_motors; i++) {
        if (!((mask >> i) & 1u)) {
            continue;
        }
        uint16_t pot = rcfw_hal_adc_pot(m->port, i);
        ct_w16(m, MA(POT_RAW, i), pot);
        int32_t pos = 0;
        bool calibrated = rcfw_pot_to_position(m, i, pot, &pos);
        RCFW_ASSERT(calibrated); /* home_allowed() checked the calibration */
        rcfw_motor_set_position(&m->motor[i], pos, m->hall_last[i]);
        m->motor[i].errors &= (uint8_t)~(RCFW_MERR_POT | RCFW_MERR_POSITION_LOST);
        ct_w32(m, MA(GOAL_POSITION, i), pos);
    }
    refresh_position_errors(m);
    uint8_t img[RCFW_RUNTIME_LEN];
    runtime_image(m, img);
    if (rcfw_store_save(&m->runtime, m->port, img)) {
        memcpy(m->runtime_saved, img, RCFW_RUNTIME_LEN);
    } else {
        m->stats.fram_errors++;
    }
}

/* Validate and apply a write. *persist set if persistent bytes changed. */
static uint8_t table_write(rcfw_module *m, uint16_t addr, const uint8_t *data, uint16_t len, bool *persist)
{
    RCFW_VERIFY(len > 0u, m->stats.bad_requests, RCFW_ERR_DATA_LENGTH);
    RCFW_VERIFY((uint32_t)addr + len <= RCFW_CT_SIZE, m->stats.bad_requests, RCFW_ERR_DATA_RANGE);
    uint16_t end = (uint16_t)(addr + len);
    const pending_write w = {addr, end, data};
    for (uint16_t a = addr; a < end; a++) {
        uint8_t o = rcfw_ct_owner[a];
        RCFW_VERIFY(o != 0u && (rcfw_ct_fields[o - 1u].flags & RCFW_CT_F_WRITABLE), m->stats.bad_requests,
                    RCFW_ERR_ACCESS);
    }
    /* range-check every field instance touched, composing old and new bytes */
    for (uint16_t a = addr; a < end;) {
        const rcfw_ct_field *f = &rcfw_ct_fields[rcfw_ct_owner[a] - 1u];
        uint16_t start = f->address;
        if (f->count > 1u) {
            start = (uint16_t)(f->address + ((a - f->address) / f->stride) * f->stride);
        }
        uint32_t raw = 0;
        for (uint8_t b = f->size; b > 0; b--) {
            uint16_t x = (uint16_t)(start + b - 1u);
            raw = (raw << 8) | (x >= addr && x < end ? data[x - addr] : m->ct[x]);
        }
        int32_t v = field_value(f, raw);
        bool ok = (f->size == 4u && !(f->flags & RCFW_CT_F_SIGNED)) ? raw <= (uint32_t)f->max
                                                                    : (v >= f->min && v <= f->max);
        RCFW_VERIFY(ok, m->stats.bad_requests, RCFW_ERR_DATA_LIMIT);
        if (start == RCFW_CT_HOME_REQUEST) {
            RCFW_VERIFY(home_allowed(m, &w, (uint8_t)v), m->stats.bad_requests, RCFW_ERR_RESULT_FAIL);
        }
        if (start >= RCFW_CT_TORQUE_ENABLE && start < RCFW_CT_TORQUE_ENABLE + RCFW_CT_MAX_MOTORS && v != 0) {
            RCFW_VERIFY(!(m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] & RCFW_HWERR_BUS_WATCHDOG), m->stats.bad_requests,
                        RCFW_ERR_RESULT_FAIL);
        }
        a = (uint16_t)(start + f->size);
    }
    uint8_t old_baud = m->ct[RCFW_CT_BAUD_RATE];
    memcpy(&m->ct[addr], data, len);
    *persist = addr < RCFW_CT_PERSISTENT_END;
    if (addr <= RCFW_CT_HARDWARE_ERROR_STATUS && end > RCFW_CT_HARDWARE_ERROR_STATUS) {
        /* value is 0 (checked): clear every latched error */
        for (uint8_t i = 0; i < m->n_motors; i++) {
            m->motor[i].errors = 0;
            m->ct[MA(MOTOR_ERROR, i)] = 0;
        }
        m->wd_ticks = 0;
    }
    if (addr < RCFW_CT_BUS_WATCHDOG + 2u && end > RCFW_CT_BUS_WATCHDOG) {
        m->wd_ticks = 0;
    }
    if (m->ct[RCFW_CT_HOME_REQUEST] != 0u) {
        home_from_pots(m, m->ct[RCFW_CT_HOME_REQUEST]);
        m->ct[RCFW_CT_HOME_REQUEST] = 0;
    }
    if (m->ct[RCFW_CT_BAUD_RATE] != old_baud) {
        m->baud_pending = 1;
    }
    apply_params(m);
    return 0;
}

uint8_t rcfw_module_write(rcfw_module *m, uint16_t addr, const uint8_t *data, uint16_t len)
{
    bool persist = false;
    uint8_t e = table_write(m, addr, data, len, &persist);
    if (e == 0u && persist) {
        save_params(m);
    }
    return e;
}

/* ---- protocol ---- */

static uint32_t byte_slots_us(const rcfw_module *m, uint32_t bytes)
{
    uint64_t ns = (uint64_t)bytes * 10u * 1000000000u / rcfw_module_baud_bps(m);
    return (uint32_t)((ns + 999u) / 1000u);
}

static void reply(rcfw_module *m, uint8_t err, const uint8_t *data, uint16_t len, uint32_t extra_delay_us)
{
    RCFW_ASSERT(len + 2u <= sizeof m->body);
    if (m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] != 0u) {
        err |= RCFW_ERR_ALERT;
    }
    m->body[0] = RCFW_INST_STATUS;
    m->body[1] = err;
    if (len) {
        memcpy(&m->body[2], data, len);
    }
    uint16_t n = rcfw_frame_build(m->tx, sizeof m->tx, m->ct[RCFW_CT_ID], m->body, (uint16_t)(len + 2u));
    RCFW_ASSERT(n != 0u);
    rcfw_hal_uart_send(m->port, m->tx, n, 2u * m->ct[RCFW_CT_RETURN_DELAY_TIME] + extra_delay_us);
}

static uint16_t le16(const uint8_t *p) { return (uint16_t)(p[0] | (p[1] << 8)); }

static void handle_frame(rcfw_module *m)
{
    const rcfw_parser *f = &m->rx;
    uint8_t my = m->ct[RCFW_CT_ID];
    bool bcast = f->id == RCFW_ID_BROADCAST;
    const uint8_t *pa = f->params;
    uint16_t pl = f->plen;
    if (f->inst == RCFW_INST_STATUS || (!bcast && f->id != my)) {
        return;
    }
    switch (f->inst) {
    case RCFW_INST_PING: {
        m->wd_ticks = 0;
        uint8_t d[3] = {m->ct[RCFW_CT_MODEL_NUMBER], m->ct[RCFW_CT_MODEL_NUMBER + 1u], m->ct[RCFW_CT_FIRMWARE_VERSION]};
        /* broadcast: one 16-byte-time slot per ID so replies never overlap */
        reply(m, 0, d, 3, bcast ? byte_slots_us(m, 16u * my) : 0u);
        return;
    }
    case RCFW_INST_READ: {
        if (bcast) {
            return;
        }
        m->wd_ticks = 0;
        if (pl != 4u) {
            m->stats.bad_requests++;
            reply(m, RCFW_ERR_DATA_LENGTH, 0, 0, 0);
            return;
        }
        uint16_t a = le16(pa), n = le16(pa + 2);
        if (n == 0u || (uint32_t)a + n > RCFW_CT_SIZE) {
            m->stats.bad_requests++;
            reply(m, RCFW_ERR_DATA_RANGE, 0, 0, 0);
            return;
        }
        rcfw_module_publish(m);
        reply(m, 0, &m->ct[a], n, 0);
        return;
    }
    case RCFW_INST_WRITE: {
        m->wd_ticks = 0;
        uint8_t e;
        bool persist = false;
        if (pl < 3u) {
            m->stats.bad_requests++;
            e = RCFW_ERR_DATA_LENGTH;
        } else {
            e = table_write(m, le16(pa), pa + 2, (uint16_t)(pl - 2u), &persist);
        }
        if (persist) {
            save_params(m); /* durable before acknowledged */
        }
        if (!bcast) {
            reply(m, e, 0, 0, 0);
        }
        return;
    }
    case RCFW_INST_FACTORY_RESET: {
        m->wd_ticks = 0;
        uint8_t mode = pl == 1u ? pa[0] : 0u;
        if (mode != 0xFFu && mode != 0x01u && mode != 0x02u) {
            m->stats.bad_requests++;
            if (!bcast) {
                reply(m, pl == 1u ? RCFW_ERR_DATA_RANGE : RCFW_ERR_DATA_LENGTH, 0, 0, 0);
            }
            return;
        }
        if (!bcast) {
            reply(m, 0, 0, 0, 0);
        }
        load_defaults(m, RCFW_CT_PERSISTENT_START, RCFW_CT_PERSISTENT_END, mode != 0xFFu, mode == 0x02u);
        set_fixed_identity(m);
        save_params(m);
        m->reboot_pending = 1;
        return;
    }
    case RCFW_INST_REBOOT:
        m->wd_ticks = 0;
        if (!bcast) {
            reply(m, 0, 0, 0, 0);
        }
        m->reboot_pending = 1;
        return;
    case RCFW_INST_SYNC_READ: {
        if (!bcast || pl < 5u) {
            m->stats.bad_requests++;
            return;
        }
        uint16_t a = le16(pa), n = le16(pa + 2);
        for (uint16_t k = 0; k < pl - 4u; k++) {
            if (pa[4u + k] != my) {
                continue;
            }
            m->wd_ticks = 0;
            /* slot k: all earlier replies (11 + n bytes, worst-case stuffing n/3, 2 gap) */
            uint32_t delay = byte_slots_us(m, (uint32_t)k * (13u + n + n / 3u));
            if (n == 0u || (uint32_t)a + n > RCFW_CT_SIZE) {
                m->stats.bad_requests++;
                reply(m, RCFW_ERR_DATA_RANGE, 0, 0, delay);
            } else {
                rcfw_module_publish(m);
                reply(m, 0, &m->ct[a], n, delay);
            }
            return;
        }
        return;
    }
    case RCFW_INST_SYNC_WRITE: {
        if (!bcast || pl < 5u) {
            m->stats.bad_requests++;
            return;
        }
        uint16_t a = le16(pa), n = le16(pa + 2);
        if (n == 0u || (pl - 4u) % (n + 1u) != 0u) {
            m->stats.bad_requests++;
            return;
        }
        for (uint16_t o = 4; o < pl; o = (uint16_t)(o + n + 1u)) {
            if (pa[o] != my) {
                continue;
            }
            m->wd_ticks = 0;
            bool persist = false;
            if (table_write(m, a, pa + o + 1u, n, &persist) == 0u && persist) {
                save_params(m);
            }
            return;
        }
        return;
    }
    default:
        m->stats.bad_requests++;
        if (!bcast) {
            reply(m, RCFW_ERR_INSTRUCTION, 0, 0, 0);
        }
        return;
    }
}

void rcfw_module_rx_byte(rcfw_module *m, uint8_t byte)
{
    m->rx_idle_ticks = 0;
    rcfw_rx_result r = rcfw_parser_feed(&m->rx, byte);
    switch (r) {
    case RCFW_RX_FRAME:
        m->stats.rx_frames++;
        handle_frame(m);
        break;
    case RCFW_RX_BAD_CRC:
        m->stats.rx_bad_crc++;
        break;
    case RCFW_RX_BAD_LEN:
        m->stats.rx_bad_len++;
        break;
    case RCFW_RX_BAD_STUFF:
        m->stats.rx_bad_stuff++;
        break;
    default:
        break;
    }
}
