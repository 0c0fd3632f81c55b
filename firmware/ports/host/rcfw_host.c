/* Host port: N firmware modules on one simulated RS-485 bus in simulated time (the modules' HAL, the bus, time;
 * what the simulation around them sets and reads is in rcfw_host_io.c). */
#include "host_bus.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void rcfw_assert_failed(int line)
{
    fprintf(stderr, "rcfw: firmware assertion failed at module.c line %d\n", line);
    abort();
}

/* ---- HAL ---- */
void rcfw_hal_pwm_set(struct rcfw_port *p, uint8_t motor, int16_t pwm)
{
    if (p->powered && motor < p->n_motors) {
        p->pwm[motor] = pwm;
    }
}
void rcfw_hal_bridge_enable(struct rcfw_port *p, uint8_t motor, bool on)
{
    if (p->powered && motor < p->n_motors) {
        p->bridge[motor] = on ? 1u : 0u;
    }
}
uint16_t rcfw_hal_adc_current(struct rcfw_port *p, uint8_t motor) { return p->current[motor]; }
uint16_t rcfw_hal_adc_pot(struct rcfw_port *p, uint8_t motor) { return p->pot[motor]; }
uint8_t rcfw_hal_hall_read(struct rcfw_port *p, uint8_t motor) { return p->hall[motor]; }
void rcfw_hal_uart_set_baud(struct rcfw_port *p, uint32_t bps) { p->uart_bps = bps; }

static uint64_t byte_ns(uint32_t bps) { return 10ull * 1000000000ull / bps; }

void rcfw_hal_uart_send(struct rcfw_port *p, const uint8_t *buf, uint16_t len, uint32_t delay_us)
{
    rcfw_bus *bus = p->bus;
    if (!p->powered || p->tx_broken || p->uart_bps != bus->bps || len == 0) {
        return; /* a broken transmit line: the module sends, nobody hears it (neither the host nor the others) */
    }
    uint64_t bn = byte_ns(bus->bps);
    uint64_t start = p->rx_end_ns + (uint64_t)delay_us * 1000u;
    uint64_t now_ns = bus->now_us * 1000u;
    if (start < now_ns) {
        start = now_ns;
    }
    if (start < p->tx_end_ns) {
        start = p->tx_end_ns; /* a module never overlaps itself */
    }
    uint64_t end = start + (uint64_t)len * bn;
    bool overlap = start < bus->host_busy_until_ns;
    for (int32_t i = 0; i < bus->n; i++) {
        const struct rcfw_port *o = &bus->ports[i];
        if (o != p && start < o->tx_end_ns && end > o->tx_start_ns) {
            overlap = true;
        }
    }
    if (overlap) {
        bus->collisions++;
    }
    p->tx_start_ns = start;
    p->tx_end_ns = end;
    memcpy(p->echo, buf, len);
    p->echo_len = len;
    p->echo_start_ns = start;
    if (bus->q_len + len > bus->q_cap) {
        int32_t cap = bus->q_cap * 2 + len + 256;
        timed_byte *nq = realloc(bus->q, (size_t)cap * sizeof *nq);
        if (!nq) {
            return;
        }
        bus->q = nq;
        bus->q_cap = cap;
    }
    for (uint16_t i = 0; i < len; i++) {
        uint64_t t = start + (uint64_t)(i + 1u) * bn;
        int32_t j = bus->q_len++;
        while (j > 0 && bus->q[j - 1].t_ns > t) {
            bus->q[j] = bus->q[j - 1];
            j--;
        }
        bus->q[j].t_ns = t;
        bus->q[j].b = buf[i];
    }
}

void host_power_fail(struct rcfw_port *p)
{
    p->powered = 0;
    memset(p->pwm, 0, sizeof p->pwm);
    memset(p->bridge, 0, sizeof p->bridge);
}

bool rcfw_hal_fram_read(struct rcfw_port *p, uint16_t addr, uint8_t *buf, uint16_t len)
{
    if ((uint32_t)addr + len > RCFW_HOST_FRAM_SIZE) {
        return false;
    }
    memcpy(buf, p->fram + addr, len);
    return true;
}

