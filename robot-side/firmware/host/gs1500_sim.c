#define _POSIX_C_SOURCE 200809L
#include "gs1500_sim.h"
#include <arpa/inet.h>
#include <errno.h>
#include <poll.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#define RING 1400u            /* the largest datagram */
#define BUFFER (RING + 32u)   /* the module's buffer towards the MCU: 1400 data bytes + header */
#define ESC 0x1B

enum { M_TEXT, M_ESC, M_CID, M_ADDR, M_PORT, M_LEN, M_DATA };

struct gs_sim {
    int serial_fd, udp_fd;
    uint16_t local_port;
    double bytes_per_us;
    pthread_t thread;
    pthread_mutex_t lock;       /* guards the ring and the connection table */
    volatile int stop;          /* set by gs_sim_stop, read by the thread (atomic builtins) */
    /* module -> MCU: bytes not yet on the line, oldest first, and the sizes of the frames
     * (datagram with header, notice, text response) they belong to */
    uint8_t out[BUFFER];
    uint32_t out_len;
    uint16_t frames[BUFFER];
    uint32_t nframes;
    int first_started;  /* the first frame is partly on the line already */
    double credit;     /* bytes the line may carry to the MCU now */
    double rx_credit;  /* bytes the line may carry from the MCU now */
    /* connections: '0' = UDP server on local_port, '1' = UDP client to the console */
    int server_open, client_open;
    struct sockaddr_in client_peer;
    /* MCU -> module parser */
    int state;
    char kind, cid;
    char line[160];
    size_t line_len;
    char addr[20];
    size_t addr_len;
    uint32_t port;
    int port_digits;
    uint32_t len_field;
    int len_digits;
    uint8_t data[RING];
    uint32_t got;
    gs_sim_stats stats;
};

static uint64_t now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000u + (uint64_t)ts.tv_nsec / 1000u;
}

/* Removes bytes [at, at+n) of the buffer, shrinking or removing the frames they belong to. */
static void drop_range(gs_sim *s, uint32_t at, uint32_t n)
{
    uint32_t pos = 0, i, k = 0;
    memmove(s->out + at, s->out + at + n, s->out_len - at - n);
    s->out_len -= n;
    for (i = 0; i < s->nframes; i++) {
        uint32_t fs = pos, fe = pos + s->frames[i];
        uint32_t lo = fs > at ? fs : at, hi = fe < at + n ? fe : at + n;
        uint32_t keep = s->frames[i] - (hi > lo ? hi - lo : 0);
        if (keep > 0) s->frames[k++] = (uint16_t)keep;
        pos = fe;
    }
    s->nframes = k;
}

/* Queues one frame for the MCU. When the buffer is full the oldest waiting bytes are lost
 * -- but never the rest of the frame already going out on the line -- so the frame that
 * loses its first bytes reaches the MCU with its header cut off. If even that is not
 * enough, the new frame itself loses its head. Caller holds lock. */
static void to_mcu_frame(gs_sim *s, const void *hdr, size_t hlen, const void *data, size_t dlen)
{
    size_t n = hlen + dlen, skip = 0, free_bytes = BUFFER - s->out_len, i;
    if (n > free_bytes) {
        uint32_t protect = s->first_started ? s->frames[0] : 0;
        size_t need = n - free_bytes, avail = s->out_len - protect, d = need < avail ? need : avail;
        if (d > 0) drop_range(s, protect, (uint32_t)d);
        skip = need - d;
        s->stats.overflow_bytes += (uint32_t)need;
        s->stats.overflow_events++;
    }
    if (skip >= n) return;
    for (i = skip; i < n; i++) {
        s->out[s->out_len++] = i < hlen ? ((const uint8_t *)hdr)[i] : ((const uint8_t *)data)[i - hlen];
    }
    s->frames[s->nframes++] = (uint16_t)(n - skip);
}

static void to_mcu(gs_sim *s, const void *bytes, size_t n) { to_mcu_frame(s, "", 0, bytes, n); }

