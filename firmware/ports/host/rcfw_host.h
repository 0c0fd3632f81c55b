/*
 * rcfw_host.h - host port of the motor-module firmware as a shared library
 * (librcfw_host.so). Runs N real firmware module contexts on one simulated
 * RS-485 bus in simulated time. Designed for P/Invoke from .NET:
 *   - only plain C types (int32_t, uint8_t, uint16_t, uint32_t, uint64_t, pointers to them);
 *   - one opaque handle (rcfw_bus *, an IntPtr in C#);
 *   - no callbacks, no global state (several buses may live in one process);
 *   - not thread-safe per handle: call one bus from one thread at a time.
 *
 * Conventions
 *   module  : index 0..n_modules-1 in the order given to rcfw_bus_create (NOT the bus ID).
 *   motor   : 0..motors_of_module-1 (at most RCFW_HOST_MAX_MOTORS).
 *   Status-returning functions return RCFW_HOST_OK (0) or a negative RCFW_HOST_E* code.
 *   Getters return the value; on bad arguments they return RCFW_HOST_EARG.
 *
 * Time
 *   Simulated time starts at 0 and only moves in rcfw_advance_us. Each module runs
 *   its control tick every 1e6/RCFW_HOST_CONTROL_RATE_HZ us of simulated time.
 *   rcfw_bus_write puts a frame on the line at now (or right after the host's previous frame,
 *   like a UART transmit queue) and delivers the bytes to every powered module whose baud matches the
 *   bus baud (frames are decoded at the write call; the effect is immediate). A reply
 *   is scheduled on the bus at
 *       t_write + frame_bytes * byte_time + return_delay (+ stagger slot for
 *       broadcast ping / sync read)      and then one byte every byte_time,
 *   byte_time = 10 bits / bus baud. rcfw_bus_read returns only the bytes whose
 *   arrival time is <= now, so a caller must advance time before reading a reply.
 *
 * Typical use (C#):
 *   var bus = rcfw_bus_create(2, new byte[]{1,2}, new byte[]{4,2});
 *   rcfw_bus_write(bus, pingFrame, pingFrame.Length);
 *   rcfw_advance_us(bus, 1000);
 *   int n = rcfw_bus_read(bus, buf, buf.Length);
 *   ...
 *   rcfw_bus_destroy(bus);
 */
#ifndef RCFW_HOST_H
#define RCFW_HOST_H

#include <stdint.h>

#if defined(_WIN32)
#define RCFW_HOST_API __declspec(dllexport)
#else
#define RCFW_HOST_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

#define RCFW_HOST_OK 0
#define RCFW_HOST_EARG (-1000000)   /* bad handle, index or argument */
#define RCFW_HOST_EPOWER (-1000001) /* module is powered off (FRAM cut tripped) */

#define RCFW_HOST_MAX_MOTORS 4
#define RCFW_HOST_CONTROL_RATE_HZ 10000
#define RCFW_HOST_FRAM_SIZE 2048

/* Reset causes (same values as the control-table register reset_cause). */
#define RCFW_RESET_POWER_ON 1
#define RCFW_RESET_BROWN_OUT 2
#define RCFW_RESET_WATCHDOG 3
#define RCFW_RESET_SOFTWARE 4
#define RCFW_RESET_PIN 5
#define RCFW_RESET_LOCKUP 6

typedef struct rcfw_bus rcfw_bus;

/* Create a bus with n_modules (1..253) modules. ids[i] is the initial bus ID
 * (0..252, distinct) written into module i's FRAM as a factory image;
 * motors_per_module[i] is 1..4. Each module starts with blank FRAM, factory
 * defaults (baud 1 Mbaud, return delay 0), reset cause power-on, all Hall inputs
 * at state 1, current 0, pot 0. ids NULL: boards fresh from the factory, nothing
 * written, so every module answers at the control table's default ID and reports
 * what blank FRAM gives (parameters lost). Returns NULL on bad arguments. */
RCFW_HOST_API rcfw_bus *rcfw_bus_create(int32_t n_modules, const uint8_t *ids,
                                        const uint8_t *motors_per_module);
RCFW_HOST_API void rcfw_bus_destroy(rcfw_bus *bus);

/* Host-side baud rate in bit/s (default 1000000). Only modules whose configured
 * baud equals it hear the host and are heard. */
RCFW_HOST_API int32_t rcfw_bus_set_baud(rcfw_bus *bus, uint32_t bps);

/* ---- simulated inputs ---- */
/* Hall state 0..7 (bit0 = H1, bit1 = H2, bit2 = H3). Decoded at once, like a pin
 * interrupt; forward sequence is 1,3,2,6,4,5. */
RCFW_HOST_API int32_t rcfw_set_hall(rcfw_bus *bus, int32_t module, int32_t motor, uint8_t state);
/* Motor-current ADC reading, 12-bit raw (0..4095), sampled every control tick. */
RCFW_HOST_API int32_t rcfw_set_current_raw(rcfw_bus *bus, int32_t module, int32_t motor, uint16_t raw);
/* Joint potentiometer ADC reading, 12-bit raw (0..4095); used for homing at start-up. */
RCFW_HOST_API int32_t rcfw_set_pot_raw(rcfw_bus *bus, int32_t module, int32_t motor, uint16_t raw);

