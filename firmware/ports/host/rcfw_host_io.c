/* Host port: what the simulation around the modules sets and reads (sensor inputs, outputs, control tables, FRAM,
 * power and resets, a broken transmit line). */
#include <string.h>

#include "host_bus.h"

int32_t rcfw_set_hall(rcfw_bus *bus, int32_t module, int32_t motor, uint8_t state)
{
    struct rcfw_port *p;
    if (host_check_motor(bus, module, motor, &p) != RCFW_HOST_OK || state > 7u) {
        return RCFW_HOST_EARG;
    }
    p->hall[motor] = state;
    if (p->powered) {
        rcfw_module_hall_edge(&p->mod, (uint8_t)motor);
    }
    return RCFW_HOST_OK;
}

/* A 12-bit ADC reading (0..4095) of one motor: its current sense, or its joint pot when `pot` is set. */
static int32_t set_adc_raw(rcfw_bus *bus, int32_t module, int32_t motor, uint16_t raw, bool pot)
{
    struct rcfw_port *p;
    if (host_check_motor(bus, module, motor, &p) != RCFW_HOST_OK || raw > 4095u) {
        return RCFW_HOST_EARG;
    }
    (pot ? p->pot : p->current)[motor] = raw;
    return RCFW_HOST_OK;
}

int32_t rcfw_set_current_raw(rcfw_bus *bus, int32_t module, int32_t motor, uint16_t raw)
{
    return set_adc_raw(bus, module, motor, raw, false);
}

int32_t rcfw_set_pot_raw(rcfw_bus *bus, int32_t module, int32_t motor, uint16_t raw)
{
    return set_adc_raw(bus, module, motor, raw, true);
}

int32_t rcfw_get_pwm(const rcfw_bus *bus, int32_t module, int32_t motor)
{
    struct rcfw_port *p;
    if (host_check_motor(bus, module, motor, &p) != RCFW_HOST_OK) {
        return RCFW_HOST_EARG;
    }
    return p->bridge[motor] ? p->pwm[motor] : 0;
}

int32_t rcfw_get_driver_enable(const rcfw_bus *bus, int32_t module, int32_t motor)
{
    struct rcfw_port *p;
    if (host_check_motor(bus, module, motor, &p) != RCFW_HOST_OK) {
        return RCFW_HOST_EARG;
    }
    return p->bridge[motor];
}

int32_t rcfw_get_tx_enable(const rcfw_bus *bus, int32_t module)
{
    struct rcfw_port *p = host_port_of(bus, module);
    if (!p) {
        return RCFW_HOST_EARG;
    }
    uint64_t now_ns = bus->now_us * 1000u;
    return p->powered && now_ns >= p->tx_start_ns && now_ns < p->tx_end_ns;
}

int32_t rcfw_get_position(const rcfw_bus *bus, int32_t module, int32_t motor)
{
    struct rcfw_port *p;
    if (host_check_motor(bus, module, motor, &p) != RCFW_HOST_OK) {
        return RCFW_HOST_EARG;
    }
    return p->mod.motor[motor].position;
}

int32_t rcfw_peek_table(const rcfw_bus *bus, int32_t module, uint16_t addr, uint8_t *buf, int32_t len)
{
    struct rcfw_port *p = host_port_of(bus, module);
    if (!p || len < 0 || (uint32_t)addr + (uint32_t)len > RCFW_CT_SIZE || (len > 0 && !buf)) {
        return RCFW_HOST_EARG;
    }
    memcpy(buf, p->mod.ct + addr, (size_t)len);
    return len;
}

int32_t rcfw_set_tx_broken(rcfw_bus *bus, int32_t module, int32_t broken)
{
    struct rcfw_port *p = host_port_of(bus, module);
    if (!p) {
        return RCFW_HOST_EARG;
    }
    p->tx_broken = broken != 0 ? 1u : 0u;
    return RCFW_HOST_OK;
}

int32_t rcfw_table_write(rcfw_bus *bus, int32_t module, uint16_t addr, const uint8_t *buf, int32_t len)
{
    struct rcfw_port *p = host_port_of(bus, module);
    if (!p || len <= 0 || len > 0xFFFF || !buf) {
        return RCFW_HOST_EARG;
    }
    return rcfw_module_write(&p->mod, addr, buf, (uint16_t)len);
}

int32_t rcfw_is_powered(const rcfw_bus *bus, int32_t module)
{
    struct rcfw_port *p = host_port_of(bus, module);
    return p ? p->powered : RCFW_HOST_EARG;
}

int32_t rcfw_power_cycle(rcfw_bus *bus, int32_t module)
{
    struct rcfw_port *p = host_port_of(bus, module);
    if (!p) {
        return RCFW_HOST_EARG;
    }
    p->cut_remaining = -1;
    host_boot(p, RCFW_RESET_POWER_ON);
    return RCFW_HOST_OK;
}

int32_t rcfw_power_off(rcfw_bus *bus, int32_t module)
{
    struct rcfw_port *p = host_port_of(bus, module);
    if (!p) {
        return RCFW_HOST_EARG;
    }
    host_power_fail(p);
    return RCFW_HOST_OK;
}

int32_t rcfw_reset(rcfw_bus *bus, int32_t module, uint8_t cause)
{
    struct rcfw_port *p = host_port_of(bus, module);
    if (!p || cause < RCFW_RESET_POWER_ON || cause > RCFW_RESET_LOCKUP) {
        return RCFW_HOST_EARG;
    }
    if (!p->powered) {
        return RCFW_HOST_EPOWER;
    }
    host_boot(p, cause);
    return RCFW_HOST_OK;
}

int32_t rcfw_fram_cut_after(rcfw_bus *bus, int32_t module, int32_t n_bytes)
{
    struct rcfw_port *p = host_port_of(bus, module);
    if (!p) {
        return RCFW_HOST_EARG;
    }
    p->cut_remaining = n_bytes < 0 ? -1 : n_bytes;
    return RCFW_HOST_OK;
}

int32_t rcfw_fram_peek(const rcfw_bus *bus, int32_t module, uint16_t addr, uint8_t *buf, int32_t len)
{
    struct rcfw_port *p = host_port_of(bus, module);
    if (!p || len < 0 || (uint32_t)addr + (uint32_t)len > RCFW_HOST_FRAM_SIZE || (len > 0 && !buf)) {
        return RCFW_HOST_EARG;
    }
    memcpy(buf, p->fram + addr, (size_t)len);
    return len;
}

int32_t rcfw_fram_poke(rcfw_bus *bus, int32_t module, uint16_t addr, const uint8_t *buf, int32_t len)
{
    struct rcfw_port *p = host_port_of(bus, module);
    if (!p || len < 0 || (uint32_t)addr + (uint32_t)len > RCFW_HOST_FRAM_SIZE || (len > 0 && !buf)) {
        return RCFW_HOST_EARG;
    }
    memcpy(p->fram + addr, buf, (size_t)len);
    return len;
}