bool rcfw_hal_fram_write(struct rcfw_port *p, uint16_t addr, const uint8_t *buf, uint16_t len)
{
    if ((uint32_t)addr + len > RCFW_HOST_FRAM_SIZE || !p->powered) {
        return false;
    }
    for (uint16_t i = 0; i < len; i++) {
        if (p->cut_remaining == 0) {
            host_power_fail(p);
            return false;
        }
        if (p->cut_remaining > 0) {
            p->cut_remaining--;
        }
        p->fram[addr + i] = buf[i];
    }
    return true;
}

/* ---- helpers ---- */
struct rcfw_port *host_port_of(const rcfw_bus *bus, int32_t module)
{
    if (!bus || module < 0 || module >= bus->n) {
        return NULL;
    }
    return &bus->ports[module];
}

void host_boot(struct rcfw_port *p, uint8_t cause)
{
    p->powered = 1;
    memset(p->pwm, 0, sizeof p->pwm);
    memset(p->bridge, 0, sizeof p->bridge);
    p->tx_end_ns = 0;
    p->next_tick_us = p->bus->now_us + TICK_US;
    rcfw_module_init(&p->mod, p, p->n_motors, cause);
}

/* ---- API ---- */
rcfw_bus *rcfw_bus_create(int32_t n_modules, const uint8_t *ids, const uint8_t *motors_per_module)
{
    if (n_modules < 1 || n_modules > 253 || !motors_per_module) {
        return NULL;
    }
    for (int32_t i = 0; i < n_modules; i++) {
        if ((ids && ids[i] > 252) || motors_per_module[i] < 1 || motors_per_module[i] > RCFW_HOST_MAX_MOTORS) {
            return NULL;
        }
        for (int32_t j = 0; ids && j < i; j++) {
            if (ids[j] == ids[i]) {
                return NULL;
            }
        }
    }
    rcfw_bus *bus = calloc(1, sizeof *bus);
    if (!bus) {
        return NULL;
    }
    bus->ports = calloc((size_t)n_modules, sizeof *bus->ports);
    if (!bus->ports) {
        free(bus);
        return NULL;
    }
    bus->n = n_modules;
    bus->bps = 1000000u;
    for (int32_t i = 0; i < n_modules; i++) {
        struct rcfw_port *p = &bus->ports[i];
        p->bus = bus;
        p->index = i;
        p->n_motors = motors_per_module[i];
        p->cut_remaining = -1;
        memset(p->hall, 1, sizeof p->hall);
        host_boot(p, RCFW_RESET_POWER_ON);
        if (!ids) {
            continue; /* fresh from the factory: the firmware's defaults, as blank FRAM gives them */
        }
        /* factory image: the module's ID, then a clean error state */
        uint8_t zero = 0;
        (void)rcfw_module_write(&p->mod, RCFW_CT_ID, &ids[i], 1);
        (void)rcfw_module_write(&p->mod, RCFW_CT_HARDWARE_ERROR_STATUS, &zero, 1);
    }
    return bus;
}

void rcfw_bus_destroy(rcfw_bus *bus)
{
    if (!bus) {
        return;
    }
    free(bus->q);
    free(bus->ports);
    free(bus);
}

int32_t rcfw_bus_set_baud(rcfw_bus *bus, uint32_t bps)
{
    if (!bus || bps < 1200u || bps > 10000000u) {
        return RCFW_HOST_EARG;
    }
    bus->bps = bps;
    return RCFW_HOST_OK;
}

int32_t host_check_motor(const rcfw_bus *bus, int32_t module, int32_t motor, struct rcfw_port **out)
{
    struct rcfw_port *p = host_port_of(bus, module);
    if (!p || motor < 0 || motor >= p->n_motors) {
        return RCFW_HOST_EARG;
    }
    *out = p;
    return RCFW_HOST_OK;
}

static void after_bus_activity(struct rcfw_port *p)
{
    if (p->powered && rcfw_module_take_reboot(&p->mod)) {
        uint64_t tx_end = p->tx_end_ns, tx_start = p->tx_start_ns;
        host_boot(p, RCFW_CAUSE_SOFTWARE);
        p->tx_end_ns = tx_end; /* the reply already on the line stays there */
        p->tx_start_ns = tx_start;
    }
}

