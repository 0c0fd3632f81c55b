/* Hardware abstraction: functions every port implements (link-time binding, tinyusb style).
 * The core never touches hardware or globals; each call passes the port context that the
 * port handed to rcfw_module_init, so the host can run many modules in one process.
 * Calls are made from the contexts noted; ports must make them short and non-blocking
 * except where noted. */
#ifndef RCFW_HAL_H
#define RCFW_HAL_H

#include <stdbool.h>
#include <stdint.h>

struct rcfw_port; /* defined by the port */

/* PWM: signed duty -255..255 (8-bit magnitude + direction). Tick context. */
void rcfw_hal_pwm_set(struct rcfw_port *p, uint8_t motor, int16_t pwm);
/* Motor bridge driver enable. Tick and main context. */
void rcfw_hal_bridge_enable(struct rcfw_port *p, uint8_t motor, bool on);
/* ADC: latest 12-bit motor-current sample (tick context) and pot sample. */
uint16_t rcfw_hal_adc_current(struct rcfw_port *p, uint8_t motor);
uint16_t rcfw_hal_adc_pot(struct rcfw_port *p, uint8_t motor);
/* Hall inputs: bit0 = H1, bit1 = H2, bit2 = H3. */
uint8_t rcfw_hal_hall_read(struct rcfw_port *p, uint8_t motor);
/* UART. set_baud: bit/s. send: transmit len bytes starting delay_us after the end of the
 * last received byte; the port drives RS-485 driver-enable high for the transmission
 * and low after the last stop bit. The buffer stays valid until the next send. */
void rcfw_hal_uart_set_baud(struct rcfw_port *p, uint32_t bps);
void rcfw_hal_uart_send(struct rcfw_port *p, const uint8_t *buf, uint16_t len, uint32_t delay_us);
/* FRAM (byte addressed, no erase). Main context; may block for the transfer.
 * Return false on a transfer failure. */
bool rcfw_hal_fram_read(struct rcfw_port *p, uint16_t addr, uint8_t *buf, uint16_t len);
bool rcfw_hal_fram_write(struct rcfw_port *p, uint16_t addr, const uint8_t *buf, uint16_t len);
/* Timer: the port calls rcfw_module_tick every 1e6/RCFW_CONTROL_RATE_HZ us (periodic
 * timer interrupt) and rcfw_module_hall_edge on Hall pin changes. No HAL call needed. */

#endif
