/* A motor module: control table, protocol handling, control loop, persistence.
 * Everything lives in rcfw_module; the core has no global state. */
#ifndef RCFW_MODULE_H
#define RCFW_MODULE_H
#include <stdbool.h>
#include <stdint.h>

#include "rcfw/frame.h"
#include "rcfw/motor.h"
#include "rcfw/store.h"
#include "rcfw_ct_gen.h"

#define RCFW_CONTROL_RATE_HZ 10000u
#define RCFW_RX_TIMEOUT_TICKS 20u   /* 2 ms of silence inside a frame drops it */
#define RCFW_RUNTIME_SAVE_TICKS 10u /* position/goal record at most every 1 ms */

/* hardware_error_status bits (their positions are the field's "bits" in control-table.json) */
#define RCFW_HWERR_OVERCURRENT RCFW_CT_HARDWARE_ERROR_STATUS_BIT_OVER_CURRENT
#define RCFW_HWERR_HALL RCFW_CT_HARDWARE_ERROR_STATUS_BIT_HALL
#define RCFW_HWERR_POT_MISMATCH RCFW_CT_HARDWARE_ERROR_STATUS_BIT_POT_MISMATCH
#define RCFW_HWERR_BUS_WATCHDOG RCFW_CT_HARDWARE_ERROR_STATUS_BIT_BUS_WATCHDOG   /* stage 2: torque off */
#define RCFW_HWERR_PARAMS_LOST RCFW_CT_HARDWARE_ERROR_STATUS_BIT_PARAMETERS_LOST
#define RCFW_HWERR_POSITION_LOST RCFW_CT_HARDWARE_ERROR_STATUS_BIT_POSITION_LOST
#define RCFW_HWERR_BUS_HOLD RCFW_CT_HARDWARE_ERROR_STATUS_BIT_BUS_HOLD           /* stage 1: holding */

/* reset_cause values */
#define RCFW_CAUSE_POWER_ON 1u
#define RCFW_CAUSE_BROWN_OUT 2u
#define RCFW_CAUSE_WATCHDOG 3u
#define RCFW_CAUSE_SOFTWARE 4u
#define RCFW_CAUSE_PIN 5u
#define RCFW_CAUSE_LOCKUP 6u

/* FRAM map */
#define RCFW_FRAM_PARAMS_A 0x000u
#define RCFW_FRAM_PARAMS_B 0x100u
#define RCFW_FRAM_RUNTIME_A 0x200u
#define RCFW_FRAM_RUNTIME_B 0x240u
#define RCFW_FRAM_USED 0x280u
#define RCFW_PARAMS_MAGIC 0x5052u  /* "RP" */
#define RCFW_RUNTIME_MAGIC 0x5352u /* "RS" */
#define RCFW_RUNTIME_LEN (RCFW_CT_MAX_MOTORS * 8u)

#define RCFW_TX_MAX 512u

typedef struct {
    uint32_t rx_frames;    /* valid frames (any ID) */
    uint32_t rx_bad_crc;
    uint32_t rx_bad_len;   /* too short, too long, truncated (resync or timeout) */
    uint32_t rx_bad_stuff;
    uint32_t bad_requests; /* valid frames refused (range, access, limit, length) */
    uint32_t fram_errors;
} rcfw_stats;

typedef struct rcfw_module {
    struct rcfw_port *port;
    _Alignas(4) uint8_t ct[RCFW_CT_SIZE];
    rcfw_motor motor[RCFW_CT_MAX_MOTORS];
    uint8_t hall_last[RCFW_CT_MAX_MOTORS];
    uint8_t n_motors;
    uint8_t ema_k;
    uint8_t limit_step;
    uint8_t reboot_pending;
    uint8_t baud_pending;
    uint8_t runtime_due;
    uint16_t runtime_div;
    uint16_t rx_idle_ticks;
    /* bus watchdog: ticks since the last valid frame addressed to the module; stage 1 (hold) at wd_limit_ticks,
     * stage 2 (torque off) at wd_off_ticks (= wd_limit_ticks when bus_watchdog_off is 0: no hold stage) */
    uint32_t wd_ticks;
    uint32_t wd_limit_ticks;
    uint32_t wd_off_ticks;
    rcfw_store params;
    rcfw_store runtime;
    uint8_t runtime_saved[RCFW_RUNTIME_LEN];
    rcfw_parser rx;
    /* REG WRITE waiting for ACTION (reg_len 0: none) */
    uint16_t reg_addr;
    uint16_t reg_len;
    uint8_t reg_data[RCFW_CT_SIZE];
    /* SYNC/BULK READ reply built in tx, sent once chain_prev's status has been heard (chain_len 0: none) */
    uint8_t chain_prev;
    uint16_t chain_len;
    /* FAST SYNC/BULK READ part in tx, sent when the packet reaches fast_at bytes (fast_len 0: none) */
    uint16_t fast_len;
    uint16_t fast_at;
    uint16_t fast_pos;
    uint16_t fast_crc;
    uint16_t fast_total; /* LEN of the combined packet */
    /* the part just before this module's: where it starts in the packet, its ID, and the CRC its last two
     * bytes must carry; heard otherwise, the bytes are not that packet and the module gives up */
    uint16_t fast_prev_at;
    uint8_t fast_prev_id;
    uint16_t fast_expect;
    uint8_t body[RCFW_CT_SIZE + 8u];
    uint8_t tx[RCFW_TX_MAX];
    rcfw_stats stats;
} rcfw_module;

/* Start (or restart after any reset) a module: load parameters and position from FRAM,
 * home/check against the pots, record the reset cause. n_motors 1..4. */
void rcfw_module_init(rcfw_module *m, struct rcfw_port *port, uint8_t n_motors, uint8_t reset_cause);
/* Copy the motors' state (present_*, hall_error_count, motor_error, present_setpoint) into
 * the control table. Done before every READ / SYNC READ; the tick does not pay for it. */
void rcfw_module_publish(rcfw_module *m);
/* Control period (RCFW_CONTROL_RATE_HZ), timer interrupt context. */
void rcfw_module_tick(rcfw_module *m);
/* Hall pin change of one motor (pin interrupt context, same priority as the tick). */
void rcfw_module_hall_edge(rcfw_module *m, uint8_t motor);
/* One received UART byte (main context, with the tick masked while a frame is handled). */
void rcfw_module_rx_byte(rcfw_module *m, uint8_t byte);
/* Main-loop housekeeping: runtime record to FRAM, pending baud change. */
void rcfw_module_poll(rcfw_module *m);
/* True once after a reboot / factory reset instruction has been answered: the port resets. */
bool rcfw_module_take_reboot(rcfw_module *m);
/* Local table access (same checks as a bus WRITE; persistent changes are saved).
 * Returns 0 or an RCFW_ERR_* code. */
uint8_t rcfw_module_write(rcfw_module *m, uint16_t addr, const uint8_t *data, uint16_t len);
uint32_t rcfw_module_baud_bps(const rcfw_module *m);
uint32_t rcfw_baud_code_bps(uint8_t code);
/* Potentiometer reading -> Hall position by the calibration table; false if uncalibrated. */
bool rcfw_pot_to_position(const rcfw_module *m, uint8_t motor, uint16_t raw, int32_t *pos);
#endif
