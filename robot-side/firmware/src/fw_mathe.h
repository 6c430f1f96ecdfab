/* The thesis' "Mathe" test on the reliable stream. Both sides send random operands 1..7
 * at the same time; each side folds the operands it SENDS, and separately the operands it
 * RECEIVES, into a running result, alternately adding and multiplying (uint32, wraps):
 *   r = 0; r = r + o1; r = r * o2; r = r + o3; r = r * o4; ...
 * After its last operand each side sends its result and operand count; the peer compares
 * them with what it computed from the operands it received. Any loss, duplicate or
 * reordering that slipped through the stream shows up as a mismatch.
 *
 * Messages (ASCII, one per stream segment, no terminator):
 *   "OP <n>"                 n = 1..7
 *   "END <result> <count>"   decimal, result as unsigned 32-bit */
#ifndef FW_MATHE_H
#define FW_MATHE_H

#include <stdbool.h>
#include <stdint.h>
#include "fw_reliable.h"

typedef struct {
    uint32_t total;          /* operands to send */
    uint32_t sent;           /* operands handed to the stream */
    uint32_t sent_result;
    uint32_t recv_count;
    uint32_t recv_result;
    uint32_t peer_count;     /* from the peer's END */
    uint32_t peer_result;
    bool end_sent;
    bool end_acked;
    bool peer_end;
    bool malformed;          /* a message that is neither OP nor END arrived */
    uint32_t rng;
    uint8_t msg[32];         /* the segment in flight (stream keeps a pointer to it) */
} mathe_game;

void mathe_init(mathe_game *g, uint32_t operands, uint32_t seed);
uint32_t mathe_fold(uint32_t result, uint32_t index, uint32_t operand); /* index is 1-based */
/* Sends the next operand or the END message when the stream is free. */
void mathe_poll(mathe_game *g, rs_stream *s, uint32_t now);
void mathe_receive(mathe_game *g, const uint8_t *p, uint16_t n);
bool mathe_done(const mathe_game *g);
bool mathe_agrees(const mathe_game *g);

#endif
