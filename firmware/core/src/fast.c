/* FAST SYNC READ (0x8A) and FAST BULK READ (0x9A): the listed modules answer with ONE status packet,
 *   FF FF FD 00 | FE | LEN_L LEN_H | 55 | part 1 | part 2 | ... | part N
 *   part k = error, ID, data (length n_k), CRC_L CRC_H
 * LEN = 1 + sum(4 + n_k). The first listed module sends the header and its part; each later module adds its
 * part as soon as the previous part has ended (plus its return delay), having counted the packet's bytes on the
 * bus. The CRC of part k covers every byte of the packet from the first FF to the end of part k's data, so the
 * last part's CRC is the CRC of the whole packet. The parts are not byte-stuffed (a part's place is fixed by the
 * instruction); a refused part carries its error and n_k zero bytes (a part asked with n_k = 0: data length
 * error, no data). A list with a part longer than a module can send is dropped by every module, so that no
 * module is left waiting for a part that never comes. A waiting module checks the part before its own as it
 * hears it (its ID, and its CRC against the bytes heard): anything else (the previous module silent, and the
 * host's next frame instead) makes it give up rather than send into the middle of another frame. */
#include <string.h>

#include "internal.h"
#include "rcfw/crc16.h"
#include "rcfw/hal.h"

#define PACKET_HEAD 8u /* FF FF FD 00 FE LEN_L LEN_H 55 */

static uint16_t le16(const uint8_t *p) { return (uint16_t)(p[0] | (p[1] << 8)); }

/* Entry k of the list: ID, address and length (sync: common address and length). */
static void entry(const rcfw_parser *f, uint16_t k, uint8_t *id, uint16_t *a, uint16_t *n)
{
    if (f->inst == RCFW_INST_FAST_SYNC_READ) {
        *id = f->params[4u + k];
        *a = le16(f->params);
        *n = le16(f->params + 2);
    } else {
        const uint8_t *e = f->params + 5u * k;
        *id = e[0];
        *a = le16(e + 1);
        *n = le16(e + 3);
    }
}

/* Error, ID and data of this module's part into tx at offset o. Returns the part length without CRC. */
static uint16_t build_part(rcfw_module *m, uint16_t o, uint16_t a, uint16_t n)
{
    uint8_t e = rcfwi_check_read(m, a, n);
    if (e != 0u) {
        m->stats.bad_requests++;
    } else {
        rcfw_module_publish(m);
    }
    if (m->ct[RCFW_CT_HARDWARE_ERROR_STATUS] != 0u) {
        e |= RCFW_ERR_ALERT;
    }
    m->tx[o] = e;
    m->tx[o + 1u] = m->ct[RCFW_CT_ID];
    if (e & 0x7Fu) {
        memset(&m->tx[o + 2u], 0, n);
    } else {
        memcpy(&m->tx[o + 2u], &m->ct[a], n);
    }
    return (uint16_t)(n + 2u);
}

static void send_with_crc(rcfw_module *m, uint16_t len, uint16_t crc)
{
    crc = rcfw_crc16(crc, m->tx + (len - m->fast_len), m->fast_len);
    m->tx[len] = (uint8_t)crc;
    m->tx[len + 1u] = (uint8_t)(crc >> 8);
    m->fast_len = 0;
    rcfw_hal_uart_send(m->port, m->tx, (uint16_t)(len + 2u), 2u * m->ct[RCFW_CT_RETURN_DELAY_TIME]);
}

