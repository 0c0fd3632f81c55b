/* CRC, stuffing, framing and the shared test vectors. */
#include <stdlib.h>

#include "rcfw/crc16.h"
#include "rcfw/frame.h"
#include "test_vectors_gen.h"
#include "tf.h"

static void crc_published_examples(void)
{
    /* ROBOTIS e-Manual: ping ID 1 -> CRC 0x4E19 (bytes 19 4E) */
    const uint8_t ping[] = {0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x03, 0x00, 0x01};
    CHECK_EQ(rcfw_crc16(0, ping, sizeof ping), 0x4E19);
    /* chaining equals one pass */
    CHECK_EQ(rcfw_crc16(rcfw_crc16(0, ping, 3), ping + 3, 5), 0x4E19);
    /* CRC-16/BUYPASS check value */
    CHECK_EQ(rcfw_crc16(0, (const uint8_t *)"123456789", 9), 0xFEE8);
    for (int i = 0; i < TV_COUNT; i++) {
        const tv_vector *v = &tv_vectors[i];
        if (!v->valid) {
            continue;
        }
        uint16_t c = rcfw_crc16(0, v->frame, v->frame_len - 2u);
        CHECK_EQ(c, v->frame[v->frame_len - 2] | (v->frame[v->frame_len - 1] << 8));
    }
}

static void stuffing_round_trips(void)
{
    uint8_t src[64], st[128];
    /* runs of FF FF FD, FD tails, patterns at the boundaries */
    const uint8_t pats[][8] = {{0xFF, 0xFF, 0xFD}, {0xFF, 0xFF, 0xFD, 0xFD}, {0xFF, 0xFF, 0xFD, 0xFF, 0xFF, 0xFD},
                               {0xFF, 0xFF, 0xFF, 0xFD, 0xFD, 0xFD}, {0xFD, 0xFF, 0xFF, 0xFD, 0x00}};
    const int lens[] = {3, 4, 6, 6, 5};
    for (int p = 0; p < 5; p++) {
        uint16_t s = rcfw_stuff(pats[p], (uint16_t)lens[p], st, sizeof st);
        CHECK(s > lens[p]);
        int32_t u = rcfw_unstuff(st, s);
        CHECK_EQ(u, lens[p]);
        CHECK(memcmp(st, pats[p], (size_t)lens[p]) == 0);
    }
    /* FF FF FD x N */
    for (int n = 1; n <= 20; n++) {
        for (int i = 0; i < 3 * n; i++) {
            src[i] = (uint8_t)((i % 3) == 2 ? 0xFD : 0xFF);
        }
        uint16_t s = rcfw_stuff(src, (uint16_t)(3 * n), st, sizeof st);
        CHECK_EQ(s, 4 * n);
        CHECK_EQ(rcfw_unstuff(st, s), 3 * n);
        CHECK(memcmp(st, src, (size_t)(3 * n)) == 0);
    }
    /* random bytes from a small alphabet */
    srand(1);
    for (int it = 0; it < 20000; it++) {
        int n = rand() % 40;
        static const uint8_t alpha[] = {0xFF, 0xFD, 0x00, 0x55};
        for (int i = 0; i < n; i++) {
            src[i] = alpha[rand() % 4];
        }
        uint16_t s = rcfw_stuff(src, (uint16_t)n, st, sizeof st);
        CHECK(n == 0 || s >= n);
        /* the stuffed body never contains a header */
        for (int i = 0; i + 3 < s; i++) {
            CHECK(!(st[i] == 0xFF && st[i + 1] == 0xFF && st[i + 2] == 0xFD && st[i + 3] == 0x00));
        }
        int32_t u = rcfw_unstuff(st, s);
        CHECK_EQ(u, n);
        CHECK(memcmp(st, src, (size_t)n) == 0);
    }
    /* capacity too small */
    const uint8_t p3[] = {0xFF, 0xFF, 0xFD};
    CHECK_EQ(rcfw_stuff(p3, 3, st, 3), 0);
    /* unstuffed FF FF FD is rejected */
    uint8_t bad[] = {0x03, 0xFF, 0xFF, 0xFD, 0x00};
    CHECK_EQ(rcfw_unstuff(bad, sizeof bad), -1);
}

