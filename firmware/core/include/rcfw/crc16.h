#ifndef RCFW_CRC16_H
#define RCFW_CRC16_H
#include <stddef.h>
#include <stdint.h>
/* Dynamixel Protocol 2.0 CRC-16: poly 0x8005, init 0, MSB first, no reflection, no xorout
 * (CRC-16/BUYPASS). Pass 0 as crc for a new computation; chain for pieces. */
uint16_t rcfw_crc16(uint16_t crc, const uint8_t *data, size_t len);
#endif
