#include "fw_reliable.h"

static void emit(rs_stream *s, const uint8_t *payload, uint16_t n, uint32_t now)
{
    uint8_t hdr[2];
    hdr[0] = s->tx_seq;
    hdr[1] = s->rx_last;
    (void)s->output(s->ctx, hdr, payload, n);
    s->ack_due = 0; /* every segment carries the ack */
    s->last_out_at = now;
}

void rs_init(rs_stream *s, uint8_t modulus, uint32_t rto_ms, uint32_t keepalive_ms,
             rs_output_fn output, rs_deliver_fn deliver, void *ctx, uint32_t now)
{
    if (modulus < 2 || modulus > RS_MAX_MODULUS) modulus = RS_DEFAULT_MODULUS;
    s->modulus = modulus;
    s->tx_seq = 0;
    s->rx_last = (uint8_t)(modulus - 1); /* "received the one before 0": expect 0 next */
    s->in_flight = 0;
    s->ack_due = 0;
    s->tx_payload = 0;
    s->tx_len = 0;
    s->tx_sent_at = now;
    s->last_out_at = now;
    s->rto_ms = rto_ms;
    s->keepalive_ms = keepalive_ms;
    s->output = output;
    s->deliver = deliver;
    s->ctx = ctx;
    s->stats.data_sent = s->stats.retransmissions = s->stats.acks_sent = 0;
    s->stats.delivered = s->stats.duplicates = s->stats.invalid = 0;
}

int rs_can_send(const rs_stream *s) { return !s->in_flight; }

int rs_send(rs_stream *s, const uint8_t *payload, uint16_t n, uint32_t now)
{
    if (s->in_flight || n == 0 || n > RS_MAX_PAYLOAD) return 0;
    s->tx_payload = payload;
    s->tx_len = n;
    s->in_flight = 1;
    s->tx_sent_at = now;
    s->stats.data_sent++;
    emit(s, payload, n, now);
    return 1;
}

void rs_input(rs_stream *s, const uint8_t *seg, uint16_t n, uint32_t now)
{
    uint8_t seq, ack;
    (void)now;
    if (n < 2 || seg[0] >= s->modulus || seg[1] >= s->modulus) {
        s->stats.invalid++;
        return;
    }
    seq = seg[0];
    ack = seg[1];
    if (s->in_flight && ack == s->tx_seq) {
        s->in_flight = 0;
        s->tx_payload = 0;
        s->tx_seq = (uint8_t)((s->tx_seq + 1) % s->modulus);
    }
    if (n == 2) return; /* pure ack: its sequence byte carries no meaning */
    if (seq == (uint8_t)((s->rx_last + 1) % s->modulus)) {
        s->rx_last = seq;
        s->stats.delivered++;
        if (s->deliver) s->deliver(s->ctx, seg + 2, (uint16_t)(n - 2));
    } else {
        s->stats.duplicates++;
    }
    s->ack_due = 1; /* answered by the next data segment or, failing that, in rs_poll */
}

void rs_poll(rs_stream *s, uint32_t now)
{
    if (s->in_flight && (uint32_t)(now - s->tx_sent_at) >= s->rto_ms) {
        s->tx_sent_at = now;
        s->stats.retransmissions++;
        emit(s, s->tx_payload, s->tx_len, now);
        return;
    }
    if (s->ack_due || (!s->in_flight && (uint32_t)(now - s->last_out_at) >= s->keepalive_ms)) {
        uint8_t prev = (uint8_t)((s->tx_seq + s->modulus - 1) % s->modulus);
        uint8_t hdr[2];
        hdr[0] = s->in_flight ? s->tx_seq : prev; /* ignored by the peer */
        hdr[1] = s->rx_last;
        (void)s->output(s->ctx, hdr, 0, 0);
        s->stats.acks_sent++;
        s->ack_due = 0;
        s->last_out_at = now;
    }
}
