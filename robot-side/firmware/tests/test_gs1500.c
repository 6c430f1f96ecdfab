/* The GS1500M serial parser and driver: fragmented input, cut-off headers, garbage,
 * maximum sizes, ESC y source addresses, notices, text lines, the AT start-up sequence
 * and the exact bytes of outgoing frames. */
#include <string.h>
#include "fw_gs1500.h"
#include "test_util.h"

static uint8_t buf[GS_MAX_DATA];
static gs_parser P;

typedef struct {
    int datagrams, lines, ok, fail;
    uint16_t last_len;
    char last_line[GS_LINE_RING + 1];
    uint8_t last[GS_MAX_DATA];
    char cid;
    uint16_t port;
    uint8_t ip[4];
} seen_t;
static seen_t seen;

static void feed(const uint8_t *d, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        gs_event ev = gs_parser_push(&P, d[i]);
        if (ev == GS_EV_DATAGRAM) {
            seen.datagrams++;
            seen.last_len = P.len;
            memcpy(seen.last, buf, P.len);
            seen.cid = P.cid;
            seen.port = P.port;
            memcpy(seen.ip, P.ip, 4);
        } else if (ev == GS_EV_LINE) {
            seen.lines++;
            gs_parser_line(&P, seen.last_line, sizeof seen.last_line);
        } else if (ev == GS_EV_SENT_OK) {
            seen.ok++;
        } else if (ev == GS_EV_SENT_FAIL) {
            seen.fail++;
        }
    }
}
static void feed_str(const char *s) { feed((const uint8_t *)s, strlen(s)); }

static void reset(void)
{
    gs_parser_init(&P, buf, sizeof buf);
    memset(&seen, 0, sizeof seen);
}

/* ESC Z <cid> <len4> <data> */
static size_t frame_z(uint8_t *out, char cid, const uint8_t *data, uint16_t n)
{
    out[0] = GS_ESC;
    out[1] = 'Z';
    out[2] = (uint8_t)cid;
    out[3] = (uint8_t)('0' + n / 1000 % 10);
    out[4] = (uint8_t)('0' + n / 100 % 10);
    out[5] = (uint8_t)('0' + n / 10 % 10);
    out[6] = (uint8_t)('0' + n % 10);
    memcpy(out + 7, data, n);
    return 7u + n;
}

static void test_basic_and_fragmented(void)
{
    static uint8_t stream[4096];
    static uint8_t payload[300];
    size_t n = 0, i, step;
    for (i = 0; i < sizeof payload; i++) payload[i] = (uint8_t)(i * 7); /* contains ESC, CR, LF */
    reset();
    n += frame_z(stream + n, '1', payload, 300);
    memcpy(stream + n, "\r\nOK\r\n", 6);
    n += 6;
    n += frame_z(stream + n, '1', payload, 17);
    stream[n++] = GS_ESC;
    stream[n++] = 'O';
    /* one byte at a time, then in chunks of every size: same result */
    for (step = 1; step <= 64; step = step * 2 + 1) {
        reset();
        for (i = 0; i < n; i += step) feed(stream + i, i + step <= n ? step : n - i);
        CHECK_EQ(seen.datagrams, 2);
        CHECK_EQ(seen.last_len, 17);
        CHECK(memcmp(seen.last, payload, 17) == 0);
        CHECK_EQ(seen.cid, '1');
        CHECK_EQ(seen.port, 0);
        CHECK_EQ(seen.lines, 1);
        CHECK(strcmp(seen.last_line, "OK") == 0);
        CHECK_EQ(seen.ok, 1);
        CHECK_EQ(P.stats.resyncs, 0);
    }
}

