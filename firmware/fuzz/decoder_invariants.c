/* The receiver's invariants, checked on every fuzz input (libFuzzer run and the CTest corpus replays):
 * - the parser never holds more than RCFW_RX_MAX bytes and never expects more;
 * - a delivered frame is exactly the bytes on the wire from its header to its CRC: re-encoding its meaning gives those
 *   bytes back (nothing read past the frame, nothing skipped), and its parameters fit inside what was received;
 * - frames delivered never need more bytes than were fed;
 * - after an error the parser is idle, or restarted at the header that interrupted the frame. */
#include "decoder_invariants.h"

#include <stdio.h>
#include <string.h>

#include "rcfw/frame.h"

#define MIN_FRAME 10u /* header 4, ID, LEN 2, instruction, CRC 2 */

static void fail(const char *what, size_t at)
{
    fprintf(stderr, "decoder invariant broken at input byte %zu: %s\n", at, what);
    __builtin_trap();
}

void rcfw_check_decoder_invariants(const uint8_t *data, size_t size)
{
    static rcfw_parser p;
    static uint8_t body[RCFW_RX_MAX];
    static uint8_t again[RCFW_RX_MAX + 8];
    rcfw_parser_reset(&p);
    size_t start = 0;
    size_t frames = 0;
    for (size_t i = 0; i < size; i++) {
        rcfw_rx_result r = rcfw_parser_feed(&p, data[i]);
        if (p.pos > RCFW_RX_MAX || p.need > RCFW_RX_MAX) {
            fail("buffer bound", i);
        }
        if (p.in_frame && p.pos == 0u) {
            start = i - 3u; /* a header (FF FF FD 00) ended here */
        }
        if (r == RCFW_RX_FRAME) {
            frames++;
            size_t wire = i - start + 1u;
            if (p.in_frame || wire != 4u + p.need || p.params != p.buf + 4 || (size_t)p.plen + 1u > (size_t)p.need - 5u) {
                fail("frame bounds", i);
            }
            body[0] = p.inst;
            memcpy(body + 1, p.params, p.plen);
            uint16_t n = rcfw_frame_build(again, sizeof again, p.id, body, (uint16_t)(p.plen + 1u));
            if (n != wire || memcmp(again, data + start, wire) != 0) {
                fail("re-encoded frame differs from the wire bytes", i);
            }
        } else if (r < 0) {
            int restarted = p.in_frame && p.pos == 0u && p.need == 3u;
            if (p.in_frame && !restarted) {
                fail("parser not reset after an error", i);
            }
        }
    }
    if (frames * MIN_FRAME > size) {
        fail("more frames than bytes", size);
    }
}
