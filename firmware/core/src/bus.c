/* Dynamixel Protocol 2.0 instructions: what a module does with each frame it receives. */
#include <string.h>

#include "internal.h"
#include "rcfw/hal.h"
#include "rcfw/verify.h"

#define CLEAR_ERRORS 0x02u /* Clear option: latched errors (0x01, multi-turn, does not apply) */

static uint32_t byte_slots_us(const rcfw_module *m, uint32_t bytes)
{
    uint64_t ns = (uint64_t)bytes * 10u * 1000000000u / rcfw_module_baud_bps(m);
    return (uint32_t)((ns + 999u) / 1000u);
}

static uint16_t build_status(rcfw_module *m, uint8_t err, const uint8_t *data, uint16_t len)
{
    RCFW_ASSERT(len + 2u <= sizeof m->body);
    if (m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] != 0u) {
        err |= RCFW_ERR_ALERT;
    }
    m->body[0] = RCFW_INST_STATUS;
    m->body[1] = err;
    if (len && data) {
        memcpy(&m->body[2], data, len);
    } else if (len) {
        memset(&m->body[2], 0, len);
    }
    uint16_t n = rcfw_frame_build(m->tx, sizeof m->tx, m->ct[RCFW_CT_ID], m->body, (uint16_t)(len + 2u));
    RCFW_ASSERT(n != 0u);
    return n;
}

static void send_tx(rcfw_module *m, uint16_t n, uint32_t extra_delay_us)
{
    rcfw_hal_uart_send(m->port, m->tx, n, 2u * m->ct[RCFW_CT_RETURN_DELAY_TIME] + extra_delay_us);
}

static void reply(rcfw_module *m, uint8_t err, const uint8_t *data, uint16_t len, uint32_t extra_delay_us)
{
    send_tx(m, build_status(m, err, data, len), extra_delay_us);
}

/* Status of a read. A refused one carries its error and the requested length of zero bytes, as a ROBOTIS
 * device does (a master that takes the data without looking at the error finds the length it asked for);
 * only a length longer than the whole table, which no reply could carry, gets the error alone. */
static uint16_t build_read_status(rcfw_module *m, uint16_t a, uint16_t n)
{
    uint8_t e = rcfwi_check_read(m, a, n);
    if (e != 0u) {
        m->stats.bad_requests++;
        return build_status(m, e, 0, n <= RCFW_CT_SIZE ? n : 0u);
    }
    rcfw_module_publish(m);
    return build_status(m, 0, &m->ct[a], n);
}

/* A reply of a SYNC READ / BULK READ: the first listed module answers after its return delay, every other
 * one when it has heard the previous module's status packet end (plus its return delay). */
static void chained_reply(rcfw_module *m, uint8_t prev_id, uint16_t a, uint16_t n)
{
    uint16_t len = build_read_status(m, a, n);
    if (prev_id == RCFW_ID_BROADCAST) {
        send_tx(m, len, 0);
        return;
    }
    m->chain_prev = prev_id;
    m->chain_len = len;
}

static uint16_t le16(const uint8_t *p) { return (uint16_t)(p[0] | (p[1] << 8)); }

static void sync_read(rcfw_module *m, const uint8_t *pa, uint16_t pl, uint8_t my)
{
    uint16_t a = le16(pa), n = le16(pa + 2);
    for (uint16_t k = 0; k < pl - 4u; k++) {
        if (pa[4u + k] == my) {
            m->wd_ticks = 0;
            chained_reply(m, k == 0u ? RCFW_ID_BROADCAST : pa[3u + k], a, n);
            return;
        }
    }
}

/* BULK READ: per module ID, addr (2), length (2). */
static void bulk_read(rcfw_module *m, const uint8_t *pa, uint16_t pl, uint8_t my)
{
    for (uint16_t o = 0; o < pl; o = (uint16_t)(o + 5u)) {
        if (pa[o] == my) {
            m->wd_ticks = 0;
            chained_reply(m, o == 0u ? RCFW_ID_BROADCAST : pa[o - 5u], le16(pa + o + 1u), le16(pa + o + 3u));
            return;
        }
    }
}

static void sync_write(rcfw_module *m, const uint8_t *pa, uint16_t pl, uint8_t my)
{
    uint16_t a = le16(pa), n = le16(pa + 2);
    if (n == 0u || (pl - 4u) % (n + 1u) != 0u) {
        m->stats.bad_requests++;
        return;
    }
    for (uint16_t o = 4; o < pl; o = (uint16_t)(o + n + 1u)) {
        if (pa[o] == my) {
            m->wd_ticks = 0;
            (void)rcfwi_write(m, a, pa + o + 1u, n);
            return;
        }
    }
}

