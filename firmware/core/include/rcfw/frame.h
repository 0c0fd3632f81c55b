/* Dynamixel Protocol 2.0 framing: FF FF FD 00 | ID | LEN_L LEN_H | INST | PARAMS | CRC_L CRC_H
 * LEN = bytes after the length field (instruction + stuffed params + 2 CRC bytes).
 * CRC covers everything from the first FF to the last param (stuffed form).
 * Stuffing: in INST+PARAMS every FF FF FD is followed by an extra FD. */
#ifndef RCFW_FRAME_H
#define RCFW_FRAME_H
#include <stdbool.h>
#include <stdint.h>

#define RCFW_ID_BROADCAST 0xFEu
#define RCFW_INST_PING 0x01u
#define RCFW_INST_READ 0x02u
#define RCFW_INST_WRITE 0x03u
#define RCFW_INST_REG_WRITE 0x04u
#define RCFW_INST_ACTION 0x05u
#define RCFW_INST_FACTORY_RESET 0x06u
#define RCFW_INST_REBOOT 0x08u
#define RCFW_INST_CLEAR 0x10u
#define RCFW_INST_STATUS 0x55u
#define RCFW_INST_SYNC_READ 0x82u
#define RCFW_INST_SYNC_WRITE 0x83u
#define RCFW_INST_FAST_SYNC_READ 0x8Au
#define RCFW_INST_BULK_READ 0x92u
#define RCFW_INST_BULK_WRITE 0x93u
#define RCFW_INST_FAST_BULK_READ 0x9Au

/* status error byte (low 7 bits = Dynamixel error number, bit 7 = hardware alert) */
#define RCFW_ERR_RESULT_FAIL 0x01u
#define RCFW_ERR_INSTRUCTION 0x02u
#define RCFW_ERR_CRC 0x03u
#define RCFW_ERR_DATA_RANGE 0x04u
#define RCFW_ERR_DATA_LENGTH 0x05u
#define RCFW_ERR_DATA_LIMIT 0x06u
#define RCFW_ERR_ACCESS 0x07u
#define RCFW_ERR_ALERT 0x80u

#ifndef RCFW_RX_MAX
#define RCFW_RX_MAX 1024u /* raw bytes from ID to CRC inclusive */
#endif

/* Stuff src (n bytes of INST+PARAMS) into dst; returns stuffed length or 0 if cap is short. */
uint16_t rcfw_stuff(const uint8_t *src, uint16_t n, uint8_t *dst, uint16_t cap);
/* Remove stuffing in place; returns the new length, or -1 if an FF FF FD is not followed
 * by the stuffing FD (a header or garbage inside the body). */
int32_t rcfw_unstuff(uint8_t *buf, uint16_t n);

/* Build a whole frame (header, stuffing, CRC). body = INST followed by params (unstuffed).
 * Returns total length or 0 if it does not fit in cap. */
uint16_t rcfw_frame_build(uint8_t *out, uint16_t cap, uint8_t id, const uint8_t *body, uint16_t body_len);

typedef enum {
    RCFW_RX_MORE = 0,     /* need more bytes */
    RCFW_RX_FRAME = 1,    /* a valid frame is ready in the parser */
    RCFW_RX_BAD_CRC = -1, /* dropped */
    RCFW_RX_BAD_LEN = -2, /* length too short or too long: dropped */
    RCFW_RX_BAD_STUFF = -3
} rcfw_rx_result;

typedef struct {
    uint8_t buf[RCFW_RX_MAX]; /* ID, LEN_L, LEN_H, INST, params..., CRC_L, CRC_H */
    uint16_t pos;             /* bytes in buf */
    uint16_t need;            /* total bytes expected in buf (3 + LEN) */
    uint32_t window;          /* last 4 raw bytes */
    uint8_t in_frame;
    /* valid after RCFW_RX_FRAME */
    uint8_t id;
    uint8_t inst;
    const uint8_t *params;
    uint16_t plen;
} rcfw_parser;

void rcfw_parser_reset(rcfw_parser *p);
/* Feed one byte. Resynchronises on a new header seen inside a frame. */
rcfw_rx_result rcfw_parser_feed(rcfw_parser *p, uint8_t byte);

#endif