static void to_mcu_text(gs_sim *s, const char *text) { to_mcu(s, text, strlen(text)); }

static void command(gs_sim *s, const char *cmd)
{
    s->stats.commands++;
    if (strcmp(cmd, "AT") == 0 || strcmp(cmd, "ATE0") == 0 || strcmp(cmd, "AT+BDATA=1") == 0) {
        to_mcu_text(s, "\r\nOK\r\n");
    } else if (strncmp(cmd, "AT+WA=", 6) == 0) {
        to_mcu_text(s, "\r\n    IP              SubNet         Gateway   \r\n 127.0.0.1: 255.0.0.0: 127.0.0.1\r\nOK\r\n");
    } else if (strncmp(cmd, "AT+NSUDP=", 9) == 0) {
        long port = strtol(cmd + 9, NULL, 10);
        if (port == s->local_port || port == 0) {
            s->server_open = 1;
            to_mcu_text(s, "\r\nCONNECT 0\r\nOK\r\n");
        } else {
            to_mcu_text(s, "\r\nERROR\r\n");
        }
    } else if (strncmp(cmd, "AT+NCUDP=", 9) == 0) {
        char ip[32];
        long port;
        const char *comma = strchr(cmd + 9, ',');
        if (comma == NULL || (size_t)(comma - (cmd + 9)) >= sizeof ip) {
            to_mcu_text(s, "\r\nERROR\r\n");
            return;
        }
        memcpy(ip, cmd + 9, (size_t)(comma - (cmd + 9)));
        ip[comma - (cmd + 9)] = '\0';
        port = strtol(comma + 1, NULL, 10);
        memset(&s->client_peer, 0, sizeof s->client_peer);
        s->client_peer.sin_family = AF_INET;
        s->client_peer.sin_port = htons((uint16_t)port);
        if (inet_pton(AF_INET, ip, &s->client_peer.sin_addr) != 1 || port <= 0 || port > 65535) {
            to_mcu_text(s, "\r\nERROR\r\n");
            return;
        }
        /* the optional third argument (source port) is our bound port: one socket */
        s->client_open = 1;
        to_mcu_text(s, "\r\nCONNECT 1\r\nOK\r\n");
    } else if (strncmp(cmd, "AT+NCLOSE=", 10) == 0) {
        if (cmd[10] == '0') s->server_open = 0;
        if (cmd[10] == '1') s->client_open = 0;
        to_mcu_text(s, "\r\nOK\r\n");
    } else {
        to_mcu_text(s, "\r\nERROR\r\n");
    }
}

static void send_frame(gs_sim *s)
{
    struct sockaddr_in to;
    int ok = 0;
    s->stats.frames_from_mcu++;
    if (s->kind == 'Z' && s->cid == '1' && s->client_open) {
        to = s->client_peer;
        ok = 1;
    } else if (s->kind == 'Y' && s->cid == '0' && s->server_open) {
        memset(&to, 0, sizeof to);
        to.sin_family = AF_INET;
        to.sin_port = htons((uint16_t)s->port);
        ok = inet_pton(AF_INET, s->addr, &to.sin_addr) == 1;
    }
    if (ok && sendto(s->udp_fd, s->data, s->got, 0, (struct sockaddr *)&to, sizeof to) == (ssize_t)s->got) {
        s->stats.udp_out++;
        to_mcu(s, "\x1bO", 2);
    } else {
        s->stats.send_failed++;
        to_mcu(s, "\x1b" "F", 2);
    }
}

static void bad_header(gs_sim *s)
{
    s->stats.bad_from_mcu++;
    s->state = M_TEXT;
    s->line_len = 0;
}