/* BULK WRITE: per module ID, addr (2), length (2), data. The whole list is checked for consistency first:
 * a list whose lengths do not add up is dropped by every module (none acts on half a frame). */
static void bulk_write(rcfw_module *m, const uint8_t *pa, uint16_t pl, uint8_t my)
{
    uint16_t o = 0;
    while (o < pl) {
        uint16_t left = (uint16_t)(pl - o);
        RCFW_VERIFY(left >= 6u && le16(pa + o + 3u) >= 1u && le16(pa + o + 3u) <= left - 5u, m->stats.bad_requests, );
        o = (uint16_t)(o + 5u + le16(pa + o + 3u));
    }
    for (o = 0; o < pl; o = (uint16_t)(o + 5u + le16(pa + o + 3u))) {
        if (pa[o] == my) {
            m->wd_ticks = 0;
            (void)rcfwi_write(m, le16(pa + o + 1u), pa + o + 5u, le16(pa + o + 3u));
            return;
        }
    }
}

/* REG WRITE: checked now, kept until ACTION applies it (checked again then). */
static uint8_t reg_write(rcfw_module *m, const uint8_t *pa, uint16_t pl)
{
    RCFW_VERIFY(pl >= 3u && pl - 2u <= sizeof m->reg_data, m->stats.bad_requests, RCFW_ERR_DATA_LENGTH);
    uint16_t n = (uint16_t)(pl - 2u);
    uint8_t e = rcfwi_check_write(m, le16(pa), pa + 2, n);
    if (e == 0u) {
        m->reg_addr = le16(pa);
        m->reg_len = n;
        memcpy(m->reg_data, pa + 2, n);
    }
    return e;
}

static uint8_t action(rcfw_module *m, uint16_t pl)
{
    RCFW_VERIFY(pl == 0u, m->stats.bad_requests, RCFW_ERR_DATA_LENGTH);
    /* nothing registered: an instruction error, as the ROBOTIS e-Manual's error table says of an ACTION
     * without a REG WRITE */
    RCFW_VERIFY(m->reg_len != 0u, m->stats.bad_requests, RCFW_ERR_INSTRUCTION);
    uint16_t n = m->reg_len;
    m->reg_len = 0;
    return rcfwi_write(m, m->reg_addr, m->reg_data, n);
}

/* CLEAR: option, then the key 44 58 4C 22. Option 0x02 clears the latched errors; 0x01 (multi-turn
 * position) does not apply to Hall-count positions: result fail. */
static uint8_t clear(rcfw_module *m, const uint8_t *pa, uint16_t pl)
{
    static const uint8_t key[4] = {0x44u, 0x58u, 0x4Cu, 0x22u};
    RCFW_VERIFY(pl == 5u, m->stats.bad_requests, RCFW_ERR_DATA_LENGTH);
    RCFW_VERIFY(memcmp(pa + 1, key, 4) == 0 && (pa[0] == 0x01u || pa[0] == CLEAR_ERRORS), m->stats.bad_requests,
                RCFW_ERR_DATA_RANGE);
    RCFW_VERIFY(pa[0] == CLEAR_ERRORS, m->stats.bad_requests, RCFW_ERR_RESULT_FAIL);
    rcfwi_clear_errors(m);
    return 0;
}

static uint8_t factory_reset(rcfw_module *m, const uint8_t *pa, uint16_t pl)
{
    RCFW_VERIFY(pl == 1u, m->stats.bad_requests, RCFW_ERR_DATA_LENGTH);
    RCFW_VERIFY(pa[0] == 0xFFu || pa[0] == 0x01u || pa[0] == 0x02u, m->stats.bad_requests, RCFW_ERR_DATA_RANGE);
    return 0;
}

/* Broadcast-only instructions with a list (sync/bulk): no reply, malformed lists are dropped. */
static bool list_instruction(rcfw_module *m, const rcfw_parser *f, uint8_t my)
{
    const uint8_t *pa = f->params;
    uint16_t pl = f->plen;
    bool bulk = f->inst == RCFW_INST_BULK_READ || f->inst == RCFW_INST_BULK_WRITE;
    if (f->inst != RCFW_INST_SYNC_READ && f->inst != RCFW_INST_SYNC_WRITE && !bulk) {
        return false;
    }
    if (f->id != RCFW_ID_BROADCAST || pl < 5u || (f->inst == RCFW_INST_BULK_READ && pl % 5u != 0u)) {
        m->stats.bad_requests++;
        return true;
    }
    switch (f->inst) {
    case RCFW_INST_SYNC_READ:
        sync_read(m, pa, pl, my);
        break;
    case RCFW_INST_SYNC_WRITE:
        sync_write(m, pa, pl, my);
        break;
    case RCFW_INST_BULK_READ:
        bulk_read(m, pa, pl, my);
        break;
    default:
        bulk_write(m, pa, pl, my);
        break;
    }
    return true;
}