void rcfwi_fast_read(rcfw_module *m, const rcfw_parser *f)
{
    uint16_t pl = f->plen;
    bool sync = f->inst == RCFW_INST_FAST_SYNC_READ;
    if (f->id != RCFW_ID_BROADCAST || pl < 5u || (!sync && pl % 5u != 0u)) {
        m->stats.bad_requests++;
        return;
    }
    uint16_t count = sync ? (uint16_t)(pl - 4u) : (uint16_t)(pl / 5u);
    uint32_t total = 1u, at = PACKET_HEAD;
    int32_t mine = -1;
    uint16_t my_a = 0, my_n = 0;
    bool unanswerable = false;
    for (uint16_t k = 0; k < count; k++) {
        uint8_t id;
        uint16_t a, n;
        entry(f, k, &id, &a, &n);
        if (id == m->ct[RCFW_CT_ID] && mine < 0) {
            mine = k;
            my_a = a;
            my_n = n;
            m->fast_at = (uint16_t)at;
        }
        if (mine < 0) {
            m->fast_prev_id = id; /* the part before this module's, once it is found */
            m->fast_prev_at = (uint16_t)at;
        }
        unanswerable |= n + PACKET_HEAD + 4u > sizeof m->tx;
        total += 4u + n;
        at += 4u + n;
    }
    if (unanswerable || total + 7u > 0xFFFFu) {
        m->stats.bad_requests++; /* a part no module could send: every module drops the whole list */
        return;
    }
    if (mine < 0) {
        return;
    }
    m->wd_ticks = 0;
    m->fast_total = (uint16_t)total;
    if (mine == 0) {
        static const uint8_t head[5] = {0xFFu, 0xFFu, 0xFDu, 0x00u, RCFW_ID_BROADCAST};
        memcpy(m->tx, head, 5);
        m->tx[5] = (uint8_t)total;
        m->tx[6] = (uint8_t)(total >> 8);
        m->tx[7] = RCFW_INST_STATUS;
        m->fast_len = (uint16_t)(PACKET_HEAD + build_part(m, PACKET_HEAD, my_a, my_n));
        send_with_crc(m, m->fast_len, 0);
        return;
    }
    m->fast_len = build_part(m, 0, my_a, my_n);
    m->fast_pos = 0;
    m->fast_crc = 0;
}

/* A byte of the packet past its header, at offset p: the part before this module's must carry its ID and
 * end with the CRC of everything heard before that CRC. */
static bool part_byte_ok(rcfw_module *m, uint16_t p, uint8_t b)
{
    if (p == m->fast_prev_at + 1u) {
        return b == m->fast_prev_id;
    }
    if (p == m->fast_at - 2u) {
        m->fast_expect = m->fast_crc;
        return b == (uint8_t)m->fast_crc;
    }
    return p != m->fast_at - 1u || b == (uint8_t)(m->fast_expect >> 8);
}

/* One byte heard on the bus while this module waits for its place in a fast read packet. */
void rcfwi_fast_heard(rcfw_module *m, uint8_t b)
{
    if (m->fast_len == 0u) {
        return;
    }
    static const uint8_t head[8] = {0xFFu, 0xFFu, 0xFDu, 0x00u, RCFW_ID_BROADCAST, 0, 0, RCFW_INST_STATUS};
    uint16_t p = m->fast_pos;
    bool ok = p >= PACKET_HEAD ? part_byte_ok(m, p, b)
                               : (p == 5u && b == (uint8_t)m->fast_total) ||
                                     (p == 6u && b == (uint8_t)(m->fast_total >> 8)) ||
                                     (p != 5u && p != 6u && b == head[p]);
    if (!ok) {
        if (p < 4u) { /* not the packet's header yet: look again from this byte (FF FF FF: the last two) */
            static const uint8_t ff2[2] = {0xFFu, 0xFFu};
            m->fast_pos = b != 0xFFu ? 0u : p == 2u ? 2u : 1u;
            m->fast_crc = rcfw_crc16(0, ff2, m->fast_pos);
            return;
        }
        m->fast_len = 0; /* some other packet: give up, the host asks again */
        m->stats.bad_requests++;
        return;
    }
    m->fast_crc = rcfw_crc16(m->fast_crc, &b, 1);
    if (++m->fast_pos == m->fast_at) {
        send_with_crc(m, m->fast_len, m->fast_crc);
    }
}
