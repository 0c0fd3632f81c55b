/* Control-tick cost benchmark for qemu-system-arm -M microbit (ARMv6-M like the KV11Z's M0+).
 * The real core runs with a RAM HAL; one 4-motor tick runs between bench_mark_begin() and
 * bench_mark_end(). Executed instructions between the two are counted from qemu's exec trace
 * (firmware/ports/kv11z/bench/count-tick.sh). Exits through semihosting. */
#include <stdint.h>
#include <string.h>

#include "rcfw/hal.h"
#include "rcfw/module.h"

struct rcfw_port {
    uint8_t hall[4];
    uint16_t cur[4];
    int16_t pwm[4];
    uint8_t en[4];
    uint8_t fram[RCFW_FRAM_USED];
};

static struct rcfw_port port;
static rcfw_module module;

void rcfw_assert_failed(int line)
{
    (void)line;
    for (;;) {
    }
}
void rcfw_hal_pwm_set(struct rcfw_port *p, uint8_t m, int16_t v) { p->pwm[m] = v; }
void rcfw_hal_bridge_enable(struct rcfw_port *p, uint8_t m, bool on) { p->en[m] = on; }
uint16_t rcfw_hal_adc_current(struct rcfw_port *p, uint8_t m) { return p->cur[m]; }
uint16_t rcfw_hal_adc_pot(struct rcfw_port *p, uint8_t m) { (void)p; (void)m; return 0; }
uint8_t rcfw_hal_hall_read(struct rcfw_port *p, uint8_t m) { return p->hall[m]; }
void rcfw_hal_uart_set_baud(struct rcfw_port *p, uint32_t bps) { (void)p; (void)bps; }
void rcfw_hal_uart_send(struct rcfw_port *p, const uint8_t *b, uint16_t n, uint32_t d)
{
    (void)p; (void)b; (void)n; (void)d;
}
bool rcfw_hal_fram_read(struct rcfw_port *p, uint16_t a, uint8_t *b, uint16_t n)
{
    if ((uint32_t)a + n > sizeof p->fram) {
        return false;
    }
    memcpy(b, p->fram + a, n);
    return true;
}
bool rcfw_hal_fram_write(struct rcfw_port *p, uint16_t a, const uint8_t *b, uint16_t n)
{
    if ((uint32_t)a + n > sizeof p->fram) {
        return false;
    }
    memcpy(p->fram + a, b, n);
    return true;
}

__attribute__((noinline)) void bench_mark_begin(void) { __asm volatile("nop"); }
__attribute__((noinline)) void bench_mark_end(void) { __asm volatile("nop"); }

static void semihost_exit(void)
{
    register uint32_t r0 __asm("r0") = 0x18u;
    register uint32_t r1 __asm("r1") = 0x20026u;
    __asm volatile("bkpt 0xAB" : : "r"(r0), "r"(r1) : "memory");
}

int main(void)
{
    static const uint8_t seq[6] = {1, 3, 2, 6, 4, 5};
    for (int i = 0; i < 4; i++) {
        port.hall[i] = 1;
    }
    rcfw_module_init(&module, &port, 4, RCFW_CAUSE_POWER_ON);
    uint8_t on[4] = {1, 1, 1, 1};
    int32_t goals[4] = {100000, -100000, 5000, 7};
    uint16_t limit = 2000;
    for (uint8_t i = 0; i < 4; i++) {
        rcfw_module_write(&module, (uint16_t)(RCFW_CT_CURRENT_LIMIT + i * RCFW_CT_CURRENT_LIMIT_STRIDE),
                          (const uint8_t *)&limit, 2);
    }
    rcfw_module_write(&module, RCFW_CT_GOAL_POSITION, (const uint8_t *)goals, 16);
    rcfw_module_write(&module, RCFW_CT_TORQUE_ENABLE, on, 4);
    /* worst-ish case: every motor changes Hall state every tick, current limit active on two */
    for (int t = 0; t < 64; t++) {
        for (int i = 0; i < 4; i++) {
            port.hall[i] = seq[(t + i) % 6];
            port.cur[i] = (uint16_t)(i < 2 ? 3000 + (t & 7) : 500 + (t & 15));
        }
        bench_mark_begin();
        rcfw_module_tick(&module);
        bench_mark_end();
    }
    semihost_exit();
    return 0;
}

extern uint32_t _data_start, _data_end, _data_load, _bss_start, _bss_end, _stack_top;
void bench_reset(void);
void bench_reset(void)
{
    uint32_t *s = &_data_load, *d = &_data_start;
    while (d < &_data_end) {
        *d++ = *s++;
    }
    for (d = &_bss_start; d < &_bss_end;) {
        *d++ = 0;
    }
    (void)main();
    for (;;) {
    }
}
typedef void (*vec_t)(void);
__attribute__((section(".vectors"), used)) const vec_t bench_vectors[16] = {
    (vec_t)(uintptr_t)&_stack_top, bench_reset, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