static void from_mcu(gs_sim *s, uint8_t b)
{
    switch (s->state) {
    case M_TEXT:
        if (b == ESC) {
            s->state = M_ESC;
            s->line_len = 0;
        } else if (b == '\r' || b == '\n') {
            if (s->line_len > 0) {
                s->line[s->line_len] = '\0';
                command(s, s->line);
                s->line_len = 0;
            }
        } else if (s->line_len + 1 < sizeof s->line) {
            s->line[s->line_len++] = (char)b;
        }
        break;
    case M_ESC:
        if (b == 'Z' || b == 'Y') {
            s->kind = (char)b;
            s->state = M_CID;
        } else {
            bad_header(s);
        }
        break;
    case M_CID:
        s->cid = (char)b;
        s->len_field = 0;
        s->len_digits = 0;
        s->addr_len = 0;
        s->port = 0;
        s->port_digits = 0;
        s->state = s->kind == 'Z' ? M_LEN : M_ADDR;
        break;
    case M_ADDR:
        if (b == ':' && s->addr_len > 0) {
            s->addr[s->addr_len] = '\0';
            s->state = M_PORT;
        } else if (((b >= '0' && b <= '9') || b == '.') && s->addr_len + 1 < sizeof s->addr) {
            s->addr[s->addr_len++] = (char)b;
        } else {
            bad_header(s);
        }
        break;
    case M_PORT:
        if (b == ':' && s->port_digits > 0) {
            s->state = M_LEN;
        } else if (b >= '0' && b <= '9' && s->port_digits < 5) {
            s->port = s->port * 10u + (uint32_t)(b - '0');
            s->port_digits++;
        } else {
            bad_header(s);
        }
        break;
    case M_LEN:
        if (b < '0' || b > '9') {
            bad_header(s);
            break;
        }
        s->len_field = s->len_field * 10u + (uint32_t)(b - '0');
        if (++s->len_digits == 4) {
            if (s->len_field == 0 || s->len_field > RING) {
                bad_header(s);
                to_mcu(s, "\x1b" "F", 2);
            } else {
                s->got = 0;
                s->state = M_DATA;
            }
        }
        break;
    case M_DATA:
        s->data[s->got++] = b;
        if (s->got == s->len_field) {
            send_frame(s);
            s->state = M_TEXT;
        }
        break;
    default:
        s->state = M_TEXT;
    }
}

static void from_network(gs_sim *s)
{
    uint8_t buf[2048];
    int budget;
    for (budget = 0; budget < 64; budget++) {
        struct sockaddr_in src;
        socklen_t slen = sizeof src;
        char hdr[64];
        ssize_t n = recvfrom(s->udp_fd, buf, sizeof buf, MSG_DONTWAIT, (struct sockaddr *)&src, &slen);
        if (n < 0) return;
        s->stats.udp_in++;
        if (n == 0 || n > (ssize_t)RING) {
            s->stats.udp_dropped++; /* the module's buffer cannot hold it */
            continue;
        }
        pthread_mutex_lock(&s->lock);
        if (s->client_open && src.sin_addr.s_addr == s->client_peer.sin_addr.s_addr &&
            src.sin_port == s->client_peer.sin_port) {
            snprintf(hdr, sizeof hdr, "\x1bZ1%04d", (int)n);
        } else if (s->server_open) {
            char ip[INET_ADDRSTRLEN];
            inet_ntop(AF_INET, &src.sin_addr, ip, sizeof ip);
            snprintf(hdr, sizeof hdr, "\x1by0%s %u\t%04d", ip, (unsigned)ntohs(src.sin_port), (int)n);
        } else {
            s->stats.udp_dropped++;
            pthread_mutex_unlock(&s->lock);
            continue;
        }
        to_mcu_frame(s, hdr, strlen(hdr), buf, (size_t)n);
        pthread_mutex_unlock(&s->lock);
    }
}

