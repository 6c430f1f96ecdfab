#include "fw_mathe.h"

static uint16_t put_uint(uint8_t *out, uint32_t v)
{
    uint8_t digits[10];
    uint16_t n = 0, i;
    do {
        digits[n++] = (uint8_t)('0' + v % 10u);
        v /= 10u;
    } while (v != 0);
    for (i = 0; i < n; i++) out[i] = digits[n - 1 - i];
    return n;
}

/* Parses a decimal number at *p; false if none or it overflows 32 bits. */
static bool get_uint(const uint8_t **p, const uint8_t *end, uint32_t *v)
{
    uint64_t acc = 0;
    const uint8_t *q = *p;
    if (q >= end || *q < '0' || *q > '9') return false;
    while (q < end && *q >= '0' && *q <= '9') {
        acc = acc * 10u + (uint64_t)(*q - '0');
        if (acc > 0xFFFFFFFFu) return false;
        q++;
    }
    *p = q;
    *v = (uint32_t)acc;
    return true;
}

static bool match(const uint8_t **p, const uint8_t *end, const char *word)
{
    const uint8_t *q = *p;
    while (*word != '\0') {
        if (q >= end || *q != (uint8_t)*word) return false;
        q++;
        word++;
    }
    *p = q;
    return true;
}

void mathe_init(mathe_game *g, uint32_t operands, uint32_t seed)
{
    g->total = operands;
    g->sent = g->sent_result = 0;
    g->recv_count = g->recv_result = 0;
    g->peer_count = g->peer_result = 0;
    g->end_sent = g->end_acked = g->peer_end = g->malformed = false;
    g->rng = seed ? seed : 1u;
}

uint32_t mathe_fold(uint32_t result, uint32_t index, uint32_t operand)
{
    return (index % 2u == 1u) ? result + operand : result * operand;
}

void mathe_poll(mathe_game *g, rs_stream *s, uint32_t now)
{
    uint16_t n;
    if (!rs_can_send(s)) return;
    if (g->end_sent) {
        g->end_acked = true;
        return;
    }
    if (g->sent < g->total) {
        uint32_t operand;
        g->rng ^= g->rng << 13;
        g->rng ^= g->rng >> 17;
        g->rng ^= g->rng << 5;
        operand = 1u + g->rng % 7u;
        g->msg[0] = 'O';
        g->msg[1] = 'P';
        g->msg[2] = ' ';
        n = (uint16_t)(3 + put_uint(g->msg + 3, operand));
        if (rs_send(s, g->msg, n, now)) {
            g->sent++;
            g->sent_result = mathe_fold(g->sent_result, g->sent, operand);
        }
        return;
    }
    g->msg[0] = 'E';
    g->msg[1] = 'N';
    g->msg[2] = 'D';
    g->msg[3] = ' ';
    n = 4;
    n = (uint16_t)(n + put_uint(g->msg + n, g->sent_result));
    g->msg[n++] = ' ';
    n = (uint16_t)(n + put_uint(g->msg + n, g->sent));
    if (rs_send(s, g->msg, n, now)) g->end_sent = true;
}

void mathe_receive(mathe_game *g, const uint8_t *p, uint16_t n)
{
    const uint8_t *end = p + n;
    uint32_t a, b;
    if (match(&p, end, "OP ") && get_uint(&p, end, &a) && p == end && a >= 1 && a <= 7) {
        g->recv_count++;
        g->recv_result = mathe_fold(g->recv_result, g->recv_count, a);
        return;
    }
    p = end - n;
    if (match(&p, end, "END ") && get_uint(&p, end, &a) && match(&p, end, " ") && get_uint(&p, end, &b) &&
        p == end) {
        g->peer_result = a;
        g->peer_count = b;
        g->peer_end = true;
        return;
    }
    g->malformed = true;
}

bool mathe_done(const mathe_game *g) { return g->end_acked && g->peer_end; }

bool mathe_agrees(const mathe_game *g)
{
    return g->peer_end && !g->malformed && g->peer_count == g->recv_count && g->peer_result == g->recv_result;
}
