/* Control-table access rules (which status error a read or write gets) and applying writes. */
#include <string.h>

#include "internal.h"
#include "rcfw/hal.h"
#include "rcfw/verify.h"

#define MA RCFWI_MA

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

static int32_t ct32_after(const rcfw_module *m, const pending_write *w, uint16_t a)
{
    uint32_t raw = 0;
    for (uint8_t b = 4; b > 0; b--) {
        raw = (raw << 8) | ct8_after(m, w, (uint16_t)(a + b - 1u));
    }
    return (int32_t)raw;
}

static const rcfw_ct_field *owner(uint16_t a)
{
    uint8_t o = rcfw_ct_owner[a];
    return o == 0u ? 0 : &rcfw_ct_fields[o - 1u];
}

/* First byte of the instance of f that contains byte a. */
static uint16_t instance_start(const rcfw_ct_field *f, uint16_t a)
{
    return f->count > 1u ? (uint16_t)(f->address + ((a - f->address) / f->stride) * f->stride) : f->address;
}

uint8_t rcfwi_check_read(const rcfw_module *m, uint16_t addr, uint16_t len)
{
    (void)m;
    if (len == 0u) {
        return RCFW_ERR_DATA_LENGTH;
    }
    if ((uint32_t)addr + len > RCFW_CT_SIZE) {
        return RCFW_ERR_ACCESS;
    }
    for (uint16_t a = addr; a < addr + len; a++) {
        const rcfw_ct_field *f = owner(a);
        if (f == 0 || (f->flags & RCFW_CT_F_WRITE_ONLY)) {
            return RCFW_ERR_ACCESS;
        }
    }
    return 0;
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

static bool any_torque(const rcfw_module *m)
{
    for (uint8_t i = 0; i < RCFW_CT_MAX_MOTORS; i++) {
        if (m->ct[MA(TORQUE_ENABLE, i)] != 0u) {
            return true;
        }
    }
    return false;
}

/* Configured limits (data limit error): a goal position outside its motor's position_min..position_max. */
static bool within_limits(const rcfw_module *m, const pending_write *w, uint16_t start)
{
    for (uint8_t i = 0; i < RCFW_CT_MAX_MOTORS; i++) {
        if (start == MA(GOAL_POSITION, i)) {
            int32_t g = ct32_after(m, w, start);
            return g >= ct32_after(m, w, MA(POSITION_MIN, i)) && g <= ct32_after(m, w, MA(POSITION_MAX, i));
        }
    }
    return true;
}

static uint16_t ct16_after(const rcfw_module *m, const pending_write *w, uint16_t a)
{
    return (uint16_t)(ct8_after(m, w, a) | (ct8_after(m, w, (uint16_t)(a + 1u)) << 8));
}

/* The bus watchdog's stages in order (data limit error otherwise), as the write leaves them: bus_watchdog_off is 0
 * (no hold stage) or later than bus_watchdog. */
static bool watchdog_stages_ordered(const rcfw_module *m, const pending_write *w)
{
    uint16_t off = ct16_after(m, w, RCFW_CT_BUS_WATCHDOG_OFF);
    return off == 0u || off > ct16_after(m, w, RCFW_CT_BUS_WATCHDOG);
}

/* A field whose write would move a motor: a goal (position or PWM), or torque_enable 1. */
static bool starts_motion(uint16_t start, int32_t v)
{
    for (uint8_t i = 0; i < RCFW_CT_MAX_MOTORS; i++) {
        if (start == MA(GOAL_POSITION, i) || start == MA(GOAL_PWM, i) || (start == MA(TORQUE_ENABLE, i) && v != 0)) {
            return true;
        }
    }
    return false;
}

static uint8_t check_value(rcfw_module *m, const pending_write *w, const rcfw_ct_field *f, uint16_t start)
{
    uint32_t raw = 0;
    for (uint8_t b = f->size; b > 0; b--) {
        raw = (raw << 8) | ct8_after(m, w, (uint16_t)(start + b - 1u));
    }
    int32_t v = rcfwi_field_value(f, raw);
    bool in_range = (f->size == 4u && !(f->flags & RCFW_CT_F_SIGNED)) ? raw <= (uint32_t)f->max
                                                                      : (v >= f->min && v <= f->max);
    RCFW_VERIFY(in_range, m->stats.bad_requests, RCFW_ERR_DATA_RANGE);
    RCFW_VERIFY(within_limits(m, w, start), m->stats.bad_requests, RCFW_ERR_DATA_LIMIT);
    if (start == RCFW_CT_BUS_WATCHDOG || start == RCFW_CT_BUS_WATCHDOG_OFF) {
        RCFW_VERIFY(watchdog_stages_ordered(m, w), m->stats.bad_requests, RCFW_ERR_DATA_LIMIT);
    }
    if (start == RCFW_CT_HOME_REQUEST) {
        RCFW_VERIFY(home_allowed(m, w, (uint8_t)v), m->stats.bad_requests, RCFW_ERR_RESULT_FAIL);
    }
    if (start >= RCFW_CT_TORQUE_ENABLE && start < RCFW_CT_TORQUE_ENABLE + RCFW_CT_MAX_MOTORS && v != 0) {
        RCFW_VERIFY(!(m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] & RCFW_HWERR_BUS_WATCHDOG), m->stats.bad_requests,
                    RCFW_ERR_RESULT_FAIL);
    }
    /* while holding (bus watchdog stage 1) nothing starts moving until the host has cleared bit6 */
    if (starts_motion(start, v)) {
        RCFW_VERIFY(!(m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] & RCFW_HWERR_BUS_HOLD), m->stats.bad_requests,
                    RCFW_ERR_RESULT_FAIL);
    }
    return 0;
}