/* Moves as many buffered bytes to the serial line as the baud rate allows. */
static void drain(gs_sim *s, double elapsed_us)
{
    pthread_mutex_lock(&s->lock);
    s->credit += elapsed_us * s->bytes_per_us;
    if (s->credit > BUFFER) s->credit = BUFFER;
    while (s->out_len > 0 && s->credit >= 1.0) {
        uint32_t chunk = s->out_len, w;
        ssize_t k;
        if (chunk > (uint32_t)s->credit) chunk = (uint32_t)s->credit;
        k = send(s->serial_fd, s->out, chunk, MSG_DONTWAIT | MSG_NOSIGNAL);
        if (k <= 0) break;
        w = (uint32_t)k;
        memmove(s->out, s->out + w, s->out_len - w);
        s->out_len -= w;
        s->credit -= (double)w;
        while (w > 0) { /* account the bytes to their frames */
            if (w >= s->frames[0]) {
                w -= s->frames[0];
                memmove(s->frames, s->frames + 1, (s->nframes - 1) * sizeof s->frames[0]);
                s->nframes--;
                s->first_started = 0;
            } else {
                s->frames[0] = (uint16_t)(s->frames[0] - w);
                w = 0;
                s->first_started = 1;
            }
        }
    }
    if (s->out_len == 0 && s->credit > 64) s->credit = 64; /* an idle line banks no bursts */
    pthread_mutex_unlock(&s->lock);
}

static void *run(void *arg)
{
    gs_sim *s = arg;
    uint64_t last = now_us();
    while (!__atomic_load_n(&s->stop, __ATOMIC_ACQUIRE)) {
        struct pollfd p[2];
        uint64_t t;
        p[0].fd = s->serial_fd;
        /* the UART from the MCU carries no more than the baud rate: without credit the
         * bytes wait in the (small) socket buffer and the firmware's write blocks */
        p[0].events = s->rx_credit >= 1.0 ? POLLIN : 0;
        p[1].fd = s->udp_fd;
        p[1].events = POLLIN;
        p[0].revents = p[1].revents = 0;
        (void)poll(p, 2, 1);
        if (p[0].revents & (POLLIN | POLLHUP)) {
            uint8_t buf[512];
            size_t want = s->rx_credit < (double)sizeof buf ? (size_t)s->rx_credit : sizeof buf;
            ssize_t n = recv(s->serial_fd, buf, want ? want : 1, MSG_DONTWAIT);
            ssize_t i;
            if (n == 0) break; /* the firmware side closed */
            if (n > 0) s->rx_credit -= (double)n;
            pthread_mutex_lock(&s->lock);
            for (i = 0; i < n; i++) from_mcu(s, buf[i]);
            pthread_mutex_unlock(&s->lock);
        }
        if (p[1].revents & POLLIN) from_network(s);
        t = now_us();
        s->rx_credit += (double)(t - last) * s->bytes_per_us;
        if (s->rx_credit > 256.0) s->rx_credit = 256.0;
        drain(s, (double)(t - last));
        last = t;
    }
    return NULL;
}

gs_sim *gs_sim_start(int serial_fd, int udp_fd, uint16_t local_port, uint32_t baud)
{
    gs_sim *s = calloc(1, sizeof *s);
    if (s == NULL) return NULL;
    s->serial_fd = serial_fd;
    s->udp_fd = udp_fd;
    s->local_port = local_port;
    s->bytes_per_us = (double)(baud ? baud : 460800u) / 10.0 / 1e6; /* 8N1: 10 bits per byte */
    s->state = M_TEXT;
    pthread_mutex_init(&s->lock, NULL);
    if (pthread_create(&s->thread, NULL, run, s) != 0) {
        free(s);
        return NULL;
    }
    return s;
}

void gs_sim_disconnect(gs_sim *s, char cid)
{
    char msg[32];
    pthread_mutex_lock(&s->lock);
    if (cid == '0') s->server_open = 0;
    if (cid == '1') s->client_open = 0;
    snprintf(msg, sizeof msg, "\r\nDISCONNECT %c\r\n", cid);
    to_mcu_text(s, msg);
    pthread_mutex_unlock(&s->lock);
}

void gs_sim_stop(gs_sim *s, gs_sim_stats *stats)
{
    if (s == NULL) return;
    __atomic_store_n(&s->stop, 1, __ATOMIC_RELEASE);
    pthread_join(s->thread, NULL);
    if (stats) *stats = s->stats;
    pthread_mutex_destroy(&s->lock);
    free(s);
}
