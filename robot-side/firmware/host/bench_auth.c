/* Verification cost per datagram for footprint.sh (tools/auth_cost.py): bench_loop() checks N
 * datagrams of the console (a 30-byte option request and a 200-byte one, each with its
 * 32-byte trailer), tagged beforehand with increasing counters; callgrind counts only
 * bench_loop. usage: fw_auth_bench PAYLOAD_BYTES N */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fw_auth.h"

static fw_team_key g_key;
static uint8_t *g_data;
static uint16_t g_len;
static unsigned g_accepted;

void bench_loop(fw_auth_state *s, unsigned n);
void bench_loop(fw_auth_state *s, unsigned n)
{
    unsigned i;
    for (i = 0; i < n; i++) {
        uint16_t payload;
        if (fw_auth_check(s, FW_AUTH_DIR_CONSOLE, 3, g_data + (size_t)i * g_len, g_len, &payload) == FW_AUTH_OK) {
            g_accepted++;
        }
    }
}

int main(int argc, char **argv)
{
    unsigned n, i;
    uint16_t payload_bytes;
    fw_auth_state s;
    if (argc != 3) {
        fprintf(stderr, "usage: fw_auth_bench PAYLOAD_BYTES N\n");
        return 2;
    }
    payload_bytes = (uint16_t)atoi(argv[1]);
    n = (unsigned)atoi(argv[2]);
    for (i = 0; i < 32; i++) g_key.key[i] = (uint8_t)(i * 13 + 5);
    g_len = (uint16_t)(payload_bytes + FW_AUTH_TRAILER);
    g_data = malloc((size_t)n * g_len);
    if (g_data == NULL) return 1;
    for (i = 0; i < n; i++) {
        uint8_t *d = g_data + (size_t)i * g_len;
        memset(d, (int)(i & 0x7f), payload_bytes);
        fw_auth_append(&g_key, FW_AUTH_DIR_CONSOLE, 3, 0, 1000u + i, d, payload_bytes, g_len);
    }
    fw_auth_init(&s, &g_key, 0);
    bench_loop(&s, n);
    printf("%u of %u datagrams of %u bytes accepted\n", g_accepted, n, (unsigned)g_len);
    free(g_data);
    return g_accepted == n ? 0 : 1;
}
