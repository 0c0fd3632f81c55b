/* Boards fresh from the factory (rcfw_bus_create with no IDs) and unplugged modules (rcfw_power_off): what the
 * virtual robot's factory mode (bus-sim --factory) rests on. */
#include "bus_helpers.h"

static int32_t field_default(uint16_t address)
{
    for (int i = 0; i < RCFW_CT_FIELD_COUNT; i++) {
        if (rcfw_ct_fields[i].address == address) {
            return rcfw_ct_fields[i].def;
        }
    }
    return -1;
}

static int ping(rcfw_bus *bus, uint8_t id, status_t *st, int max)
{
    send_frame(bus, id, RCFW_INST_PING, NULL, 0);
    return collect(bus, 2000, st, max);
}

static void blank_boards_answer_at_the_default_id_with_defaults(void)
{
    const uint8_t motors[2] = {3, 1};
    rcfw_bus *bus = rcfw_bus_create(2, NULL, motors);
    CHECK(bus != NULL);
    const int32_t def_id = field_default(RCFW_CT_ID);
    for (int m = 0; m < 2; m++) {
        CHECK_EQ(peek8(bus, m, RCFW_CT_ID), def_id);
        CHECK_EQ(peek16(bus, m, RCFW_CT_KP), field_default(RCFW_CT_KP));
        CHECK_EQ(peek8(bus, m, RCFW_CT_BAUD_RATE), field_default(RCFW_CT_BAUD_RATE));
        CHECK(peek8(bus, m, RCFW_CT_HARDWARE_ERROR_STATUS) & RCFW_HWERR_PARAMS_LOST);
    }
    /* both answer a ping at the default ID: two replies on the line at once */
    status_t st[4];
    int before = rcfw_bus_collisions(bus);
    (void)ping(bus, (uint8_t)def_id, st, 4);
    CHECK(rcfw_bus_collisions(bus) > before);
    rcfw_bus_destroy(bus);
}

static void an_unplugged_module_is_silent_and_keeps_its_new_id(void)
{
    const uint8_t motors[2] = {1, 1};
    rcfw_bus *bus = rcfw_bus_create(2, NULL, motors);
    const uint8_t def_id = (uint8_t)field_default(RCFW_CT_ID);
    CHECK_EQ(rcfw_power_off(bus, 1), RCFW_HOST_OK);
    CHECK_EQ(rcfw_is_powered(bus, 1), 0);
    CHECK_EQ(rcfw_power_off(bus, 2), RCFW_HOST_EARG);
    status_t st[4];
    CHECK_EQ(ping(bus, def_id, st, 4), 1); /* only the plugged-in one */
    const uint8_t new_id = 21;
    CHECK_EQ(write_ack(bus, def_id, RCFW_CT_ID, &new_id, 1) & 0x7F, 0); /* applied (bit 7: the alert of "parameters lost") */
    CHECK_EQ(rcfw_power_cycle(bus, 0), RCFW_HOST_OK); /* power cut: the ID is in FRAM */
    CHECK_EQ(ping(bus, new_id, st, 4), 1);
    CHECK_EQ(ping(bus, def_id, st, 4), 0);
    CHECK_EQ(rcfw_power_cycle(bus, 1), RCFW_HOST_OK); /* plug the second one in */
    CHECK_EQ(ping(bus, def_id, st, 4), 1);
    CHECK_EQ(ping(bus, new_id, st, 4), 1);
    rcfw_bus_destroy(bus);
}

int main(void)
{
    TF_RUN(blank_boards_answer_at_the_default_id_with_defaults);
    TF_RUN(an_unplugged_module_is_silent_and_keeps_its_new_id);
    TF_END();
}
