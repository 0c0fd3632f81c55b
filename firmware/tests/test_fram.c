/* FRAM: cut power at every byte of a parameter write; after restart the parameters are the
 * old or the new set, never a mix. Also the runtime (position) record and the store itself. */
#include "bus_helpers.h"
#include "rcfw/store.h"

static void write_set(rcfw_bus *bus, uint16_t base_value)
{
    /* one WRITE covering kp, speed_limit, current_limit, control_mode, pot_cal_count,
     * position_min/max of motor 0 (16..35) */
    uint8_t b[20];
    for (int i = 0; i < 20; i++) {
        b[i] = 0;
    }
    uint16_t kp = base_value, sl = (uint16_t)(base_value + 1), cl = (uint16_t)(base_value % 4000 + 2);
    int32_t gr = 100000 + base_value, pmin = -(int32_t)base_value, pmax = base_value * 3;
    memcpy(b + 0, &gr, 4);
    memcpy(b + 4, &kp, 2);
    memcpy(b + 6, &sl, 2);
    memcpy(b + 8, &cl, 2);
    b[10] = 0;
    b[11] = 0;
    memcpy(b + 12, &pmin, 4);
    memcpy(b + 16, &pmax, 4);
    wr(bus, 1, RCFW_CT_GEAR_RATIO, b, 20);
}

static void cut_at_every_byte(void)
{
    const uint8_t ids[1] = {1}, motors[1] = {4};
    uint8_t old_img[RCFW_CT_PERSISTENT_END], new_img[RCFW_CT_PERSISTENT_END], got[RCFW_CT_PERSISTENT_END];
    int saw_old = 0, saw_new = 0;
    const int total = (int)(RCFW_CT_PERSISTENT_END + RCFW_STORE_WRITE_OVERHEAD);
    for (int cut = 0; cut <= total + 2; cut++) {
        rcfw_bus *bus = rcfw_bus_create(1, ids, motors);
        status_t st[2];
        write_set(bus, 1111);
        CHECK_EQ(collect(bus, 2000, st, 2), 1);
        /* a second complete generation so both slots hold valid older data */
        write_set(bus, 2222);
        CHECK_EQ(collect(bus, 2000, st, 2), 1);
        rcfw_peek_table(bus, 0, 0, old_img, sizeof old_img);
        rcfw_fram_cut_after(bus, 0, cut);
        write_set(bus, 3333);
        int replies = collect(bus, 2000, st, 2);
        if (cut < total) {
            CHECK_EQ(rcfw_is_powered(bus, 0), 0);
            CHECK_EQ(replies, 0); /* never acknowledged before it is durable */
        } else {
            CHECK_EQ(replies, 1);
        }
        if (cut == total + 2) {
            rcfw_peek_table(bus, 0, 0, new_img, sizeof new_img);
        }
        rcfw_power_cycle(bus, 0);
        rcfw_peek_table(bus, 0, 0, got, sizeof got);
        CHECK_EQ(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS) & RCFW_HWERR_PARAMS_LOST, 0);
        if (memcmp(got, old_img, sizeof got) == 0) {
            saw_old++;
            CHECK(cut < total);
        } else {
            /* must be exactly the new set */
            CHECK_EQ(peek16(bus, 0, RCFW_CT_KP), 3333);
            CHECK_EQ(peek16(bus, 0, RCFW_CT_SPEED_LIMIT), 3334);
            CHECK_EQ(peek32(bus, 0, RCFW_CT_POSITION_MAX), 9999);
            CHECK_EQ(peek32(bus, 0, RCFW_CT_GEAR_RATIO), 103333);
            saw_new++;
        }
        rcfw_bus_destroy(bus);
    }
    /* the record becomes valid only with its last byte */
    CHECK_EQ(saw_old, total);
    CHECK_EQ(saw_new, 3);
    (void)new_img;
}

static void cut_during_runtime_record(void)
{
    const uint8_t ids[1] = {1}, motors[1] = {2};
    const int total = (int)(RCFW_RUNTIME_LEN + RCFW_STORE_WRITE_OVERHEAD);
    for (int cut = 0; cut < total; cut++) {
        rcfw_bus *bus = rcfw_bus_create(1, ids, motors);
        rcfw_set_hall(bus, 0, 0, 3); /* +1 */
        rcfw_advance_us(bus, 2000);  /* saved */
        CHECK_EQ(rcfw_get_position(bus, 0, 0), 1);
        rcfw_fram_cut_after(bus, 0, cut);
        rcfw_set_hall(bus, 0, 0, 2); /* +1 -> 2, the next save is cut */
        rcfw_advance_us(bus, 2000);
        CHECK_EQ(rcfw_is_powered(bus, 0), 0);
        rcfw_power_cycle(bus, 0);
        int32_t p = rcfw_get_position(bus, 0, 0);
        CHECK(p == 1); /* the torn record never wins */
        CHECK_EQ(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS) & RCFW_HWERR_POSITION_LOST, 0);
        rcfw_bus_destroy(bus);
    }
}

static void blank_and_corrupt_fram(void)
{
    const uint8_t ids[1] = {9}, motors[1] = {1};
    rcfw_bus *bus = rcfw_bus_create(1, ids, motors);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_ID), 9);
    /* flip a byte in both parameter slots: defaults are loaded and flagged */
    uint8_t b;
    rcfw_fram_peek(bus, 0, RCFW_FRAM_PARAMS_A + 20, &b, 1);
    b ^= 0xFF;
    rcfw_fram_poke(bus, 0, RCFW_FRAM_PARAMS_A + 20, &b, 1);
    rcfw_fram_peek(bus, 0, RCFW_FRAM_PARAMS_B + 20, &b, 1);
    b ^= 0xFF;
    rcfw_fram_poke(bus, 0, RCFW_FRAM_PARAMS_B + 20, &b, 1);
    rcfw_power_cycle(bus, 0);
    CHECK(peek8(bus, 0, RCFW_CT_HARDWARE_ERROR_STATUS) & RCFW_HWERR_PARAMS_LOST);
    CHECK_EQ(peek8(bus, 0, RCFW_CT_ID), 1);
    /* corrupting only the newest slot falls back to the older one */
    uint16_t newest = write_kp_twice_newest_slot(bus); /* kp 500, then 600 */
    rcfw_fram_peek(bus, 0, (uint16_t)(newest + 30), &b, 1);
    b ^= 1;
    rcfw_fram_poke(bus, 0, (uint16_t)(newest + 30), &b, 1);
    rcfw_power_cycle(bus, 0);
    CHECK_EQ(peek16(bus, 0, RCFW_CT_KP), 500);
    rcfw_bus_destroy(bus);
}

int main(void)
{
    TF_RUN(cut_at_every_byte);
    TF_RUN(cut_during_runtime_record);
    TF_RUN(blank_and_corrupt_fram);
    TF_END();
}