static void test_esc_y(void)
{
    reset();
    feed_str("\x1by0192.168.17.4 3838\t0005hello");
    CHECK_EQ(seen.datagrams, 1);
    CHECK_EQ(seen.cid, '0');
    CHECK_EQ(seen.port, 3838);
    CHECK(seen.ip[0] == 192 && seen.ip[1] == 168 && seen.ip[2] == 17 && seen.ip[3] == 4);
    CHECK(memcmp(seen.last, "hello", 5) == 0);
    /* broken addresses resynchronise and the next frame still parses */
    feed_str("\x1by0192.168.17 3838\t0001x");      /* three octets */
    feed_str("\x1by0300.1.1.1 1\t0001x");           /* octet > 255 */
    feed_str("\x1by01.2.3.4 99999\t0001x");         /* port > 65535 */
    feed_str("\x1by01.2.3.4 80 0001x");             /* space instead of TAB */
    CHECK_EQ(P.stats.resyncs, 4);
    CHECK_EQ(seen.datagrams, 1);
    feed_str("\x1by010.0.0.1 1\t0002ok");
    CHECK_EQ(seen.datagrams, 2);
    CHECK_EQ(seen.port, 1);
}

static void test_cut_off_headers(void)
{
    static uint8_t frame[64];
    static const uint8_t data[] = {0, 42, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 8, 1};
    size_t n = frame_z(frame, '1', data, sizeof data), cut;
    /* every possible loss of the first `cut` bytes, then a good frame: the good frame
     * is always recovered and the parser never reports the cut one as a datagram */
    for (cut = 1; cut < n; cut++) {
        reset();
        feed(frame + cut, n - cut);
        feed(frame, n);
        CHECK_EQ(seen.datagrams, 1);
        CHECK_EQ(seen.last_len, sizeof data);
        CHECK(memcmp(seen.last, data, sizeof data) == 0);
    }
    /* a header cut inside its length digits */
    reset();
    feed_str("\x1bZ1" "00");
    feed(frame, n);
    CHECK_EQ(seen.datagrams, 1);
    CHECK_EQ(P.stats.resyncs, 1);
    /* a header whose data is cut short swallows the next frame at most, then recovers */
    reset();
    feed_str("\x1bZ10020abc");
    feed(frame, n);
    feed(frame, n);
    feed(frame, n);
    CHECK(seen.datagrams >= 2);
    CHECK_EQ(seen.last_len, sizeof data);
    CHECK(memcmp(seen.last, data, sizeof data) == 0);
}

static void test_garbage_and_lines(void)
{
    static uint8_t junk[5000];
    size_t i;
    uint32_t x = 1;
    reset();
    for (i = 0; i < sizeof junk; i++) {
        x = x * 1664525u + 1013904223u;
        junk[i] = (uint8_t)(x >> 24);
    }
    feed(junk, sizeof junk);
    feed_str("\x1b\x1b\x1bQ\x1bZ\x1bZ1abcd");
    feed_str("\r\nCONNECT 3\r\n");
    CHECK(strcmp(seen.last_line, "CONNECT 3") == 0);
    /* binary bytes make a "line" garbage, never a keyword */
    {
        int lines = seen.lines;
        feed_str("O\x01K\r\n");
        CHECK_EQ(seen.lines, lines);
    }
    /* a line longer than the 64-byte ring keeps its last 64 bytes */
    feed_str("\r\n");
    for (i = 0; i < 100; i++) feed_str("x");
    feed_str("TAIL\r\n");
    CHECK_EQ(strlen(seen.last_line), GS_LINE_RING);
    CHECK(strcmp(seen.last_line + GS_LINE_RING - 4, "TAIL") == 0);
    /* an unterminated text fragment before ESC does not glue onto the next line */
    feed_str("garb");
    feed_str("\x1bO");
    feed_str("OK\r\n");
    CHECK(strcmp(seen.last_line, "OK") == 0);
    feed_str("\x1b" "F");
    CHECK_EQ(seen.fail, 1);
    /* still working */
    feed_str("\x1bZ20003abc");
    CHECK_EQ(seen.last_len, 3);
    CHECK_EQ(seen.cid, '2');
}

