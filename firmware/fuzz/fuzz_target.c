/* libFuzzer target: arbitrary bytes through the frame parser of a module on the host bus,
 * plus every decoded frame re-injected as a valid frame (fixed CRC) so control-table writes,
 * sync read/write and factory reset are exercised beyond the CRC check.
 * Layout of the input: byte 0 selects how much time passes between chunks; the rest is
 * split at 0xA5 0x5A markers into chunks written to the bus.
 * Invariants after every chunk, per module: PWM within -255..255; the bus watchdog's stages in order
 * (bus_watchdog_off 0 or later than bus_watchdog); stage 2 tripped (bit3) -> every motor off; while a hold lasts
 * (bit6), a motor driven since it began keeps the goal the hold froze (no write moves it). */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "rcfw/frame.h"
#include "rcfw/module.h"
#include "decoder_invariants.h"
#include "rcfw_host.h"

#define MODULES 2

/* What a hold froze, per module: valid while the module has been seen holding since. */
typedef struct {
    int holding;
    uint8_t driven[RCFW_CT_MAX_MOTORS];
    int32_t goal[RCFW_CT_MAX_MOTORS];
} hold_seen;

static uint32_t peek_le(const rcfw_bus *bus, int32_t m, uint16_t addr, int32_t n)
{
    uint8_t b[4] = {0};
    (void)rcfw_peek_table(bus, m, addr, b, n);
    return (uint32_t)b[0] | ((uint32_t)b[1] << 8) | ((uint32_t)b[2] << 16) | ((uint32_t)b[3] << 24);
}

static void check_watchdog(const rcfw_bus *bus, int32_t m, int32_t motors, hold_seen *h)
{
    uint32_t stage1 = peek_le(bus, m, RCFW_CT_BUS_WATCHDOG, 2), stage2 = peek_le(bus, m, RCFW_CT_BUS_WATCHDOG_OFF, 2);
    if (stage2 != 0u && stage2 <= stage1) {
        __builtin_trap();
    }
    uint32_t hw = peek_le(bus, m, RCFW_CT_HARDWARE_ERROR_STATUS, 1);
    for (int32_t k = 0; k < motors; k++) {
        uint16_t torque = (uint16_t)(RCFW_CT_TORQUE_ENABLE + k);
        if ((hw & RCFW_HWERR_BUS_WATCHDOG) && (peek_le(bus, m, torque, 1) != 0u || rcfw_get_pwm(bus, m, k) != 0 ||
                                               rcfw_get_driver_enable(bus, m, k) != 0)) {
            __builtin_trap();
        }
    }
    if (!(hw & RCFW_HWERR_BUS_HOLD)) {
        h->holding = 0;
        return;
    }
    for (int32_t k = 0; k < motors; k++) {
        uint8_t driven = peek_le(bus, m, (uint16_t)(RCFW_CT_TORQUE_ENABLE + k), 1) != 0u;
        int32_t goal = (int32_t)peek_le(bus, m, (uint16_t)(RCFW_CT_GOAL_POSITION + k * RCFW_CT_GOAL_POSITION_STRIDE), 4);
        if (h->holding && h->driven[k] && driven && goal != h->goal[k]) {
            __builtin_trap();
        }
        if (!h->holding || !driven) {
            h->driven[k] = driven;
            h->goal[k] = goal;
        }
    }
    h->holding = 1;
}

static void check_invariants(rcfw_bus *bus, hold_seen *holds)
{
    for (int32_t m = 0; m < MODULES; m++) {
        int32_t motors = m == 0 ? 4 : 2;
        for (int32_t k = 0; k < motors; k++) {
            int32_t pwm = rcfw_get_pwm(bus, m, k);
            if (pwm > 255 || pwm < -255) {
                __builtin_trap();
            }
        }
        check_watchdog(bus, m, motors, &holds[m]);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const uint8_t ids[MODULES] = {1, 2};
    static const uint8_t motors[MODULES] = {4, 2};
    hold_seen holds[MODULES];
    memset(holds, 0, sizeof holds);
    rcfw_bus *bus = rcfw_bus_create(MODULES, ids, motors);
    if (!bus || size == 0) {
        rcfw_bus_destroy(bus);
        return 0;
    }
    rcfw_check_decoder_invariants(data, size);
    uint32_t step_us = (uint32_t)(data[0] & 0x0F) * 20u;
    size_t start = 1;
    uint8_t frame[1100];
    uint8_t rx[4096];
    for (size_t i = 1; i <= size; i++) {
        int end = i == size || (i + 1 < size && data[i] == 0xA5 && data[i + 1] == 0x5A);
        if (!end) {
            continue;
        }
        size_t n = i - start;
        /* raw bytes */
        rcfw_bus_write(bus, data + start, (int32_t)n);
        /* the same bytes as the body of a valid frame: id = first byte */
        if (n >= 2 && n < 1000) {
            uint16_t fl = rcfw_frame_build(frame, sizeof frame, data[start], data + start + 1, (uint16_t)(n - 1));
            if (fl) {
                rcfw_bus_write(bus, frame, fl);
            }
        }
        rcfw_advance_us(bus, step_us);
        (void)rcfw_bus_read(bus, rx, sizeof rx);
        check_invariants(bus, holds);
        start = i + 2;
        i++;
    }
    rcfw_advance_us(bus, 300);
    (void)rcfw_bus_read(bus, rx, sizeof rx);
    check_invariants(bus, holds);
    rcfw_bus_destroy(bus);
    return 0;
}