/* ---- time ---- */
/* Advance simulated time by us microseconds, running control ticks (10 kHz). */
RCFW_HOST_API int32_t rcfw_advance_us(rcfw_bus *bus, uint32_t us);
RCFW_HOST_API uint64_t rcfw_now_us(const rcfw_bus *bus);

/* ---- bus bytes ---- */
/* Host -> modules. Returns RCFW_HOST_OK. */
RCFW_HOST_API int32_t rcfw_bus_write(rcfw_bus *bus, const uint8_t *bytes, int32_t len);
/* Modules -> host: copies up to cap bytes that have arrived by now; returns count. */
RCFW_HOST_API int32_t rcfw_bus_read(rcfw_bus *bus, uint8_t *buf, int32_t cap);
/* Bytes queued on the bus that have not arrived yet (0 = line idle). */
RCFW_HOST_API int32_t rcfw_bus_pending(const rcfw_bus *bus);
/* Number of reply overlaps seen (two modules driving the line at once). */
RCFW_HOST_API int32_t rcfw_bus_collisions(const rcfw_bus *bus);

/* ---- simulated outputs and introspection ---- */
/* Signed PWM command -255..255 actually applied to the bridge (0 when disabled). */
RCFW_HOST_API int32_t rcfw_get_pwm(const rcfw_bus *bus, int32_t module, int32_t motor);
/* Motor bridge driver enable (1 = driving, 0 = off). */
RCFW_HOST_API int32_t rcfw_get_driver_enable(const rcfw_bus *bus, int32_t module, int32_t motor);
/* RS-485 driver-enable pin of the module (1 while it transmits). */
RCFW_HOST_API int32_t rcfw_get_tx_enable(const rcfw_bus *bus, int32_t module);
/* Present position in Hall counts (same value as control-table present_position). */
RCFW_HOST_API int32_t rcfw_get_position(const rcfw_bus *bus, int32_t module, int32_t motor);
/* Copy len bytes of the module's control table from addr (debug/inspection,
 * bypasses the bus). Returns len or RCFW_HOST_EARG. */
RCFW_HOST_API int32_t rcfw_peek_table(const rcfw_bus *bus, int32_t module, uint16_t addr,
                                      uint8_t *buf, int32_t len);
/* Breaks (1) or mends (0) the module's transmit line: from now on nothing it sends reaches the bus (the host
 * hears no reply, the modules after it in a chained SYNC/BULK READ wait for it in vain); it still hears
 * everything. Returns RCFW_HOST_OK or RCFW_HOST_EARG. */
RCFW_HOST_API int32_t rcfw_set_tx_broken(rcfw_bus *bus, int32_t module, int32_t broken);
/* Writes len bytes into the module's control table at addr through the module's own write path (checked and
 * applied as a WRITE frame's data would be, without a frame on the bus: a write that did not come from the
 * host under test). Returns the protocol error code (0 = applied) or RCFW_HOST_EARG. */
RCFW_HOST_API int32_t rcfw_table_write(rcfw_bus *bus, int32_t module, uint16_t addr, const uint8_t *buf,
                                       int32_t len);
/* 1 if the module is powered, 0 if it is off (after a FRAM cut). */
RCFW_HOST_API int32_t rcfw_is_powered(const rcfw_bus *bus, int32_t module);

/* ---- power, reset, FRAM ---- */
/* Power off and on: RAM state is lost, FRAM kept; reset cause = power-on. */
RCFW_HOST_API int32_t rcfw_power_cycle(rcfw_bus *bus, int32_t module);
/* Power off (the module is unplugged): RAM state lost, FRAM kept, no ticks, no bus,
 * outputs off, until rcfw_power_cycle powers it on again. */
RCFW_HOST_API int32_t rcfw_power_off(rcfw_bus *bus, int32_t module);
/* Reset with a given cause (RCFW_RESET_*), e.g. EMI brown-out. FRAM kept. */
RCFW_HOST_API int32_t rcfw_reset(rcfw_bus *bus, int32_t module, uint8_t cause);
/* After n_bytes more FRAM bytes are written the module loses power: the write in
 * progress is torn, the module stops (no ticks, no bus, outputs off) until
 * rcfw_power_cycle. n_bytes < 0 disarms. */
RCFW_HOST_API int32_t rcfw_fram_cut_after(rcfw_bus *bus, int32_t module, int32_t n_bytes);
/* Raw FRAM access for tests (RCFW_HOST_FRAM_SIZE bytes). Return len or error. */
RCFW_HOST_API int32_t rcfw_fram_peek(const rcfw_bus *bus, int32_t module, uint16_t addr,
                                     uint8_t *buf, int32_t len);
RCFW_HOST_API int32_t rcfw_fram_poke(rcfw_bus *bus, int32_t module, uint16_t addr,
                                     const uint8_t *buf, int32_t len);

#ifdef __cplusplus
}
#endif
#endif
