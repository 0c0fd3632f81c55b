#include "rcfw/store.h"

#include "rcfw/crc16.h"
#include "rcfw/hal.h"

void rcfw_store_init(rcfw_store *s, uint16_t base0, uint16_t base1, uint16_t magic, uint16_t len)
{
    s->base[0] = base0;
    s->base[1] = base1;
    s->magic = magic;
    s->len = len;
    s->seq = 0;
    s->current = 0xFFu;
}

/* Validate one slot by streaming it through the CRC in small chunks (no big buffer). */
static bool slot_valid(const rcfw_store *s, struct rcfw_port *p, uint8_t slot, uint32_t *seq)
{
    uint8_t hdr[8];
    uint16_t a = s->base[slot];
    if (!rcfw_hal_fram_read(p, a, hdr, 8)) {
        return false;
    }
    if ((uint16_t)(hdr[0] | (hdr[1] << 8)) != s->magic || (uint16_t)(hdr[2] | (hdr[3] << 8)) != s->len) {
        return false;
    }
    uint16_t crc = rcfw_crc16(0, hdr, 8);
    uint8_t chunk[32];
    uint16_t off = 0;
    while (off < s->len) {
        uint16_t n = (uint16_t)(s->len - off);
        if (n > sizeof chunk) {
            n = sizeof chunk;
        }
        if (!rcfw_hal_fram_read(p, (uint16_t)(a + 8u + off), chunk, n)) {
            return false;
        }
        crc = rcfw_crc16(crc, chunk, n);
        off = (uint16_t)(off + n);
    }
    uint8_t c[2];
    if (!rcfw_hal_fram_read(p, (uint16_t)(a + 8u + s->len), c, 2)) {
        return false;
    }
    if ((uint16_t)(c[0] | (c[1] << 8)) != crc) {
        return false;
    }
    *seq = (uint32_t)hdr[4] | ((uint32_t)hdr[5] << 8) | ((uint32_t)hdr[6] << 16) | ((uint32_t)hdr[7] << 24);
    return true;
}

bool rcfw_store_load(rcfw_store *s, struct rcfw_port *p, uint8_t *data)
{
    uint32_t seq0 = 0, seq1 = 0;
    bool v0 = slot_valid(s, p, 0, &seq0);
    bool v1 = slot_valid(s, p, 1, &seq1);
    if (!v0 && !v1) {
        s->current = 0xFFu;
        s->seq = 0;
        return false;
    }
    uint8_t pick;
    if (v0 && v1) {
        pick = (int32_t)(seq1 - seq0) > 0 ? 1u : 0u; /* wrap-safe "newer" */
    } else {
        pick = v0 ? 0u : 1u;
    }
    s->current = pick;
    s->seq = pick ? seq1 : seq0;
    return rcfw_hal_fram_read(p, (uint16_t)(s->base[pick] + 8u), data, s->len);
}

bool rcfw_store_save(rcfw_store *s, struct rcfw_port *p, const uint8_t *data)
{
    uint8_t slot = s->current == 0u ? 1u : 0u; /* the older (or invalid) slot */
    uint32_t seq = s->seq + 1u;
    uint8_t hdr[8] = {(uint8_t)s->magic, (uint8_t)(s->magic >> 8), (uint8_t)s->len, (uint8_t)(s->len >> 8),
                      (uint8_t)seq, (uint8_t)(seq >> 8), (uint8_t)(seq >> 16), (uint8_t)(seq >> 24)};
    uint16_t crc = rcfw_crc16(rcfw_crc16(0, hdr, 8), data, s->len);
    uint8_t c[2] = {(uint8_t)crc, (uint8_t)(crc >> 8)};
    uint16_t a = s->base[slot];
    /* Invalidate the magic first so a torn slot can never pass as a valid older record
     * with a stale-but-matching CRC; then data, CRC, and the header last. */
    static const uint8_t zero2[2] = {0, 0};
    if (!rcfw_hal_fram_write(p, a, zero2, 2) || !rcfw_hal_fram_write(p, (uint16_t)(a + 8u), data, s->len) ||
        !rcfw_hal_fram_write(p, (uint16_t)(a + 8u + s->len), c, 2) ||
        !rcfw_hal_fram_write(p, (uint16_t)(a + 2u), hdr + 2, 6) || !rcfw_hal_fram_write(p, a, hdr, 2)) {
        return false;
    }
    s->current = slot;
    s->seq = seq;
    return true;
}
