/* Private to the core: helpers shared by module.c (state, control), table.c (control-table access
 * rules) and bus.c (instructions). Not part of the port interface. */
#ifndef RCFW_INTERNAL_H
#define RCFW_INTERNAL_H
#include <stdbool.h>
#include <stdint.h>

#include "rcfw/module.h"

uint32_t rcfwi_rd_le(const uint8_t *p, uint8_t size);
void rcfwi_wr_le(uint8_t *p, uint8_t size, uint32_t v);
static inline uint8_t rcfwi_ct8(const rcfw_module *m, uint16_t a) { return m->ct[a]; }
static inline uint16_t rcfwi_ct16(const rcfw_module *m, uint16_t a)
{
    return (uint16_t)(m->ct[a] | (m->ct[a + 1u] << 8));
}
static inline int32_t rcfwi_ct32(const rcfw_module *m, uint16_t a) { return (int32_t)rcfwi_rd_le(&m->ct[a], 4); }
static inline void rcfwi_ct_w16(rcfw_module *m, uint16_t a, uint16_t v)
{
    m->ct[a] = (uint8_t)v;
    m->ct[a + 1u] = (uint8_t)(v >> 8);
}
static inline void rcfwi_ct_w32(rcfw_module *m, uint16_t a, int32_t v) { rcfwi_wr_le(&m->ct[a], 4, (uint32_t)v); }
#define RCFWI_MA(field, i) ((uint16_t)(RCFW_CT_##field + (i) * RCFW_CT_##field##_STRIDE))

/* Field value from its little-endian raw bytes (sign-extended for signed fields). */
int32_t rcfwi_field_value(const rcfw_ct_field *f, uint32_t raw);
/* Recompute the runtime parameters (gains, limits, goals) from the table. */
void rcfwi_apply_params(rcfw_module *m);
/* Persistent area to FRAM (counted in stats.fram_errors on failure). */
void rcfwi_save_params(rcfw_module *m);
/* Position/goal record image. */
void rcfwi_runtime_image(const rcfw_module *m, uint8_t *img);
/* Factory reset (mode 0xFF all, 0x01 all but ID, 0x02 all but ID and baud), saved; reboot pending. */
void rcfwi_factory_reset(rcfw_module *m, uint8_t mode);
/* Clear every latched error (hardware_error_status, motor_error, watchdog count). */
void rcfwi_clear_errors(rcfw_module *m);

/* Status error (0 = allowed) for reading len bytes at addr. */
uint8_t rcfwi_check_read(const rcfw_module *m, uint16_t addr, uint16_t len);
/* Status error (0 = allowed) for writing data (len bytes) at addr; changes nothing. */
uint8_t rcfwi_check_write(rcfw_module *m, uint16_t addr, const uint8_t *data, uint16_t len);
/* Check, apply atomically and, if persistent bytes changed, save them before returning. */
uint8_t rcfwi_write(rcfw_module *m, uint16_t addr, const uint8_t *data, uint16_t len);
/* FAST SYNC READ / FAST BULK READ instruction (fast.c), and every byte heard while a part waits. */
void rcfwi_fast_read(rcfw_module *m, const rcfw_parser *f);
void rcfwi_fast_heard(rcfw_module *m, uint8_t b);
#endif
