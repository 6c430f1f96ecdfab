/* Reliable stream throughput and retransmissions at 0%, 10% and 30% loss over the
 * in-process link with a virtual clock (./touchline footprint prints it). One side sends
 * 100 kB in 1000-byte segments; the link delays each datagram by 2 ms (a Wi-Fi hop and
 * the module's serial line) and, in the second table, also duplicates and reorders. */
#include <stdio.h>
#include "lossy_link.h"

static link_pkt storage[LINK_MAX_PKTS];
static lossy_link L;
static size_t received;
static void count(void *ctx, const uint8_t *p, uint16_t n) { (void)ctx; (void)p; received += n; }

static void run(int drop, int dup, int reorder)
{
    static uint8_t data[1000];
    const size_t total = 100000;
    size_t sent = 0;
    received = 0;
    link_init(&L, storage, drop, dup, reorder, 777u + (uint32_t)drop, count, NULL, count, NULL);
    L.base_delay_ms = 2;
    L.end[0].rto_ms = L.end[1].rto_ms = 20;
    while (received < total && L.now < 3600000u) {
        if (sent < total && rs_can_send(&L.end[0]) && rs_send(&L.end[0], data, sizeof data, L.now)) sent += sizeof data;
        link_step(&L);
    }
    printf("  %3d%%  %3d%%  %3d%%   %8.1f kB/s  %6.1f segments/s  %5u retransmissions (%.0f%% of %u segments)\n",
           drop, dup, reorder, (double)received / (double)L.now, (double)L.end[1].stats.delivered * 1000.0 / L.now,
           L.end[0].stats.retransmissions,
           100.0 * L.end[0].stats.retransmissions / (double)L.end[0].stats.data_sent, L.end[0].stats.data_sent);
}

int main(void)
{
    printf("Reliable stream (stop-and-wait, seq 0..20), 100 kB in 1000-byte segments,\n"
           "2 ms one-way delay, retransmission timeout 20 ms, virtual clock\n");
    printf("  drop   dup reorder  throughput\n");
    run(0, 0, 0);
    run(10, 0, 0);
    run(30, 0, 0);
    run(10, 10, 10);
    run(30, 30, 30);
    return 0;
}
