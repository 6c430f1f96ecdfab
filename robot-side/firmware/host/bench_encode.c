/* Host benchmark for the encode-and-send cost per byte (run under callgrind by
 * tools/encode_cost.py): encodes one message type N times with fw_encode_message and,
 * in "send" mode, also hands each datagram to the GS1500M driver (ESC Z framing onto a
 * serial sink). Only bench_loop() is measured (callgrind --toggle-collect=bench_loop).
 *   fw_encode_bench status|text|image encode|send N */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fw_gs1500.h"
#include "fw_registry.h"
#include "fumanoid.pb.h"

void fw_log(const char *what, const char *detail, int32_t value) { (void)what; (void)detail; (void)value; }

static char g_reply[64];
static size_t g_reply_len, g_reply_pos;
static volatile uint32_t g_sink;

static int serial_read(void *ctx, uint8_t *buf, uint16_t cap)
{
    size_t n = g_reply_len - g_reply_pos;
    (void)ctx;
    if (n > cap) n = cap;
    memcpy(buf, g_reply + g_reply_pos, n);
    g_reply_pos += n;
    return (int)n;
}

/* The module answers every AT command with CONNECT + OK; data bytes go nowhere. */
static bool serial_write(void *ctx, const uint8_t *buf, uint16_t n)
{
    uint16_t i;
    (void)ctx;
    if (n >= 2 && buf[0] == 'A' && buf[1] == 'T') {
        strcpy(g_reply, "\r\nCONNECT 1\r\nOK\r\n");
        g_reply_len = strlen(g_reply);
        g_reply_pos = 0;
    }
    for (i = 0; i < n; i++) g_sink += buf[i]; /* touch every byte like a UART would */
    return true;
}

static uint8_t g_tx[1400];
static union {
    fumanoid_Status status;
    fumanoid_DebugText text;
    fumanoid_DebugImage image;
} g_msg;

void bench_loop(const pb_extension_type_t *type, int send, long n, uint32_t *bytes);
void bench_loop(const pb_extension_type_t *type, int send, long n, uint32_t *bytes)
{
    long i;
    for (i = 0; i < n; i++) {
        uint16_t len = fw_encode_message(g_tx, sizeof g_tx, FW_FRAMING_LEGACY, 1, type, &g_msg);
        if (len == 0) abort();
        if (send && !sendMsgToCon(g_tx, len, WLAN_CID_CONSOLE)) abort();
        *bytes += len;
    }
}

int main(int argc, char **argv)
{
    static gs_module m;
    gs_serial serial = {serial_read, serial_write, NULL};
    gs_config cfg = {"bench", {127, 0, 0, 1}, 11011, 3838};
    const pb_extension_type_t *type;
    uint32_t bytes = 0, now = 0;
    long n;
    int send;
    if (argc < 4) {
        fprintf(stderr, "usage: %s status|text|image encode|send N\n", argv[0]);
        return 2;
    }
    send = strcmp(argv[2], "send") == 0;
    n = strtol(argv[3], NULL, 10);
    if (strcmp(argv[1], "status") == 0) {
        type = &fumanoid_status;
        g_msg.status = (fumanoid_Status)fumanoid_Status_init_zero;
        g_msg.status.has_timestamp = g_msg.status.has_teamID = g_msg.status.has_timeOnline = true;
        g_msg.status.timestamp = 123456789;
        g_msg.status.teamID = 13;
        g_msg.status.timeOnline = 600;
        g_msg.status.has_robotPosition = true;
        g_msg.status.robotPosition.has_x = g_msg.status.robotPosition.has_y = true;
        g_msg.status.robotPosition.x = 1500.0f;
        g_msg.status.robotPosition.y = -700.0f;
        g_msg.status.has_activeRole = g_msg.status.has_currentState = g_msg.status.has_gameState = true;
        strcpy(g_msg.status.activeRole, "striker");
        strcpy(g_msg.status.currentState, "playing");
        strcpy(g_msg.status.gameState, "PLAYING");
    } else if (strcmp(argv[1], "text") == 0) {
        type = &fumanoid_debugText;
        g_msg.text = (fumanoid_DebugText)fumanoid_DebugText_init_zero;
        strcpy(g_msg.text.option, "demo.text");
        g_msg.text.has_text = true;
        memset(g_msg.text.text, 'x', 383);
        g_msg.text.has_timestamp = true;
        g_msg.text.timestamp = 42;
    } else {
        type = &fumanoid_debugImage;
        g_msg.image = (fumanoid_DebugImage)fumanoid_DebugImage_init_zero;
        strcpy(g_msg.image.option, "demo.image");
        g_msg.image.has_width = g_msg.image.has_height = g_msg.image.has_format = g_msg.image.has_data = true;
        g_msg.image.width = 40;
        g_msg.image.height = 30;
        g_msg.image.data.size = 1200;
        memset(g_msg.image.data.bytes, 0x5A, 1200);
    }
    gs_module_init(&m, &serial, &cfg);
    wlan_use(&m.driver);
    while (!pollInitNetwork(now += 10)) {
    }
    bench_loop(type, send, n, &bytes);
    printf("%s %s %ld messages %lu bytes %.1f bytes/message\n", argv[1], argv[2], n, (unsigned long)bytes,
           (double)bytes / (double)n);
    return 0;
}