int32_t rcfw_advance_us(rcfw_bus *bus, uint32_t us)
{
    if (!bus) {
        return RCFW_HOST_EARG;
    }
    uint64_t target = bus->now_us + us;
    for (int32_t i = 0; i < bus->n; i++) {
        struct rcfw_port *p = &bus->ports[i];
        while (p->next_tick_us <= target) {
            if (p->powered) {
                bus->now_us = p->next_tick_us;
                rcfw_module_tick(&p->mod);
                rcfw_module_poll(&p->mod);
                rcfw_module_publish(&p->mod); /* keeps rcfw_peek_table current */
            }
            p->next_tick_us += TICK_US;
        }
    }
    bus->now_us = target;
    return RCFW_HOST_OK;
}

uint64_t rcfw_now_us(const rcfw_bus *bus) { return bus ? bus->now_us : 0u; }

/* Every module hears what the others send (a chained SYNC/BULK READ reply waits for the previous one's
 * status). Transmissions are delivered oldest first until nobody has anything left to be heard. */
static void relay_transmissions(rcfw_bus *bus)
{
    uint64_t bn = byte_ns(bus->bps);
    for (;;) {
        struct rcfw_port *src = NULL;
        for (int32_t i = 0; i < bus->n; i++) {
            struct rcfw_port *p = &bus->ports[i];
            if (p->echo_len != 0u && (!src || p->echo_start_ns < src->echo_start_ns)) {
                src = p;
            }
        }
        if (!src) {
            return;
        }
        uint16_t len = src->echo_len;
        src->echo_len = 0;
        for (int32_t i = 0; i < bus->n; i++) {
            struct rcfw_port *p = &bus->ports[i];
            for (uint16_t k = 0; p != src && k < len && p->powered && p->uart_bps == bus->bps; k++) {
                p->rx_end_ns = src->echo_start_ns + (uint64_t)(k + 1u) * bn;
                rcfw_module_rx_byte(&p->mod, src->echo[k]);
                after_bus_activity(p);
            }
        }
    }
}

int32_t rcfw_bus_write(rcfw_bus *bus, const uint8_t *bytes, int32_t len)
{
    if (!bus || len < 0 || (len > 0 && !bytes)) {
        return RCFW_HOST_EARG;
    }
    uint64_t bn = byte_ns(bus->bps);
    uint64_t t0 = bus->now_us * 1000u;
    if (t0 < bus->host_busy_until_ns) {
        t0 = bus->host_busy_until_ns; /* the host UART queues: frames go out back to back */
    }
    uint64_t end = t0 + (uint64_t)len * bn;
    for (int32_t i = 0; i < bus->n; i++) {
        if (len > 0 && t0 < bus->ports[i].tx_end_ns && end > bus->ports[i].tx_start_ns) {
            bus->collisions++; /* host talks over a reply */
            break;
        }
    }
    for (int32_t i = 0; i < bus->n; i++) {
        struct rcfw_port *p = &bus->ports[i];
        for (int32_t k = 0; k < len && p->powered; k++) {
            if (p->uart_bps != bus->bps) {
                break;
            }
            p->rx_end_ns = t0 + (uint64_t)(k + 1) * bn;
            rcfw_module_rx_byte(&p->mod, bytes[k]);
            after_bus_activity(p);
        }
    }
    if (end > bus->host_busy_until_ns) {
        bus->host_busy_until_ns = end;
    }
    relay_transmissions(bus);
    return RCFW_HOST_OK;
}

int32_t rcfw_bus_read(rcfw_bus *bus, uint8_t *buf, int32_t cap)
{
    if (!bus || cap < 0 || (cap > 0 && !buf)) {
        return RCFW_HOST_EARG;
    }
    uint64_t now_ns = bus->now_us * 1000u;
    int32_t n = 0;
    while (n < cap && n < bus->q_len && bus->q[n].t_ns <= now_ns) {
        buf[n] = bus->q[n].b;
        n++;
    }
    if (n > 0) {
        memmove(bus->q, bus->q + n, (size_t)(bus->q_len - n) * sizeof *bus->q);
        bus->q_len -= n;
    }
    return n;
}

int32_t rcfw_bus_pending(const rcfw_bus *bus)
{
    if (!bus) {
        return RCFW_HOST_EARG;
    }
    uint64_t now_ns = bus->now_us * 1000u;
    int32_t n = 0;
    for (int32_t i = 0; i < bus->q_len; i++) {
        n += bus->q[i].t_ns > now_ns;
    }
    return n;
}

int32_t rcfw_bus_collisions(const rcfw_bus *bus) { return bus ? bus->collisions : RCFW_HOST_EARG; }
