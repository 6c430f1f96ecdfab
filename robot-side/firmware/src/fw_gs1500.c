#include "fw_gs1500.h"

enum { S_TEXT = 0, S_ESC, S_CID, S_IP, S_PORT, S_LEN, S_DATA };
enum { STEP_AT = 0, STEP_ASSOCIATE, STEP_SERVER, STEP_CLIENT, STEP_BULK, STEP_READY };

/* ------------------------------------------------------------------ parser */

void gs_parser_init(gs_parser *p, uint8_t *buf, uint16_t cap)
{
    uint8_t i;
    p->state = S_TEXT;
    p->kind = 0;
    p->cid = 0;
    for (i = 0; i < 4; i++) p->ip[i] = 0;
    p->ip_octet = 0;
    p->ip_acc = 0;
    p->ip_digits = 0;
    p->port = 0;
    p->port_digits = 0;
    p->len = 0;
    p->len_digits = 0;
    p->got = 0;
    p->buf = buf;
    p->cap = buf ? cap : 0;
    p->ring_head = 0;
    p->line_len = 0;
    p->line_binary = false;
    p->line_done = false;
    p->stats.datagrams = p->stats.lines = p->stats.garbage_lines = p->stats.resyncs = 0;
    p->stats.oversize = p->stats.notices_ok = p->stats.notices_fail = 0;
}

void gs_parser_set_buffer(gs_parser *p, uint8_t *buf, uint16_t cap)
{
    if (p->state == S_DATA && buf != p->buf) {
        p->state = S_TEXT; /* a different buffer would tear the datagram: drop it */
        p->stats.resyncs++;
    }
    p->buf = buf;
    p->cap = buf ? cap : 0;
}

static bool is_cid(uint8_t b)
{
    return (b >= '0' && b <= '9') || (b >= 'a' && b <= 'f') || (b >= 'A' && b <= 'F');
}

static void line_reset(gs_parser *p)
{
    p->line_len = 0;
    p->ring_head = 0;
    p->line_binary = false;
    p->line_done = false;
}

static void line_append(gs_parser *p, uint8_t b)
{
    p->ring[p->ring_head] = (char)b;
    p->ring_head = (uint8_t)((p->ring_head + 1) % GS_LINE_RING);
    if (p->line_len < GS_LINE_RING) p->line_len++;
    if ((b < 0x20 && b != '\t') || b >= 0x7F) p->line_binary = true;
}

uint16_t gs_parser_line(const gs_parser *p, char *out, uint16_t cap)
{
    uint16_t n = p->line_len, i;
    uint8_t start = (uint8_t)((p->ring_head + GS_LINE_RING - n) % GS_LINE_RING);
    if (cap == 0) return 0;
    if (n > cap - 1) n = (uint16_t)(cap - 1);
    for (i = 0; i < n; i++) out[i] = p->ring[(start + i) % GS_LINE_RING];
    out[n] = '\0';
    return n;
}

bool gs_parser_abort(gs_parser *p)
{
    if (p->state == S_TEXT) return false;
    p->stats.resyncs++;
    p->state = S_TEXT;
    line_reset(p);
    return true;
}

/* A header went wrong (cut off by an overflowing module buffer, or garbage): count it
 * and treat the byte that broke it as ordinary input again. */
static void resync(gs_parser *p)
{
    p->stats.resyncs++;
    p->state = S_TEXT;
    line_reset(p);
}

