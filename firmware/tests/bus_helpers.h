/* Helpers for tests that talk to modules through the host library like the .NET host does. */
#ifndef BUS_HELPERS_H
#define BUS_HELPERS_H
#include "rcfw/frame.h"
#include "rcfw/module.h"
#include "rcfw_host.h"
#include "tf.h"

typedef struct {
    int id;
    int error;
    uint8_t data[400];
    int len;
} status_t;

static inline void send_frame(rcfw_bus *bus, uint8_t id, uint8_t inst, const uint8_t *params, uint16_t n)
{
    uint8_t body[700], out[1100];
    body[0] = inst;
    if (n) {
        memcpy(body + 1, params, n);
    }
    uint16_t len = rcfw_frame_build(out, sizeof out, id, body, (uint16_t)(n + 1u));
    rcfw_bus_write(bus, out, len);
}

/* Advance time by us and decode every status packet that arrived. Returns the count. */
static inline int collect(rcfw_bus *bus, uint32_t us, status_t *st, int max)
{
    static rcfw_parser p;
    uint8_t buf[4096];
    rcfw_advance_us(bus, us);
    int n = rcfw_bus_read(bus, buf, sizeof buf);
    rcfw_parser_reset(&p);
    int k = 0;
    for (int i = 0; i < n; i++) {
        if (rcfw_parser_feed(&p, buf[i]) == RCFW_RX_FRAME && p.inst == RCFW_INST_STATUS && k < max) {
            st[k].id = p.id;
            st[k].error = p.params[0];
            st[k].len = p.plen - 1;
            memcpy(st[k].data, p.params + 1, (size_t)(p.plen - 1));
            k++;
        }
    }
    return k;
}

static inline void wr(rcfw_bus *bus, uint8_t id, uint16_t addr, const void *data, uint16_t n)
{
    uint8_t p[600];
    p[0] = (uint8_t)addr;
    p[1] = (uint8_t)(addr >> 8);
    memcpy(p + 2, data, n);
    send_frame(bus, id, RCFW_INST_WRITE, p, (uint16_t)(n + 2u));
}
static inline void wr8(rcfw_bus *bus, uint8_t id, uint16_t addr, uint8_t v) { wr(bus, id, addr, &v, 1); }
static inline void wr16(rcfw_bus *bus, uint8_t id, uint16_t addr, uint16_t v)
{
    uint8_t b[2] = {(uint8_t)v, (uint8_t)(v >> 8)};
    wr(bus, id, addr, b, 2);
}
static inline void wr32(rcfw_bus *bus, uint8_t id, uint16_t addr, int32_t v)
{
    uint32_t u = (uint32_t)v;
    uint8_t b[4] = {(uint8_t)u, (uint8_t)(u >> 8), (uint8_t)(u >> 16), (uint8_t)(u >> 24)};
    wr(bus, id, addr, b, 4);
}
static inline int32_t peek32(rcfw_bus *bus, int module, uint16_t addr)
{
    uint8_t b[4];
    rcfw_peek_table(bus, module, addr, b, 4);
    return (int32_t)((uint32_t)b[0] | ((uint32_t)b[1] << 8) | ((uint32_t)b[2] << 16) | ((uint32_t)b[3] << 24));
}
static inline int peek16(rcfw_bus *bus, int module, uint16_t addr)
{
    uint8_t b[2];
    rcfw_peek_table(bus, module, addr, b, 2);
    return b[0] | (b[1] << 8);
}
static inline int peek8(rcfw_bus *bus, int module, uint16_t addr)
{
    uint8_t b = 0;
    rcfw_peek_table(bus, module, addr, &b, 1);
    return b;
}

/* A write that expects an OK status; returns the status error byte (or -1: no reply). */
static inline int write_ack(rcfw_bus *bus, uint8_t id, uint16_t addr, const void *data, uint16_t n)
{
    status_t st[2];
    wr(bus, id, addr, data, n);
    int k = collect(bus, 2000, st, 2);
    return k == 1 ? st[0].error : -1;
}

/* Simple motor model: first-order speed response to PWM, Hall state from position. */
typedef struct {
    double pos;     /* counts */
    double vel;     /* counts/s */
    double max_vel; /* at PWM 255 */
    double tau;     /* s */
    int deadband;   /* |PWM| below this does not move (static friction) */
} motor_model;

static const uint8_t hall_fwd[6] = {1, 3, 2, 6, 4, 5};

static inline uint8_t model_hall(const motor_model *mm)
{
    long c = (long)(mm->pos >= 0 ? mm->pos : mm->pos - 1.0); /* floor */
    long i = ((c % 6) + 6) % 6;
    return hall_fwd[i];
}

/* Run the module and the model together for ms milliseconds (motor 0 of module 0). */
static inline void simulate(rcfw_bus *bus, int module, int motor, motor_model *mm, int ms)
{
    for (int t = 0; t < ms * 10; t++) {
        rcfw_advance_us(bus, 100);
        int pwm = rcfw_get_pwm(bus, module, motor);
        double target = (pwm > -mm->deadband && pwm < mm->deadband) ? 0.0 : mm->max_vel * pwm / 255.0;
        mm->vel += (target - mm->vel) * (1e-4 / mm->tau);
        if (pwm > -mm->deadband && pwm < mm->deadband && (mm->vel < 50 && mm->vel > -50)) {
            mm->vel = 0; /* friction holds it */
        }
        mm->pos += mm->vel * 1e-4;
        rcfw_set_hall(bus, module, motor, model_hall(mm));
    }
}
/* Writes kp = 500 then kp = 600 to module ID 1 (two parameter saves) and returns the FRAM address of the parameter
 * slot holding the newer copy (the one with kp 600). */
static inline uint16_t write_kp_twice_newest_slot(rcfw_bus *bus)
{
    uint16_t kp = 500;
    wr(bus, 1, RCFW_CT_KP, &kp, 2);
    rcfw_advance_us(bus, 1000);
    kp = 600;
    wr(bus, 1, RCFW_CT_KP, &kp, 2);
    rcfw_advance_us(bus, 1000);
    uint8_t s0[8], s1[8];
    rcfw_fram_peek(bus, 0, RCFW_FRAM_PARAMS_A, s0, 8);
    rcfw_fram_peek(bus, 0, RCFW_FRAM_PARAMS_B, s1, 8);
    uint32_t q0, q1;
    memcpy(&q0, s0 + 4, 4);
    memcpy(&q1, s1 + 4, 4);
    return q1 > q0 ? RCFW_FRAM_PARAMS_B : RCFW_FRAM_PARAMS_A;
}

/* A bus of n of three modules: ids 1, 2, 3 with 4, 2 and 2 motors. */
static inline rcfw_bus *make_bus(int n)
{
    const uint8_t ids[3] = {1, 2, 3}, motors[3] = {4, 2, 2};
    rcfw_bus *bus = rcfw_bus_create(n, ids, motors);
    CHECK(bus != NULL);
    return bus;
}

#endif