static void test_max_sizes(void)
{
    static uint8_t stream[1500];
    static uint8_t data[1401];
    static uint8_t small[10];
    size_t n, i;
    for (i = 0; i < sizeof data; i++) data[i] = (uint8_t)i;
    reset();
    n = frame_z(stream, '1', data, 1400);
    feed(stream, n);
    CHECK_EQ(seen.datagrams, 1);
    CHECK_EQ(seen.last_len, 1400);
    CHECK(memcmp(seen.last, data, 1400) == 0);
    feed_str("\x1bZ11401");
    CHECK_EQ(P.stats.oversize, 1);
    feed_str("\x1bZ19999");
    CHECK_EQ(P.stats.oversize, 2);
    feed_str("\x1bZ10000");
    feed_str("\x1bZ10001x");
    CHECK_EQ(seen.datagrams, 2);
    /* a datagram bigger than the caller's buffer is skipped, never written past it */
    gs_parser_init(&P, small, sizeof small);
    memset(&seen, 0, sizeof seen);
    {
        uint8_t guard[16];
        memset(guard, 0xAA, sizeof guard);
        n = frame_z(stream, '1', data, 11);
        for (i = 0; i < n; i++) (void)gs_parser_push(&P, stream[i]);
        CHECK_EQ(P.stats.oversize, 1);
        CHECK_EQ(P.stats.datagrams, 0);
        n = frame_z(stream, '1', data, 10);
        for (i = 0; i < n; i++) (void)gs_parser_push(&P, stream[i]);
        CHECK_EQ(P.stats.datagrams, 1);
        CHECK(memcmp(small, data, 10) == 0);
        for (i = 0; i < sizeof guard; i++) CHECK_EQ(guard[i], 0xAA);
    }
    /* no buffer at all (before the link is up): datagrams are skipped */
    gs_parser_init(&P, NULL, 0);
    n = frame_z(stream, '1', data, 5);
    for (i = 0; i < n; i++) CHECK(gs_parser_push(&P, stream[i]) != GS_EV_DATAGRAM);
}

/* ---- the driver against a scripted module ---- */
static uint8_t to_fw[4096];
static size_t to_fw_len, to_fw_pos;
static char from_fw[8192];
static size_t from_fw_len;

static int fake_read(void *ctx, uint8_t *b, uint16_t cap)
{
    size_t n = to_fw_len - to_fw_pos;
    (void)ctx;
    if (n > 5) n = 5; /* trickle: fragmented reads */
    if (n > cap) n = cap;
    memcpy(b, to_fw + to_fw_pos, n);
    to_fw_pos += n;
    return (int)n;
}
static bool fake_write(void *ctx, const uint8_t *b, uint16_t n)
{
    (void)ctx;
    if (from_fw_len + n > sizeof from_fw) return false;
    memcpy(from_fw + from_fw_len, b, n);
    from_fw_len += n;
    return true;
}
static void module_says(const char *s)
{
    size_t n = strlen(s);
    memcpy(to_fw + to_fw_len, s, n);
    to_fw_len += n;
}

