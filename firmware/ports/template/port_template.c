/* Port template: every function a port must provide, with what it has to do.
 * Compiled (not linked) by firmware/CMakeLists.txt so it stays in step with hal.h. */
#include "rcfw/hal.h"
#include "rcfw/module.h"

struct rcfw_port {
    uint8_t unused; /* per-module port state: pin maps, rx ring buffer, tx request, ... */
};

/* Firmware bug: make the outputs safe, then reset (reported as a software reset). */
void rcfw_assert_failed(int line)
{
    (void)line;
    for (;;) {
    }
}

/* Set duty |pwm| / 255 and the direction output of the motor's bridge driver. */
void rcfw_hal_pwm_set(struct rcfw_port *p, uint8_t motor, int16_t pwm) { (void)p; (void)motor; (void)pwm; }
/* Drive the bridge driver's enable pin. */
void rcfw_hal_bridge_enable(struct rcfw_port *p, uint8_t motor, bool on) { (void)p; (void)motor; (void)on; }
/* Latest 12-bit motor-current sample (called every tick: keep it non-blocking if possible). */
uint16_t rcfw_hal_adc_current(struct rcfw_port *p, uint8_t motor) { (void)p; (void)motor; return 0; }
/* Joint potentiometer, 12-bit (read at start-up for homing). */
uint16_t rcfw_hal_adc_pot(struct rcfw_port *p, uint8_t motor) { (void)p; (void)motor; return 0; }
/* Hall inputs of the motor: bit0 H1, bit1 H2, bit2 H3. */
uint8_t rcfw_hal_hall_read(struct rcfw_port *p, uint8_t motor) { (void)p; (void)motor; return 1; }
/* Reprogram the UART after any transmission in progress has finished. */
void rcfw_hal_uart_set_baud(struct rcfw_port *p, uint32_t bps) { (void)p; (void)bps; }
/* Queue a reply: start delay_us after the last received byte, RS-485 DE high while sending. */
void rcfw_hal_uart_send(struct rcfw_port *p, const uint8_t *buf, uint16_t len, uint32_t delay_us)
{
    (void)p; (void)buf; (void)len; (void)delay_us;
}
/* FRAM transfers; return false on a bus error. */
bool rcfw_hal_fram_read(struct rcfw_port *p, uint16_t addr, uint8_t *buf, uint16_t len)
{
    (void)p; (void)addr; (void)buf; (void)len;
    return false;
}
bool rcfw_hal_fram_write(struct rcfw_port *p, uint16_t addr, const uint8_t *buf, uint16_t len)
{
    (void)p; (void)addr; (void)buf; (void)len;
    return false;
}
