/* libFuzzer target: arbitrary serial bytes from the "module" into the GS1500M parser and
 * driver. ASan/UBSan catch any read or write past a buffer. The first input byte picks
 * the size of the datagram buffer so small buffers are exercised too. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "fw_gs1500.h"

void fw_log(const char *what, const char *detail, int32_t value);
void fw_log(const char *what, const char *detail, int32_t value) { (void)what; (void)detail; (void)value; }

static const uint8_t *g_in;
static size_t g_len, g_pos;

static int in_read(void *ctx, uint8_t *buf, uint16_t cap)
{
    size_t n = g_len - g_pos;
    (void)ctx;
    if (n > 7) n = 7;
    if (n > cap) n = cap;
    memcpy(buf, g_in + g_pos, n);
    g_pos += n;
    return (int)n;
}

static bool out_write(void *ctx, const uint8_t *buf, uint16_t n)
{
    (void)ctx;
    (void)buf;
    (void)n;
    return true;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static gs_module m;
    gs_serial serial = {in_read, out_write, NULL};
    gs_config cfg = {"fuzz", {127, 0, 0, 1}, 11011, 3838};
    uint16_t cap, len;
    uint8_t *buf;
    wlan_peer from;
    uint32_t now = 0;
    gs_parser p;
    size_t i;
    if (size < 1) return 0;
    cap = (uint16_t)(1u + data[0] * 6u); /* 1..1531 */
    buf = malloc(cap);                   /* exact size: ASan sees any overrun */
    /* the bare parser */
    gs_parser_init(&p, buf, cap);
    for (i = 1; i < size; i++) {
        if (gs_parser_push(&p, data[i]) == GS_EV_LINE) {
            char line[GS_LINE_RING + 1];
            (void)gs_parser_line(&p, line, sizeof line);
        }
    }
    /* the driver: start-up (the input may contain OK/CONNECT lines) and receiving */
    g_in = data + 1;
    g_len = size - 1;
    g_pos = 0;
    gs_module_init(&m, &serial, &cfg);
    while (g_pos < g_len) {
        if (!m.driver.poll_init(m.driver.ctx, now += 400)) continue;
        len = cap;
        if (m.driver.recv(m.driver.ctx, buf, cap, &len, &from) && len > cap) abort();
    }
    free(buf);
    return 0;
}