gs_event gs_parser_push(gs_parser *p, uint8_t b)
{
    for (;;) {
        switch (p->state) {
        case S_TEXT:
            if (b == GS_ESC) {
                if (p->line_len > 0 && !p->line_done) p->stats.garbage_lines++; /* unterminated fragment */
                line_reset(p);
                p->state = S_ESC;
                return GS_EV_NONE;
            }
            if (b == '\r' || b == '\n') {
                if (p->line_len == 0 || p->line_done) return GS_EV_NONE;
                if (p->line_binary) {
                    p->stats.garbage_lines++;
                    line_reset(p);
                    return GS_EV_NONE;
                }
                p->stats.lines++;
                p->line_done = true; /* readable until the next byte starts a new line */
                return GS_EV_LINE;
            }
            if (p->line_done) line_reset(p);
            line_append(p, b);
            return GS_EV_NONE;
        case S_ESC:
            if (b == 'Z' || b == 'y') {
                p->kind = b;
                p->state = S_CID;
                return GS_EV_NONE;
            }
            if (b == 'O' || b == 'F') {
                p->state = S_TEXT;
                if (b == 'O') {
                    p->stats.notices_ok++;
                    return GS_EV_SENT_OK;
                }
                p->stats.notices_fail++;
                return GS_EV_SENT_FAIL;
            }
            resync(p); /* also for a second ESC: it starts the next header */
            continue;
        case S_CID:
            if (!is_cid(b)) {
                resync(p);
                continue;
            }
            p->cid = (char)b;
            p->len = 0;
            p->len_digits = 0;
            if (p->kind == 'Z') {
                p->state = S_LEN;
                p->port = 0;
                p->ip[0] = p->ip[1] = p->ip[2] = p->ip[3] = 0;
            } else {
                p->state = S_IP;
                p->ip_octet = 0;
                p->ip_acc = 0;
                p->ip_digits = 0;
            }
            return GS_EV_NONE;
        case S_IP:
            if (b >= '0' && b <= '9' && p->ip_digits < 3) {
                p->ip_acc = (uint16_t)(p->ip_acc * 10u + (b - '0'));
                p->ip_digits++;
                if (p->ip_acc > 255) {
                    resync(p);
                    continue;
                }
                return GS_EV_NONE;
            }
            if ((b == '.' || b == ' ') && p->ip_digits > 0) {
                p->ip[p->ip_octet] = (uint8_t)p->ip_acc;
                p->ip_acc = 0;
                p->ip_digits = 0;
                if (b == ' ') {
                    if (p->ip_octet != 3) {
                        resync(p);
                        continue;
                    }
                    p->state = S_PORT;
                    p->port = 0;
                    p->port_digits = 0;
                    return GS_EV_NONE;
                }
                if (p->ip_octet == 3) {
                    resync(p);
                    continue;
                }
                p->ip_octet++;
                return GS_EV_NONE;
            }
            resync(p);
            continue;
        case S_PORT:
            if (b >= '0' && b <= '9' && p->port_digits < 5) {
                uint32_t v = (uint32_t)p->port * 10u + (uint32_t)(b - '0');
                if (v > 65535u) {
                    resync(p);
                    continue;
                }
                p->port = (uint16_t)v;
                p->port_digits++;
                return GS_EV_NONE;
            }
            if (b == '\t' && p->port_digits > 0) {
                p->state = S_LEN;
                return GS_EV_NONE;
            }
            resync(p);
            continue;
        case S_LEN:
            if (b < '0' || b > '9') {
                resync(p);
                continue;
            }
            p->len = (uint16_t)(p->len * 10u + (b - '0'));
            if (++p->len_digits < 4) return GS_EV_NONE;
            if (p->len == 0) {
                resync(p);
                return GS_EV_NONE;
            }
            if (p->len > GS_MAX_DATA || p->len > p->cap) {
                /* cannot be a real datagram: its bytes will be skipped as text */
                p->stats.oversize++;
                resync(p);
                return GS_EV_NONE;
            }
            p->got = 0;
            p->state = S_DATA;
            return GS_EV_NONE;
        case S_DATA:
            p->buf[p->got++] = b;
            if (p->got < p->len) return GS_EV_NONE;
            p->state = S_TEXT;
            line_reset(p);
            p->stats.datagrams++;
            return GS_EV_DATAGRAM;
        default:
            p->state = S_TEXT;
            continue;
        }
    }
}

/* ------------------------------------------------------------------ driver */

