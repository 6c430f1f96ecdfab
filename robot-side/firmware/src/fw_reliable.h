/* Reliable stream: a derivative of the alternating-bit protocol sharing the robot's UDP
 * port. Every segment starts with a 2-byte header: sequence number (0..modulus-1, wraps;
 * modulus <= 42 so the first byte never looks like 0x00 0x2A or 'R'), then the ack = the
 * last sequence number received in order from the peer. A segment of exactly 2 bytes is a
 * pure ack; data segments carry an ack too (piggy-backing).
 *
 * Stop-and-wait: one data segment in flight; retransmitted every rto_ms until acked.
 * Duplicates and out-of-order segments are acknowledged and dropped. When idle, a pure
 * ack goes out every keepalive_ms (keep-alive, and recovery from a lost ack).
 * Message boundaries are kept: one rs_send() = one segment = one deliver() call.
 *
 * Zero copy: rs_send() keeps a pointer to the caller's payload, which must stay valid
 * until rs_can_send() is true again; the output callback gets header and payload
 * separately so no 1400-byte segment buffer is needed. */
#ifndef FW_RELIABLE_H
#define FW_RELIABLE_H

#include <stdint.h>

#define RS_DEFAULT_MODULUS 21u   /* sequence numbers 0..20, as in the reference */
#define RS_MAX_MODULUS 42u
#define RS_MAX_PAYLOAD (1400u - 2u)

typedef int (*rs_output_fn)(void *ctx, const uint8_t hdr[2], const uint8_t *payload, uint16_t n);
typedef void (*rs_deliver_fn)(void *ctx, const uint8_t *payload, uint16_t n);

typedef struct {
    uint32_t data_sent;        /* data segments sent, first transmissions */
    uint32_t retransmissions;
    uint32_t acks_sent;        /* pure acks (incl. keep-alives) */
    uint32_t delivered;        /* in-order data segments handed to the application */
    uint32_t duplicates;       /* data segments acknowledged and dropped */
    uint32_t invalid;          /* segments with seq or ack out of range, or too short */
} rs_stats;

typedef struct {
    uint8_t modulus;
    uint8_t tx_seq;        /* sequence number of the segment in flight / the next one */
    uint8_t rx_last;       /* last in-order sequence number received (our ack) */
    uint8_t in_flight;
    uint8_t ack_due;       /* received data not yet acknowledged */
    const uint8_t *tx_payload;
    uint16_t tx_len;
    uint32_t tx_sent_at;
    uint32_t last_out_at;
    uint32_t rto_ms;
    uint32_t keepalive_ms;
    rs_output_fn output;
    rs_deliver_fn deliver;
    void *ctx;
    rs_stats stats;
} rs_stream;

void rs_init(rs_stream *s, uint8_t modulus, uint32_t rto_ms, uint32_t keepalive_ms,
             rs_output_fn output, rs_deliver_fn deliver, void *ctx, uint32_t now);
int rs_can_send(const rs_stream *s);
/* 1 = accepted (sent now), 0 = busy (a segment is in flight) or bad size. */
int rs_send(rs_stream *s, const uint8_t *payload, uint16_t n, uint32_t now);
void rs_input(rs_stream *s, const uint8_t *seg, uint16_t n, uint32_t now);
/* Retransmissions, delayed acks and keep-alive acks; call often. */
void rs_poll(rs_stream *s, uint32_t now);

#endif
