/* The host port's inside, shared by its two files: rcfw_host.c (the modules' HAL, the bus, simulated time) and
 * rcfw_host_io.c (what the simulation around the modules sets and reads: sensors, outputs, tables, FRAM, power). */
#ifndef HOST_BUS_H
#define HOST_BUS_H
#include "rcfw_host.h"

#include "rcfw/hal.h"
#include "rcfw/module.h"

#define TICK_US (1000000u / RCFW_CONTROL_RATE_HZ)

struct rcfw_port {
    rcfw_bus *bus;
    int32_t index;
    uint8_t n_motors;
    uint8_t powered;
    uint8_t hall[RCFW_HOST_MAX_MOTORS];
    uint16_t current[RCFW_HOST_MAX_MOTORS];
    uint16_t pot[RCFW_HOST_MAX_MOTORS];
    int16_t pwm[RCFW_HOST_MAX_MOTORS];
    uint8_t bridge[RCFW_HOST_MAX_MOTORS];
    uint32_t uart_bps;
    uint64_t rx_end_ns;   /* end of the last received byte */
    uint64_t tx_start_ns; /* last transmission window (RS-485 DE high) */
    uint64_t tx_end_ns;
    int32_t cut_remaining; /* < 0: disarmed */
    uint8_t tx_broken;     /* 1: the RS-485 driver puts nothing on the line (a broken transmit line) */
    uint8_t echo[RCFW_TX_MAX]; /* last transmission, heard by the other modules (half-duplex bus) */
    uint16_t echo_len;         /* 0: already heard */
    uint64_t echo_start_ns;
    uint64_t next_tick_us;
    uint8_t fram[RCFW_HOST_FRAM_SIZE];
    rcfw_module mod;
};

typedef struct {
    uint64_t t_ns;
    uint8_t b;
} timed_byte;

struct rcfw_bus {
    int32_t n;
    struct rcfw_port *ports;
    uint32_t bps;
    uint64_t now_us;
    uint64_t host_busy_until_ns;
    int32_t collisions;
    timed_byte *q; /* sorted by t_ns */
    int32_t q_len;
    int32_t q_cap;
};

/* The port of module index `module`, or NULL when out of range (or no bus). */
struct rcfw_port *host_port_of(const rcfw_bus *bus, int32_t module);
/* RCFW_HOST_OK with the port in *out when module and motor exist, else RCFW_HOST_EARG. */
int32_t host_check_motor(const rcfw_bus *bus, int32_t module, int32_t motor, struct rcfw_port **out);
/* Powers the module up and starts its firmware with reset cause `cause`. */
void host_boot(struct rcfw_port *p, uint8_t cause);
/* Cuts the module's power: it stops (no ticks, no bus, outputs off) until rcfw_power_cycle. */
void host_power_fail(struct rcfw_port *p);

#endif