uint8_t rcfwi_check_write(rcfw_module *m, uint16_t addr, const uint8_t *data, uint16_t len)
{
    RCFW_VERIFY(len > 0u, m->stats.bad_requests, RCFW_ERR_DATA_LENGTH);
    RCFW_VERIFY((uint32_t)addr + len <= RCFW_CT_SIZE, m->stats.bad_requests, RCFW_ERR_ACCESS);
    uint16_t end = (uint16_t)(addr + len);
    const pending_write w = {addr, end, data};
    for (uint16_t a = addr; a < end; a++) {
        const rcfw_ct_field *f = owner(a);
        RCFW_VERIFY(f != 0 && (f->flags & RCFW_CT_F_WRITABLE), m->stats.bad_requests, RCFW_ERR_ACCESS);
    }
    /* every touched field instance must be covered completely */
    for (uint16_t a = addr; a < end;) {
        const rcfw_ct_field *f = owner(a);
        uint16_t start = instance_start(f, a);
        RCFW_VERIFY(start >= addr && start + f->size <= end, m->stats.bad_requests, RCFW_ERR_DATA_LENGTH);
        a = (uint16_t)(start + f->size);
    }
    /* the persistent (EEPROM-like) area is locked while any motor is driven */
    RCFW_VERIFY(addr >= RCFW_CT_PERSISTENT_END || !any_torque(m), m->stats.bad_requests, RCFW_ERR_ACCESS);
    for (uint16_t a = addr; a < end;) {
        const rcfw_ct_field *f = owner(a);
        uint16_t start = instance_start(f, a);
        uint8_t e = check_value(m, &w, f, start);
        if (e != 0u) {
            return e;
        }
        a = (uint16_t)(start + f->size);
    }
    return 0;
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
        rcfwi_ct_w16(m, MA(POT_RAW, i), pot);
        int32_t pos = 0;
        bool calibrated = rcfw_pot_to_position(m, i, pot, &pos);
        RCFW_ASSERT(calibrated); /* home_allowed() checked the calibration */
        rcfw_motor_set_position(&m->motor[i], pos, m->hall_last[i]);
        m->motor[i].errors &= (uint8_t)~(RCFW_MERR_POT | RCFW_MERR_POSITION_LOST);
        rcfwi_ct_w32(m, MA(GOAL_POSITION, i), pos);
    }
    refresh_position_errors(m);
    uint8_t img[RCFW_RUNTIME_LEN];
    rcfwi_runtime_image(m, img);
    if (rcfw_store_save(&m->runtime, m->port, img)) {
        memcpy(m->runtime_saved, img, RCFW_RUNTIME_LEN);
    } else {
        m->stats.fram_errors++;
    }
}

void rcfwi_clear_errors(rcfw_module *m)
{
    m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] = 0;
    for (uint8_t i = 0; i < m->n_motors; i++) {
        m->motor[i].errors = 0;
        m->ct[MA(MOTOR_ERROR, i)] = 0;
    }
    m->wd_ticks = 0;
    rcfwi_apply_params(m);
}

uint8_t rcfwi_write(rcfw_module *m, uint16_t addr, const uint8_t *data, uint16_t len)
{
    uint8_t e = rcfwi_check_write(m, addr, data, len);
    if (e != 0u) {
        return e;
    }
    uint16_t end = (uint16_t)(addr + len);
    uint8_t old_baud = m->ct[RCFW_CT_BAUD_RATE];
    memcpy(&m->ct[addr], data, len);
    if (addr <= RCFW_CT_HARDWARE_ERROR_STATUS && end > RCFW_CT_HARDWARE_ERROR_STATUS) {
        rcfwi_clear_errors(m); /* the value is 0 (checked) */
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
    rcfwi_apply_params(m);
    if (addr < RCFW_CT_PERSISTENT_END) {
        rcfwi_save_params(m); /* durable before acknowledged */
    }
    return 0;
}

uint8_t rcfw_module_write(rcfw_module *m, uint16_t addr, const uint8_t *data, uint16_t len)
{
    return rcfwi_write(m, addr, data, len);
}
