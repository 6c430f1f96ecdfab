/* An in-process lossy link for the reliable stream: two rs_stream endpoints, a virtual
 * clock, and a channel that drops, duplicates and delays (so reorders) segments. */
#ifndef LOSSY_LINK_H
#define LOSSY_LINK_H

#include <stdint.h>
#include <string.h>
#include "fw_reliable.h"

#define LINK_MAX_PKTS 4096
#define LINK_MAX_SEG 1400

typedef struct {
    uint32_t due;
    int to;          /* 0 = A, 1 = B */
    uint16_t n;
    uint8_t data[LINK_MAX_SEG];
} link_pkt;

typedef struct {
    rs_stream end[2];
    link_pkt *pkts;  /* LINK_MAX_PKTS */
    int count;
    uint32_t now;
    uint32_t rng;
    int drop_pct, dup_pct, reorder_pct;
    uint32_t base_delay_ms;
    uint32_t sent, dropped, duplicated, reordered;
    rs_deliver_fn deliver[2];
    void *deliver_ctx[2];
} lossy_link;

static uint32_t link_rand(lossy_link *l)
{
    l->rng ^= l->rng << 13;
    l->rng ^= l->rng >> 17;
    l->rng ^= l->rng << 5;
    return l->rng;
}

static void link_put(lossy_link *l, int to, const uint8_t hdr[2], const uint8_t *p, uint16_t n, uint32_t extra)
{
    link_pkt *k;
    if (l->count == LINK_MAX_PKTS) return; /* a full "network" loses packets too */
    k = &l->pkts[l->count++];
    k->to = to;
    k->n = (uint16_t)(n + 2);
    k->data[0] = hdr[0];
    k->data[1] = hdr[1];
    if (n) memcpy(k->data + 2, p, n);
    k->due = l->now + l->base_delay_ms + extra;
}

static int link_output(lossy_link *l, int from, const uint8_t hdr[2], const uint8_t *p, uint16_t n)
{
    uint32_t extra = 0;
    l->sent++;
    if ((int)(link_rand(l) % 100u) < l->drop_pct) {
        l->dropped++;
        return 1;
    }
    if ((int)(link_rand(l) % 100u) < l->reorder_pct) {
        extra = 2u + link_rand(l) % 25u; /* later segments overtake this one */
        l->reordered++;
    }
    link_put(l, 1 - from, hdr, p, n, extra);
    if ((int)(link_rand(l) % 100u) < l->dup_pct) {
        l->duplicated++;
        link_put(l, 1 - from, hdr, p, n, link_rand(l) % 20u);
    }
    return 1;
}

static lossy_link *g_link;
static int out_a(void *ctx, const uint8_t hdr[2], const uint8_t *p, uint16_t n) { (void)ctx; return link_output(g_link, 0, hdr, p, n); }
static int out_b(void *ctx, const uint8_t hdr[2], const uint8_t *p, uint16_t n) { (void)ctx; return link_output(g_link, 1, hdr, p, n); }

static void link_init(lossy_link *l, link_pkt *storage, int drop, int dup, int reorder, uint32_t seed,
                      rs_deliver_fn da, void *ca, rs_deliver_fn db, void *cb)
{
    memset(l, 0, sizeof *l);
    l->pkts = storage;
    l->rng = seed ? seed : 1u;
    l->drop_pct = drop;
    l->dup_pct = dup;
    l->reorder_pct = reorder;
    l->base_delay_ms = 1;
    g_link = l;
    rs_init(&l->end[0], RS_DEFAULT_MODULUS, 20, 50, out_a, da, ca, 0);
    rs_init(&l->end[1], RS_DEFAULT_MODULUS, 20, 50, out_b, db, cb, 0);
}

/* Advances the virtual clock by 1 ms: delivers what is due, polls both ends. */
static void link_step(lossy_link *l)
{
    int i = 0;
    l->now++;
    while (i < l->count) {
        if ((int32_t)(l->now - l->pkts[i].due) >= 0) {
            link_pkt k = l->pkts[i];
            l->pkts[i] = l->pkts[--l->count];
            rs_input(&l->end[k.to], k.data, k.n, l->now);
        } else {
            i++;
        }
    }
    rs_poll(&l->end[0], l->now);
    rs_poll(&l->end[1], l->now);
}

#endif