/* A status packet of another module: the cue of a chained reply waiting for it. */
static void heard_status(rcfw_module *m, uint8_t id)
{
    if (m->chain_len != 0u && id == m->chain_prev) {
        uint16_t n = m->chain_len;
        m->chain_len = 0;
        send_tx(m, n, 0);
    }
}

static void handle_frame(rcfw_module *m)
{
    const rcfw_parser *f = &m->rx;
    uint8_t my = m->ct[RCFW_CT_ID];
    bool bcast = f->id == RCFW_ID_BROADCAST;
    const uint8_t *pa = f->params;
    uint16_t pl = f->plen;
    if (f->inst == RCFW_INST_STATUS) {
        heard_status(m, f->id);
        return;
    }
    m->chain_len = 0; /* a new instruction ends any wait for a previous module */
    m->fast_len = 0;
    if (f->inst == RCFW_INST_FAST_SYNC_READ || f->inst == RCFW_INST_FAST_BULK_READ) {
        rcfwi_fast_read(m, f);
        return;
    }
    if (list_instruction(m, f, my) || (!bcast && f->id != my)) {
        return;
    }
    m->wd_ticks = 0;
    uint8_t e;
    switch (f->inst) {
    case RCFW_INST_PING: {
        uint8_t d[3] = {m->ct[RCFW_CT_MODEL_NUMBER], m->ct[RCFW_CT_MODEL_NUMBER + 1u], m->ct[RCFW_CT_FIRMWARE_VERSION]};
        /* broadcast: one 16-byte-time slot per ID so replies never overlap */
        reply(m, 0, d, 3, bcast ? byte_slots_us(m, 16u * my) : 0u);
        return;
    }
    case RCFW_INST_READ:
        if (bcast) {
            return;
        }
        if (pl != 4u) {
            m->stats.bad_requests++;
            reply(m, RCFW_ERR_DATA_LENGTH, 0, 0, 0);
            return;
        }
        send_tx(m, build_read_status(m, le16(pa), le16(pa + 2)), 0);
        return;
    case RCFW_INST_WRITE:
        e = pl < 3u ? RCFW_ERR_DATA_LENGTH : rcfwi_write(m, le16(pa), pa + 2, (uint16_t)(pl - 2u));
        m->stats.bad_requests += pl < 3u;
        break;
    case RCFW_INST_REG_WRITE:
        e = reg_write(m, pa, pl);
        break;
    case RCFW_INST_ACTION:
        e = action(m, pl);
        break;
    case RCFW_INST_CLEAR:
        e = clear(m, pa, pl);
        break;
    case RCFW_INST_FACTORY_RESET:
        e = factory_reset(m, pa, pl);
        if (!bcast) {
            reply(m, e, 0, 0, 0); /* sent before the reset */
        }
        if (e == 0u) {
            rcfwi_factory_reset(m, pa[0]);
        }
        return;
    case RCFW_INST_REBOOT:
        e = 0;
        m->reboot_pending = 1;
        break;
    default:
        m->stats.bad_requests++;
        e = RCFW_ERR_INSTRUCTION;
        break;
    }
    if (!bcast) {
        reply(m, e, 0, 0, 0);
    }
}

void rcfw_module_rx_byte(rcfw_module *m, uint8_t byte)
{
    m->rx_idle_ticks = 0;
    rcfwi_fast_heard(m, byte);
    rcfw_rx_result r = rcfw_parser_feed(&m->rx, byte);
    switch (r) {
    case RCFW_RX_FRAME:
        m->stats.rx_frames++;
        handle_frame(m);
        break;
    case RCFW_RX_BAD_CRC:
        m->stats.rx_bad_crc++;
        break;
    case RCFW_RX_BAD_LEN:
        m->stats.rx_bad_len++;
        break;
    case RCFW_RX_BAD_STUFF:
        m->stats.rx_bad_stuff++;
        break;
    default:
        break;
    }
}
