/* Links against librcfw_host.so exactly as P/Invoke sees it: only the exported API. */
#include <stdio.h>
#include <string.h>

#include "rcfw_host.h"

int main(void)
{
    int fails = 0;
    const uint8_t ids[2] = {1, 2}, motors[2] = {4, 2};
    rcfw_bus *bus = rcfw_bus_create(2, ids, motors);
    if (!bus) {
        puts("create failed");
        return 1;
    }
    if (rcfw_bus_create(1, ids, (const uint8_t[]){5}) != NULL) {
        fails++; /* 5 motors is invalid */
    }
    const uint8_t ping[] = {0xFF, 0xFF, 0xFD, 0x00, 0xFE, 0x03, 0x00, 0x01, 0x31, 0x42};
    rcfw_bus_write(bus, ping, sizeof ping);
    rcfw_advance_us(bus, 2000);
    uint8_t buf[64];
    int32_t n = rcfw_bus_read(bus, buf, sizeof buf);
    if (n != 28 || buf[4] != 1 || buf[14 + 4] != 2) {
        printf("broadcast ping: %d bytes\n", n);
        fails++;
    }
    if (rcfw_get_pwm(bus, 5, 0) != RCFW_HOST_EARG || rcfw_get_pwm(bus, 1, 2) != RCFW_HOST_EARG) {
        fails++;
    }
    if (rcfw_now_us(bus) != 2000u || rcfw_get_driver_enable(bus, 0, 0) != 0 || rcfw_is_powered(bus, 1) != 1) {
        fails++;
    }
    rcfw_bus_destroy(bus);
    printf("%s\n", fails ? "FAIL" : "ok");
    return fails ? 1 : 0;
}
