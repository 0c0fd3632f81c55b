/* Power-fail-safe record store in FRAM: two slots, each
 *   magic u16 | len u16 | seq u32 | data[len] | crc16 (Dynamixel CRC over the 8+len bytes before it)
 * Load picks the valid slot with the newest seq; save writes seq+1 into the *other* (older
 * or invalid) slot, so a cut at any byte leaves the previous record intact. */
#ifndef RCFW_STORE_H
#define RCFW_STORE_H
#include <stdbool.h>
#include <stdint.h>

struct rcfw_port;

typedef struct {
    uint16_t base[2];
    uint16_t magic;
    uint16_t len;
    uint32_t seq;     /* seq of the newest valid slot */
    uint8_t current;  /* slot holding it, 0xFF = none valid */
} rcfw_store;

void rcfw_store_init(rcfw_store *s, uint16_t base0, uint16_t base1, uint16_t magic, uint16_t len);
/* Load the newest valid record into data (len bytes). Returns false if neither slot is valid. */
bool rcfw_store_load(rcfw_store *s, struct rcfw_port *p, uint8_t *data);
/* Save data as a new record. Returns false on a FRAM error. */
bool rcfw_store_save(rcfw_store *s, struct rcfw_port *p, const uint8_t *data);
#define RCFW_STORE_OVERHEAD 10u       /* bytes of a slot beyond the data */
#define RCFW_STORE_WRITE_OVERHEAD 12u /* bytes written by one save beyond the data (magic twice) */
#endif