static void test_driver(void)
{
    static gs_module m;
    static uint8_t rx[GS_MAX_DATA];
    gs_serial serial = {fake_read, fake_write, NULL};
    gs_config cfg = {"field", {192, 168, 0, 10}, 11011, 3838};
    uint32_t now = 0;
    uint16_t len;
    wlan_peer from;
    int i;
    gs_module_init(&m, &serial, &cfg);
    CHECK(!m.driver.poll_init(m.driver.ctx, now));
    CHECK(strstr(from_fw, "AT\r\n") != NULL);
    /* no answer: the command is repeated after a second */
    CHECK(!m.driver.poll_init(m.driver.ctx, now += 500));
    CHECK(!m.driver.poll_init(m.driver.ctx, now += 600));
    CHECK(!m.driver.poll_init(m.driver.ctx, now += 1));
    CHECK_EQ(m.stats.command_retries, 1);
    module_says("\r\nOK\r\n");
    for (i = 0; i < 10; i++) (void)m.driver.poll_init(m.driver.ctx, now += 1);
    CHECK(strstr(from_fw, "AT+WA=field\r\n") != NULL);
    module_says("\r\nERROR\r\n");
    for (i = 0; i < 10; i++) (void)m.driver.poll_init(m.driver.ctx, now += 1);
    now += 400;
    for (i = 0; i < 3; i++) (void)m.driver.poll_init(m.driver.ctx, now += 1);
    module_says("IP:x\r\nOK\r\n");
    for (i = 0; i < 10; i++) (void)m.driver.poll_init(m.driver.ctx, now += 1);
    CHECK(strstr(from_fw, "AT+NSUDP=3838\r\n") != NULL);
    module_says("\r\nOK\r\n"); /* OK without CONNECT is not enough */
    for (i = 0; i < 10; i++) (void)m.driver.poll_init(m.driver.ctx, now += 1);
    CHECK(strstr(from_fw, "AT+NCUDP") == NULL);
    module_says("\r\nCONNECT 0\r\nOK\r\n");
    for (i = 0; i < 10; i++) (void)m.driver.poll_init(m.driver.ctx, now += 1);
    CHECK(strstr(from_fw, "AT+NCUDP=192.168.0.10,11011,3838\r\n") != NULL);
    module_says("\r\nCONNECT 1\r\nOK\r\n");
    for (i = 0; i < 10; i++) (void)m.driver.poll_init(m.driver.ctx, now += 1);
    CHECK(strstr(from_fw, "AT+BDATA=1\r\n") != NULL);
    CHECK(!gs_module_ready(&m));
    module_says("\r\nOK\r\n");
    for (i = 0; i < 10; i++) (void)m.driver.poll_init(m.driver.ctx, now += 1);
    CHECK(gs_module_ready(&m));

    /* outgoing frames */
    from_fw_len = 0;
    CHECK(m.driver.send_con(m.driver.ctx, (const uint8_t *)"abc", 3, WLAN_CID_CONSOLE));
    CHECK(from_fw_len == 10 && memcmp(from_fw, "\x1bZ10003abc", 10) == 0);
    {
        wlan_peer to = {'0', {10, 0, 0, 7}, 4711};
        from_fw_len = 0;
        CHECK(m.driver.send_peer(m.driver.ctx, &to, (const uint8_t *)"hi", 2));
        CHECK(from_fw_len == 23 && memcmp(from_fw, "\x1bY010.0.0.7:4711:0002hi", 23) == 0);
    }
    {
        static uint8_t big[GS_MAX_DATA + 1];
        CHECK(!m.driver.send_con(m.driver.ctx, big, sizeof big, WLAN_CID_CONSOLE));
    }

    /* incoming, through notices and text */
    module_says("\x1bO\x1bZ10004ping\x1bO\x1by07.7.7.7 99\t0003pong");
    len = sizeof rx;
    CHECK(m.driver.recv(m.driver.ctx, rx, len, &len, &from));
    CHECK(len == 4 && memcmp(rx, "ping", 4) == 0 && from.cid == '1' && from.port == 0);
    len = sizeof rx;
    CHECK(m.driver.recv(m.driver.ctx, rx, len, &len, &from));
    CHECK(len == 3 && memcmp(rx, "pong", 3) == 0 && from.port == 99 && from.ip[0] == 7);
    len = sizeof rx;
    CHECK(!m.driver.recv(m.driver.ctx, rx, len, &len, &from));

    /* a datagram whose rest was lost in the module: abandoned once the line is idle, so it
     * cannot swallow the next frame */
    module_says("\x1bZ10100abc");
    len = sizeof rx;
    CHECK(!m.driver.recv(m.driver.ctx, rx, len, &len, &from));
    CHECK(m.driver.poll_init(m.driver.ctx, now += GS_IDLE_RESYNC_MS + 1));
    len = sizeof rx;
    CHECK(!m.driver.recv(m.driver.ctx, rx, len, &len, &from));
    CHECK_EQ(m.stats.idle_aborts, 1);
    module_says("\x1bZ10002ok");
    len = sizeof rx;
    CHECK(m.driver.recv(m.driver.ctx, rx, len, &len, &from));
    CHECK(len == 2 && memcmp(rx, "ok", 2) == 0);

    /* the module drops the console connection: the driver opens everything again */
    module_says("\r\nDISCONNECT 1\r\n");
    len = sizeof rx;
    CHECK(!m.driver.recv(m.driver.ctx, rx, len, &len, &from));
    CHECK(!gs_module_ready(&m));
    CHECK_EQ(m.stats.disconnects, 1);
    from_fw_len = 0;
    memset(from_fw, 0, sizeof from_fw);
    CHECK(!m.driver.poll_init(m.driver.ctx, now += 1));
    CHECK(strstr(from_fw, "AT\r\n") != NULL);
}

int main(void)
{
    test_basic_and_fragmented();
    test_esc_y();
    test_cut_off_headers();
    test_garbage_and_lines();
    test_max_sizes();
    test_driver();
    TEST_DONE();
}
