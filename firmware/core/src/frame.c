#include "rcfw/frame.h"

#include <string.h>

#include "rcfw/crc16.h"

#define HEADER_WORD 0xFFFFFD00u

uint16_t rcfw_stuff(const uint8_t *src, uint16_t n, uint8_t *dst, uint16_t cap)
{
    uint16_t o = 0;
    for (uint16_t i = 0; i < n; i++) {
        if (o >= cap) {
            return 0;
        }
        dst[o++] = src[i];
        if (i >= 2 && src[i] == 0xFD && src[i - 1] == 0xFF && src[i - 2] == 0xFF) {
            if (o >= cap) {
                return 0;
            }
            dst[o++] = 0xFD;
        }
    }
    return o;
}

int32_t rcfw_unstuff(uint8_t *buf, uint16_t n)
{
    uint16_t o = 0;
    uint16_t i = 0;
    while (i < n) {
        uint8_t b = buf[i++];
        buf[o++] = b;
        if (b == 0xFD && o >= 3 && buf[o - 2] == 0xFF && buf[o - 3] == 0xFF) {
            if (i >= n || buf[i] != 0xFD) {
                return -1;
            }
            i++; /* drop the stuffing byte */
        }
    }
    return o;
}

uint16_t rcfw_frame_build(uint8_t *out, uint16_t cap, uint8_t id, const uint8_t *body, uint16_t body_len)
{
    if (cap < 10u || body_len == 0u) {
        return 0;
    }
    out[0] = 0xFF;
    out[1] = 0xFF;
    out[2] = 0xFD;
    out[3] = 0x00;
    out[4] = id;
    uint16_t s = rcfw_stuff(body, body_len, out + 7, (uint16_t)(cap - 9u));
    if (s == 0) {
        return 0;
    }
    uint16_t len = (uint16_t)(s + 2u);
    out[5] = (uint8_t)(len & 0xFFu);
    out[6] = (uint8_t)(len >> 8);
    uint16_t crc = rcfw_crc16(0, out, (size_t)7u + s);
    out[7u + s] = (uint8_t)(crc & 0xFFu);
    out[8u + s] = (uint8_t)(crc >> 8);
    return (uint16_t)(9u + s);
}

void rcfw_parser_reset(rcfw_parser *p)
{
    p->pos = 0;
    p->need = 0;
    p->window = 0;
    p->in_frame = 0;
}

rcfw_rx_result rcfw_parser_feed(rcfw_parser *p, uint8_t byte)
{
    p->window = (p->window << 8) | byte;
    if (!p->in_frame) {
        if (p->window == HEADER_WORD) {
            p->in_frame = 1;
            p->pos = 0;
            p->need = 3;
        }
        return RCFW_RX_MORE;
    }
    /* A header inside INST/params cannot occur in a correctly stuffed frame: the previous
     * frame was truncated, start over at this header (CRC bytes excluded). */
    if (p->window == HEADER_WORD && p->pos >= 3u && p->pos + 2u < p->need) {
        p->pos = 0;
        p->need = 3;
        return RCFW_RX_BAD_LEN;
    }
    p->buf[p->pos++] = byte;
    if (p->pos == 3u) {
        uint16_t len = (uint16_t)(p->buf[1] | (p->buf[2] << 8));
        if (len < 3u || len > RCFW_RX_MAX - 3u) {
            p->in_frame = 0;
            return RCFW_RX_BAD_LEN;
        }
        p->need = (uint16_t)(3u + len);
        return RCFW_RX_MORE;
    }
    if (p->pos < p->need) {
        return RCFW_RX_MORE;
    }
    /* complete */
    p->in_frame = 0;
    p->window = 0;
    static const uint8_t hdr[4] = {0xFF, 0xFF, 0xFD, 0x00};
    uint16_t crc = rcfw_crc16(rcfw_crc16(0, hdr, 4), p->buf, (size_t)p->need - 2u);
    uint16_t got = (uint16_t)(p->buf[p->need - 2u] | (p->buf[p->need - 1u] << 8));
    if (crc != got) {
        return RCFW_RX_BAD_CRC;
    }
    int32_t body = rcfw_unstuff(p->buf + 3, (uint16_t)(p->need - 5u));
    if (body < 1) {
        return RCFW_RX_BAD_STUFF;
    }
    p->id = p->buf[0];
    p->inst = p->buf[3];
    p->params = p->buf + 4;
    p->plen = (uint16_t)(body - 1);
    return RCFW_RX_FRAME;
}