static uint8_t put_dec(char *out, uint32_t v)
{
    char d[10];
    uint8_t n = 0, i;
    do {
        d[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0);
    for (i = 0; i < n; i++) out[i] = d[n - 1 - i];
    return n;
}

static uint8_t put_str(char *out, const char *s)
{
    uint8_t n = 0;
    while (s[n] != '\0' && n < 40) {
        out[n] = s[n];
        n++;
    }
    return n;
}

static uint8_t put_ip(char *out, const uint8_t ip[4])
{
    uint8_t n = 0, i;
    for (i = 0; i < 4; i++) {
        if (i) out[n++] = '.';
        n = (uint8_t)(n + put_dec(out + n, ip[i]));
    }
    return n;
}

static void put_len4(char *out, uint16_t len)
{
    out[0] = (char)('0' + (len / 1000u) % 10u);
    out[1] = (char)('0' + (len / 100u) % 10u);
    out[2] = (char)('0' + (len / 10u) % 10u);
    out[3] = (char)('0' + len % 10u);
}

static bool starts_with(const char *s, const char *prefix)
{
    while (*prefix != '\0') {
        if (*s++ != *prefix++) return false;
    }
    return true;
}

static void on_line(gs_module *m)
{
    gs_parser_line(&m->parser, m->line, sizeof m->line);
    if (starts_with(m->line, "OK")) {
        m->ok_seen = true;
    } else if (starts_with(m->line, "ERROR")) {
        m->error_seen = true;
    } else if (starts_with(m->line, "CONNECT ") && is_cid((uint8_t)m->line[8])) {
        m->connect_cid = m->line[8];
    } else if (starts_with(m->line, "DISCONNECT ")) {
        char cid = m->line[11];
        if (m->step == STEP_READY && (cid == m->console_cid || cid == m->server_cid)) {
            m->stats.disconnects++;
            m->step = STEP_AT; /* open everything again */
            m->step_sent = false;
        }
    }
}

/* Feeds serial bytes to the parser; true when a datagram completed. */
static bool pump(gs_module *m)
{
    for (;;) {
        if (m->chunk_pos == m->chunk_len) {
            int n = m->serial.read(m->serial.ctx, m->chunk, sizeof m->chunk);
            if (n <= 0) {
                if ((uint32_t)(m->now - m->last_byte_at) >= GS_IDLE_RESYNC_MS && gs_parser_abort(&m->parser)) {
                    m->stats.idle_aborts++;
                }
                return false;
            }
            m->last_byte_at = m->now;
            m->chunk_len = (uint8_t)n;
            m->chunk_pos = 0;
        }
        while (m->chunk_pos < m->chunk_len) {
            gs_event ev = gs_parser_push(&m->parser, m->chunk[m->chunk_pos++]);
            if (ev == GS_EV_DATAGRAM) return true;
            if (ev == GS_EV_LINE) on_line(m);
        }
    }
}

static void send_command(gs_module *m)
{
    char cmd[72];
    uint8_t n = 0;
    switch (m->step) {
    case STEP_AT:
        n = put_str(cmd, "AT");
        break;
    case STEP_ASSOCIATE:
        n = put_str(cmd, "AT+WA=");
        n = (uint8_t)(n + put_str(cmd + n, m->cfg.ssid ? m->cfg.ssid : "touchline"));
        break;
    case STEP_SERVER:
        n = put_str(cmd, "AT+NSUDP=");
        n = (uint8_t)(n + put_dec(cmd + n, m->cfg.local_port));
        break;
    case STEP_CLIENT:
        n = put_str(cmd, "AT+NCUDP=");
        n = (uint8_t)(n + put_ip(cmd + n, m->cfg.console_ip));
        cmd[n++] = ',';
        n = (uint8_t)(n + put_dec(cmd + n, m->cfg.console_port));
        cmd[n++] = ',';
        n = (uint8_t)(n + put_dec(cmd + n, m->cfg.local_port));
        break;
    default:
        n = put_str(cmd, "AT+BDATA=1");
        break;
    }
    cmd[n++] = '\r';
    cmd[n++] = '\n';
    m->ok_seen = m->error_seen = false;
    m->connect_cid = 0;
    (void)m->serial.write(m->serial.ctx, (const uint8_t *)cmd, n);
    m->step_sent = true;
}

static bool gs_poll_init(void *ctx, uint32_t now)
{
    gs_module *m = ctx;
    m->now = now;
    if (m->step == STEP_READY) return true;
    gs_parser_set_buffer(&m->parser, 0, 0); /* no datagrams expected before the link is up */
    (void)pump(m);
    if (!m->step_sent) {
        send_command(m);
        m->step_at = now;
        return false;
    }
    if (m->ok_seen && ((m->step != STEP_SERVER && m->step != STEP_CLIENT) || m->connect_cid != 0)) {
        if (m->step == STEP_SERVER) m->server_cid = m->connect_cid;
        if (m->step == STEP_CLIENT) m->console_cid = m->connect_cid;
        m->step++;
        m->step_sent = false;
        return m->step == STEP_READY;
    }
    if ((uint32_t)(now - m->step_at) >= (m->error_seen ? 300u : 1000u)) {
        m->stats.command_retries++;
        m->step_sent = false; /* ask again */
    }
    return false;
}

static bool gs_recv(void *ctx, uint8_t *buf, uint16_t cap, uint16_t *len, wlan_peer *from)
{
    gs_module *m = ctx;
    uint8_t i;
    if (m->step != STEP_READY) return false;
    gs_parser_set_buffer(&m->parser, buf, cap);
    if (!pump(m)) return false;
    *len = m->parser.len;
    from->cid = m->parser.cid;
    from->port = m->parser.port; /* 0 for ESC Z: the peer is the cid's remote end */
    for (i = 0; i < 4; i++) from->ip[i] = m->parser.ip[i];
    return true;
}

static bool write_frame(gs_module *m, const char *hdr, uint8_t hdr_len, const uint8_t *msg, uint16_t len)
{
    if (!m->serial.write(m->serial.ctx, (const uint8_t *)hdr, hdr_len) || !m->serial.write(m->serial.ctx, msg, len)) {
        m->stats.send_rejected++;
        return false;
    }
    m->stats.sent++;
    return true;
}

static bool gs_send_con(void *ctx, const uint8_t *msg, uint16_t len, char cid)
{
    gs_module *m = ctx;
    char hdr[7];
    if (m->step != STEP_READY || len == 0 || len > GS_MAX_DATA) {
        m->stats.send_rejected++;
        return false;
    }
    hdr[0] = GS_ESC;
    hdr[1] = 'Z';
    hdr[2] = cid == WLAN_CID_CONSOLE ? m->console_cid : cid;
    put_len4(hdr + 3, len);
    return write_frame(m, hdr, sizeof hdr, msg, len);
}

static bool gs_send_peer(void *ctx, const wlan_peer *to, const uint8_t *msg, uint16_t len)
{
    gs_module *m = ctx;
    char hdr[32];
    uint8_t n = 0;
    if (to->port == 0) return gs_send_con(ctx, msg, len, to->cid);
    if (m->step != STEP_READY || len == 0 || len > GS_MAX_DATA) {
        m->stats.send_rejected++;
        return false;
    }
    hdr[n++] = GS_ESC;
    hdr[n++] = 'Y';
    hdr[n++] = m->server_cid;
    n = (uint8_t)(n + put_ip(hdr + n, to->ip));
    hdr[n++] = ':';
    n = (uint8_t)(n + put_dec(hdr + n, to->port));
    hdr[n++] = ':';
    put_len4(hdr + n, len);
    n = (uint8_t)(n + 4);
    return write_frame(m, hdr, n, msg, len);
}

void gs_module_init(gs_module *m, const gs_serial *serial, const gs_config *cfg)
{
    m->serial = *serial;
    m->cfg = *cfg;
    gs_parser_init(&m->parser, 0, 0);
    m->chunk_len = m->chunk_pos = 0;
    m->step = STEP_AT;
    m->step_sent = false;
    m->ok_seen = m->error_seen = false;
    m->connect_cid = 0;
    m->step_at = 0;
    m->now = m->last_byte_at = 0;
    m->server_cid = m->console_cid = 0;
    m->stats.sent = m->stats.send_rejected = m->stats.command_retries = m->stats.disconnects = 0;
    m->stats.idle_aborts = 0;
    m->driver.poll_init = gs_poll_init;
    m->driver.recv = gs_recv;
    m->driver.send_con = gs_send_con;
    m->driver.send_peer = gs_send_peer;
    m->driver.ctx = m;
}

bool gs_module_ready(const gs_module *m) { return m->step == STEP_READY; }
