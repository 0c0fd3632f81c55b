/* Per-motor control: Hall decoder, current EMA, current limit, speed-limited P loop.
 * Integer arithmetic only. */
#ifndef RCFW_MOTOR_H
#define RCFW_MOTOR_H
#include <stdbool.h>
#include <stdint.h>

#define RCFW_PWM_MAX 255
#define RCFW_MERR_OVERCURRENT 0x01u
#define RCFW_MERR_HALL 0x02u
#define RCFW_MERR_POT 0x04u
/* position not restored after a reset (taken from the pot, or 0 uncalibrated) and not homed since;
 * same bit as the module's RCFW_HWERR_POSITION_LOST so the tick can OR motor errors in */
#define RCFW_MERR_POSITION_LOST 0x20u

#define RCFW_MODE_POSITION 0u
#define RCFW_MODE_PWM 1u

typedef struct {
    /* state */
    int32_t position;   /* Hall counts, 6 per motor revolution */
    uint8_t hall_idx;   /* 0..5 position in the sequence, 0xFF = unknown */
    uint16_t hall_errors;
    uint32_t cur_sum;   /* EMA accumulator S */
    uint16_t cur_ma;    /* S >> k */
    int32_t setpoint;   /* speed-limited */
    uint32_t slew_acc;  /* Q16 fractional counts of slew */
    int16_t pwm;        /* applied */
    uint8_t cap;        /* PWM magnitude cap from the current limit (255 = none) */
    uint8_t errors;     /* RCFW_MERR_* latched */
    /* parameters cached from the control table */
    uint8_t enabled;
    uint8_t mode;
    uint16_t kp;         /* Q8.8 */
    uint32_t step_q16;   /* setpoint slew per tick, Q16 counts; 0 = unlimited */
    uint16_t current_limit;
    int32_t goal;        /* clamped to the position limits */
    int16_t goal_pwm;
} rcfw_motor;

/* Sequence index of a Hall state (forward 1,3,2,6,4,5), -1 for 000/111. */
int8_t rcfw_hall_index(uint8_t state);
/* Decode a new Hall state. Returns true if it was an error (invalid or skipped state). */
bool rcfw_hall_update(rcfw_motor *m, uint8_t state);
/* Set the position (homing/resume); the next Hall state re-synchronises the index. */
void rcfw_motor_set_position(rcfw_motor *m, int32_t pos, uint8_t hall_state);
/* One control period. current_raw: ADC sample; k: EMA shift; step: current-limit PWM step.
 * Returns the PWM to apply (0 when disabled). */
int16_t rcfw_motor_tick(rcfw_motor *m, uint16_t current_raw, uint8_t k, uint8_t step);
/* P law: clamp((kp * clamp(err, +-32767)) >> 8, -255, 255), rounding toward zero. */
int16_t rcfw_p_law(uint16_t kp, int32_t err);
/* Speed-limit slew step in Q16 counts per tick for speed counts/s at rate_hz ticks/s. */
uint32_t rcfw_slew_step_q16(uint16_t speed, uint32_t rate_hz);
#endif
