#define _POSIX_C_SOURCE 199309L
/* Host-library speed: simulated seconds per wall second for a bus of N 4-motor modules,
 * with a 1 kHz SYNC WRITE + SYNC READ cycle like the .NET control loop.
 * usage: rcfw_host_speed [modules=12] [sim_seconds=2] */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "rcfw/frame.h"
#include "rcfw_host.h"

int main(int argc, char **argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 12;
    int secs = argc > 2 ? atoi(argv[2]) : 2;
    if (n < 1 || n > 200 || secs < 1) {
        return 2;
    }
    uint8_t ids[200], motors[200];
    for (int i = 0; i < n; i++) {
        ids[i] = (uint8_t)(i + 1);
        motors[i] = 4;
    }
    rcfw_bus *bus = rcfw_bus_create(n, ids, motors);
    uint8_t body[1024], frame[1100], rx[8192];
    /* everyone to 4.5 Mbaud (code 7): a 1 kHz cycle of 16 B out + 32 B back per module needs it */
    const uint8_t baud[4] = {RCFW_INST_WRITE, 8, 0, 7};
    rcfw_bus_write(bus, frame, rcfw_frame_build(frame, sizeof frame, 0xFE, baud, 4));
    rcfw_advance_us(bus, 1000);
    rcfw_bus_set_baud(bus, 4500000u);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    long replies = 0;
    for (int ms = 0; ms < secs * 1000; ms++) {
        uint16_t k = 0;
        body[k++] = RCFW_INST_SYNC_WRITE;
        body[k++] = 232, body[k++] = 0, body[k++] = 16, body[k++] = 0;
        for (int i = 0; i < n; i++) {
            body[k++] = ids[i];
            for (int j = 0; j < 16; j++) {
                body[k++] = (uint8_t)(j % 4 == 0 ? ms & 0x7F : 0);
            }
        }
        rcfw_bus_write(bus, frame, rcfw_frame_build(frame, sizeof frame, 0xFE, body, k));
        k = 0;
        body[k++] = RCFW_INST_SYNC_READ;
        body[k++] = 248, body[k++] = 0, body[k++] = 32, body[k++] = 0;
        for (int i = 0; i < n; i++) {
            body[k++] = ids[i];
        }
        rcfw_bus_write(bus, frame, rcfw_frame_build(frame, sizeof frame, 0xFE, body, k));
        rcfw_advance_us(bus, 1000);
        replies += rcfw_bus_read(bus, rx, sizeof rx);
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double wall = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    printf("%d modules x 4 motors, %d s simulated in %.3f s wall: %.1fx real time, %.2f us per module-tick, "
           "%ld reply bytes, %d collisions\n",
           n, secs, wall, secs / wall, wall * 1e6 / ((double)secs * 10000.0 * n), replies, rcfw_bus_collisions(bus));
    rcfw_bus_destroy(bus);
    return 0;
}
