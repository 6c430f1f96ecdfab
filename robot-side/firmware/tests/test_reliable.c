/* The reliable stream over a lossy in-process link (>= 20% drop, duplication and
 * reordering): the thesis' "Lorem ipsum" test in both directions at once, and "Mathe". */
#include <stdio.h>
#include <string.h>
#include "fw_mathe.h"
#include "lossy_link.h"
#include "test_util.h"

static link_pkt storage[LINK_MAX_PKTS];
static lossy_link L;

typedef struct {
    uint8_t data[65536];
    size_t len;
    int overflow;
} sink;
static sink sink_a, sink_b;

static void to_sink(void *ctx, const uint8_t *p, uint16_t n)
{
    sink *s = ctx;
    if (s->len + n > sizeof s->data) {
        s->overflow = 1;
        return;
    }
    memcpy(s->data + s->len, p, n);
    s->len += n;
}

static const char *lorem =
    "Lorem ipsum dolor sit amet, consectetur adipiscing elit, sed do eiusmod tempor incididunt ut labore et "
    "dolore magna aliqua. Ut enim ad minim veniam, quis nostrud exercitation ullamco laboris nisi ut aliquip ex "
    "ea commodo consequat. Duis aute irure dolor in reprehenderit in voluptate velit esse cillum dolore eu "
    "fugiat nulla pariatur. Excepteur sint occaecat cupidatat non proident, sunt in culpa qui officia deserunt "
    "mollit anim id est laborum. ";

static size_t make_text(uint8_t *out, size_t n, int variant)
{
    size_t i, k = strlen(lorem);
    for (i = 0; i < n; i++) out[i] = (uint8_t)lorem[(i + (size_t)variant * 13u) % k];
    /* number the sentences so a reordered or repeated chunk cannot look right */
    for (i = 0; i + 8 < n; i += 97) {
        char tag[10];
        snprintf(tag, sizeof tag, "[%06zu]", i);
        memcpy(out + i, tag, 8);
    }
    return n;
}

static uint8_t text_a[20000], text_b[20000];

/* Returns virtual ms taken, or 0 on timeout. */
static uint32_t lorem_both_ways(int drop, int dup, int reorder, uint32_t seed, uint32_t limit_ms)
{
    size_t off_a = 0, off_b = 0, len_a = make_text(text_a, sizeof text_a, 1), len_b = make_text(text_b, 7000, 2);
    uint32_t chunk_rng = seed;
    memset(&sink_a, 0, sizeof sink_a);
    memset(&sink_b, 0, sizeof sink_b);
    link_init(&L, storage, drop, dup, reorder, seed, to_sink, &sink_a, to_sink, &sink_b);
    while (L.now < limit_ms) {
        if (off_a < len_a && rs_can_send(&L.end[0])) {
            size_t n;
            chunk_rng = chunk_rng * 1103515245u + 12345u;
            n = 1u + (chunk_rng >> 8) % 1000u;
            if (n > len_a - off_a) n = len_a - off_a;
            if (rs_send(&L.end[0], text_a + off_a, (uint16_t)n, L.now)) off_a += n;
        }
        if (off_b < len_b && rs_can_send(&L.end[1])) {
            size_t n = len_b - off_b < 300 ? len_b - off_b : 300;
            if (rs_send(&L.end[1], text_b + off_b, (uint16_t)n, L.now)) off_b += n;
        }
        link_step(&L);
        if (off_a == len_a && off_b == len_b && rs_can_send(&L.end[0]) && rs_can_send(&L.end[1])) break;
    }
    CHECK_EQ(sink_b.len, len_a);
    CHECK(memcmp(sink_b.data, text_a, len_a) == 0);
    CHECK_EQ(sink_a.len, len_b);
    CHECK(memcmp(sink_a.data, text_b, len_b) == 0);
    return L.now < limit_ms ? L.now : 0;
}

static mathe_game game_a, game_b;
static void to_game(void *ctx, const uint8_t *p, uint16_t n) { mathe_receive(ctx, p, n); }

static void mathe_under_loss(int drop, int dup, int reorder, uint32_t seed)
{
    link_init(&L, storage, drop, dup, reorder, seed, to_game, &game_a, to_game, &game_b);
    mathe_init(&game_a, 300, seed * 3u + 1u);
    mathe_init(&game_b, 250, seed * 7u + 5u);
    while (L.now < 600000u && !(mathe_done(&game_a) && mathe_done(&game_b))) {
        mathe_poll(&game_a, &L.end[0], L.now);
        mathe_poll(&game_b, &L.end[1], L.now);
        link_step(&L);
    }
    CHECK(mathe_done(&game_a));
    CHECK(mathe_done(&game_b));
    CHECK(mathe_agrees(&game_a));
    CHECK(mathe_agrees(&game_b));
    CHECK_EQ(game_a.peer_count, 250);
    CHECK_EQ(game_b.peer_count, 300);
    CHECK_EQ(game_b.recv_result, game_a.sent_result);
    CHECK_EQ(game_a.recv_result, game_b.sent_result);
}

static void test_protocol_details(void)
{
    /* out-of-range sequence or ack bytes are invalid; pure acks get no answer */
    static const uint8_t bad_seq[] = {21, 0, 'x'};
    static const uint8_t bad_ack[] = {0, 42, 'x'};
    static const uint8_t pure[] = {5, 20};
    static const uint8_t first[] = {0, 20, 'a'};
    link_init(&L, storage, 0, 0, 0, 1, to_sink, &sink_a, to_sink, &sink_b);
    memset(&sink_a, 0, sizeof sink_a);
    rs_input(&L.end[0], bad_seq, sizeof bad_seq, 0);
    rs_input(&L.end[0], bad_ack, sizeof bad_ack, 0);
    rs_input(&L.end[0], bad_ack, 1, 0);
    CHECK_EQ(L.end[0].stats.invalid, 3);
    rs_input(&L.end[0], pure, sizeof pure, 0);
    CHECK(!L.end[0].ack_due);
    rs_input(&L.end[0], first, sizeof first, 0);
    CHECK(L.end[0].ack_due);
    CHECK_EQ(sink_a.len, 1);
    rs_input(&L.end[0], first, sizeof first, 0); /* duplicate: acked, not delivered */
    CHECK_EQ(sink_a.len, 1);
    CHECK_EQ(L.end[0].stats.duplicates, 1);
    /* a data segment piggy-backs the ack: no separate pure ack goes out */
    {
        uint32_t acks = L.end[0].stats.acks_sent;
        CHECK(rs_send(&L.end[0], (const uint8_t *)"b", 1, 1));
        CHECK(!L.end[0].ack_due);
        CHECK(!rs_send(&L.end[0], (const uint8_t *)"c", 1, 1)); /* stop-and-wait */
        rs_poll(&L.end[0], 2);
        CHECK_EQ(L.end[0].stats.acks_sent, acks);
    }
    /* sequence numbers never reach 42: the first byte cannot look like 0x00 0x2A or 'R' */
    CHECK(RS_DEFAULT_MODULUS <= 42);
}

int main(void)
{
    test_protocol_details();
    CHECK(lorem_both_ways(0, 0, 0, 11, 100000) > 0);
    CHECK(lorem_both_ways(20, 20, 20, 12, 600000) > 0);
    CHECK(lorem_both_ways(30, 25, 30, 13, 900000) > 0);
    CHECK(L.dropped > 0 && L.duplicated > 0 && L.reordered > 0);
    mathe_under_loss(0, 0, 0, 21);
    mathe_under_loss(20, 20, 20, 22);
    mathe_under_loss(30, 30, 30, 23);
    TEST_DONE();
}
