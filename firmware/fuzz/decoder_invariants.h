#ifndef RCFW_DECODER_INVARIANTS_H
#define RCFW_DECODER_INVARIANTS_H
#include <stddef.h>
#include <stdint.h>

/* Feeds data to a fresh parser and traps on any broken receiver invariant (see decoder_invariants.c). */
void rcfw_check_decoder_invariants(const uint8_t *data, size_t size);

#endif