static int parse_all(rcfw_parser *p, const uint8_t *b, int n, int *frames)
{
    int dropped = 0;
    *frames = 0;
    for (int i = 0; i < n; i++) {
        rcfw_rx_result r = rcfw_parser_feed(p, b[i]);
        if (r == RCFW_RX_FRAME) {
            (*frames)++;
        } else if (r < 0) {
            dropped++;
        }
    }
    return dropped;
}

static void vectors_decode_and_encode(void)
{
    static rcfw_parser p;
    for (int i = 0; i < TV_COUNT; i++) {
        const tv_vector *v = &tv_vectors[i];
        rcfw_parser_reset(&p);
        int frames = 0;
        (void)parse_all(&p, v->frame, v->frame_len, &frames);
        if (!v->valid) {
            CHECK_EQ(frames, 0);
            if (frames) {
                fprintf(stderr, "  invalid vector decoded: %s\n", v->name);
            }
            continue;
        }
        CHECK_EQ(frames, 1);
        if (frames != 1) {
            fprintf(stderr, "  vector not decoded: %s\n", v->name);
            continue;
        }
        CHECK_EQ(p.id, v->id);
        CHECK_EQ(p.inst, v->instruction);
        if (v->kind == 1) {
            CHECK_EQ(p.plen, v->params_len + 1);
            CHECK_EQ(p.params[0], v->error);
            CHECK(memcmp(p.params + 1, v->params, v->params_len) == 0);
        } else {
            CHECK_EQ(p.plen, v->params_len);
            CHECK(memcmp(p.params, v->params, v->params_len) == 0);
        }
        /* encoder reproduces the exact bytes */
        uint8_t body[600], out[900];
        body[0] = (uint8_t)v->instruction;
        uint16_t bl = 1;
        if (v->kind == 1) {
            body[bl++] = (uint8_t)v->error;
        }
        memcpy(body + bl, v->params, v->params_len);
        bl = (uint16_t)(bl + v->params_len);
        uint16_t n = rcfw_frame_build(out, sizeof out, (uint8_t)v->id, body, bl);
        CHECK_EQ(n, v->frame_len);
        CHECK(memcmp(out, v->frame, v->frame_len) == 0);
    }
}

static void parser_resync_and_garbage(void)
{
    static rcfw_parser p;
    const uint8_t ping[] = {0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x03, 0x00, 0x01, 0x19, 0x4E};
    uint8_t buf[64];
    int frames;
    /* garbage, then a truncated frame immediately followed by a good one */
    size_t n = 0;
    const uint8_t junk[] = {0x00, 0xFF, 0xFD, 0xFF, 0xFF, 0x12};
    memcpy(buf + n, junk, sizeof junk);
    n += sizeof junk;
    const uint8_t trunc[] = {0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x09, 0x00, 0x03, 0x74};
    memcpy(buf + n, trunc, sizeof trunc);
    n += sizeof trunc;
    memcpy(buf + n, ping, sizeof ping);
    n += sizeof ping;
    rcfw_parser_reset(&p);
    int dropped = parse_all(&p, buf, (int)n, &frames);
    CHECK_EQ(frames, 1);
    CHECK(dropped >= 1);
    /* every single-bit corruption of a ping is dropped */
    for (int i = 0; i < (int)sizeof ping; i++) {
        for (int b = 0; b < 8; b++) {
            memcpy(buf, ping, sizeof ping);
            buf[i] ^= (uint8_t)(1u << b);
            rcfw_parser_reset(&p);
            (void)parse_all(&p, buf, sizeof ping, &frames);
            CHECK_EQ(frames, 0);
        }
    }
    /* back-to-back frames */
    memcpy(buf, ping, sizeof ping);
    memcpy(buf + sizeof ping, ping, sizeof ping);
    rcfw_parser_reset(&p);
    (void)parse_all(&p, buf, 2 * sizeof ping, &frames);
    CHECK_EQ(frames, 2);
}

int main(void)
{
    TF_RUN(crc_published_examples);
    TF_RUN(stuffing_round_trips);
    TF_RUN(vectors_decode_and_encode);
    TF_RUN(parser_resync_and_garbage);
    TF_END();
}
