/* touchline-robot: the small-robot firmware core on the host. The core talks either to
 * plain UDP (default) or, with --wifi-sim, to a simulated GS1500M serial Wi-Fi module
 * over a socketpair, exactly as it would talk to the module's UART on the board.
 *
 *   touchline-robot --id N [--team T] [--name NAME] --console HOST:PORT [--port P]
 *                   [--framing legacy|length] [--wifi-sim [--baud B]] [--rate HZ]
 *                   [--reliable] [--reliable-print] [--reliable-send FILE] [--mathe N]
 *                   [--reliable-peer HOST:PORT] [--seed S] [--rto MS]
 *                   [--gc-return HOST[:PORT]] [--gc-return-rate HZ]
 *                   [--team-msg-rate HZ] [--team-msg-to HOST[:PORT]] [--team-key FILE [--boot-file FILE]]
 *                   [--match-budget BYTES] [--match-sends N]
 *
 * --match-budget BYTES: the match digest's datagram size (default one MTU, capped at 1400);
 * --match-sends N: digests per period in play (default 1: the rule; more only to show that the
 * console flags a robot breaking it).
 * --team-key FILE: the team key (`team.key` of `touchline keys new`); without it the robot
 * runs in lab mode (no tags checked or sent), as before keys existed (docs/security.md).
 * --boot-file FILE: the simulated flash word of the board's boot number (board/board_boot.c):
 * each start takes one above it (never below the clock's seconds) and writes it back; without
 * it the boot number is the clock's seconds.
 *
 * First line on stdout: "listening on port <port>". */
#define _POSIX_C_SOURCE 200809L
#include <arpa/inet.h>
#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "fw_mathe.h"
#include "fw_robot.h"
#include "host_udp.h"
#include "host_wifi.h"
#include "sim_world.h"

static volatile sig_atomic_t g_stop;
static int32_t g_robot_id;

static void on_signal(int sig)
{
    (void)sig;
    g_stop = 1;
}

void fw_log(const char *what, const char *detail, int32_t value)
{
    fprintf(stderr, "robot %ld: %s%s%s (%ld)\n", (long)g_robot_id, what, detail ? ": " : "", detail ? detail : "",
            (long)value);
}

static uint32_t now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint32_t)((uint64_t)ts.tv_sec * 1000u + (uint64_t)ts.tv_nsec / 1000000u);
}

static void usage(const char *why)
{
    fprintf(stderr,
            "touchline-robot: %s\n"
            "usage: touchline-robot --id N [--team T] [--name NAME] --console HOST:PORT [--port P]\n"
            "                       [--framing legacy|length] [--wifi-sim [--baud B]] [--rate HZ]\n"
            "                       [--reliable] [--reliable-print] [--reliable-send FILE] [--mathe N]\n"
            "                       [--reliable-peer HOST:PORT] [--seed S] [--rto MS]\n"
            "                       [--gc-return HOST[:PORT]] [--gc-return-rate HZ]\n"
            "                       [--team-msg-rate HZ] [--team-msg-to HOST[:PORT]] [--team-key FILE]\n"
            "                       [--match-budget BYTES] [--match-sends N]\n"
            "                       [--boot-file FILE]\n",
            why);
    exit(2);
}

/* The applications on the reliable stream: print what arrives ("Lorem ipsum" receiver),
 * send a file ("Lorem ipsum" sender), and the Mathe game. */
typedef struct {
    bool print;
    bool mathe_on;
    bool mathe_reported;
    mathe_game mathe;
    uint8_t *send_data;
    size_t send_len, send_off;
    uint16_t send_chunk;
    bool send_reported;
} stream_apps;

static void apps_receive(void *ctx, const uint8_t *p, uint16_t n)
{
    stream_apps *a = ctx;
    if (a->mathe_on) {
        mathe_receive(&a->mathe, p, n);
        return;
    }
    if (a->print) {
        fwrite(p, 1, n, stdout);
        fflush(stdout);
    }
}

static void apps_poll(void *ctx, rs_stream *s, uint32_t now)
{
    stream_apps *a = ctx;
    if (a->mathe_on) {
        mathe_poll(&a->mathe, s, now);
        if (mathe_done(&a->mathe) && !a->mathe_reported) {
            a->mathe_reported = true;
            printf("MATHE sent count=%lu result=%lu\n", (unsigned long)a->mathe.sent, (unsigned long)a->mathe.sent_result);
            printf("MATHE received count=%lu result=%lu peer-says count=%lu result=%lu\n",
                   (unsigned long)a->mathe.recv_count, (unsigned long)a->mathe.recv_result,
                   (unsigned long)a->mathe.peer_count, (unsigned long)a->mathe.peer_result);
            printf("MATHE %s\n", mathe_agrees(&a->mathe) ? "OK" : "MISMATCH");
            fflush(stdout);
        }
        return;
    }
    if (a->send_data != NULL && a->send_off < a->send_len && rs_can_send(s)) {
        size_t n = a->send_len - a->send_off;
        if (n > a->send_chunk) n = a->send_chunk;
        if (rs_send(s, a->send_data + a->send_off, (uint16_t)n, now)) a->send_off += n;
    }
    if (a->send_data != NULL && a->send_off == a->send_len && rs_can_send(s) && !a->send_reported) {
        a->send_reported = true;
        fw_log("reliable send complete", 0, (int32_t)a->send_len);
    }
}

/* "host[:port]" -> a peer of the core; port defaults to default_port. 0 on success. */
static int parse_peer(const char *text, uint16_t default_port, wlan_peer *out)
{
    char buf[300];
    struct sockaddr_in a;
    if (strchr(text, ':') == NULL) {
        snprintf(buf, sizeof buf, "%s:%u", text, (unsigned)default_port);
        text = buf;
    }
    if (host_parse_address(text, &a) != 0) return -1;
    memset(out, 0, sizeof *out);
    memcpy(out->ip, &a.sin_addr.s_addr, 4);
    out->port = ntohs(a.sin_port);
    return 0;
}

/* A rate in Hz (decimals allowed) as a period in ms; 0 Hz = off. */
static uint16_t period_of(const char *text, double min_hz, double max_hz, const char *why)
{
    char *end;
    double hz = strtod(text, &end);
    if (*end != '\0' || !(hz == 0.0 || (hz >= min_hz && hz <= max_hz))) usage(why);
    return hz == 0.0 ? 0 : (uint16_t)(1000.0 / hz + 0.5);
}

static uint8_t *read_file(const char *path, size_t *len)
{
    FILE *f = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
    uint8_t *buf = NULL;
    size_t cap = 0, n = 0;
    if (f == NULL) return NULL;
    for (;;) {
        size_t got;
        if (n == cap) {
            cap = cap ? cap * 2 : 65536;
            buf = realloc(buf, cap); /* host side only: the core never allocates */
            if (buf == NULL) exit(1);
        }
        got = fread(buf + n, 1, cap - n, f);
        if (got == 0) break;
        n += got;
    }
    if (f != stdin) fclose(f);
    *len = n;
    return buf;
}

/* Trims spaces and the line end in place. */
static char *trim(char *t)
{
    char *e;
    while (*t == ' ' || *t == '\t') t++;
    e = t + strlen(t);
    while (e > t && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\n' || e[-1] == '\r')) *--e = '\0';
    return t;
}

/* Reads `team.key` (lines "team-key = <64 hex>" and "key-id = <8 hex>", '#' comments);
 * exits with a clear message when the file is missing, unreadable or wrong. */
static void read_team_key(const char *path, fw_team_key *out)
{
    char line[256], key[80] = "", id[16] = "";
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        fprintf(stderr, "touchline-robot: cannot read the team key %s: %s (make one with `touchline keys new`)\n", path,
                strerror(errno));
        exit(2);
    }
    while (fgets(line, sizeof line, f) != NULL) {
        char *t = trim(line), *eq;
        if (*t == '#' || *t == '\0') continue;
        eq = strchr(t, '=');
        if (eq == NULL) continue;
        *eq = '\0';
        if (strcmp(trim(t), "team-key") == 0) snprintf(key, sizeof key, "%s", trim(eq + 1));
        else if (strcmp(trim(t), "key-id") == 0) snprintf(id, sizeof id, "%s", trim(eq + 1));
    }
    fclose(f);
    if (strlen(key) != 64 || strlen(id) != 8 || fw_auth_parse_hex(key, id, out) != 0) {
        fprintf(stderr,
                "touchline-robot: %s is not a team key: it needs 'team-key = ' with 64 hex digits (32 bytes) and "
                "'key-id = ' with 8 (found %zu and %zu); make a new one with `touchline keys new --force`\n",
                path, strlen(key), strlen(id));
        exit(2);
    }
}

/* The boot number (the high word of the robot's own counter), counted up like the board's flash
 * counter: one above the number kept in path (the simulated flash; NULL = none) and never below
 * the clock's seconds, so a lost file does not go back either. Written back before the robot talks. */
static uint32_t next_boot(const char *path)
{
    uint32_t boot = (uint32_t)time(NULL);
    unsigned long kept;
    FILE *f;
    if (path == NULL) return boot;
    f = fopen(path, "r");
    if (f != NULL) {
        if (fscanf(f, "%lu", &kept) == 1 && (uint32_t)kept + 1u > boot) boot = (uint32_t)kept + 1u;
        fclose(f);
    }
    f = fopen(path, "w");
    if (f == NULL || fprintf(f, "%lu\n", (unsigned long)boot) < 0 || fclose(f) != 0) {
        fprintf(stderr, "touchline-robot: cannot keep the boot number in %s: %s\n", path, strerror(errno));
        exit(2);
    }
    return boot;
}

int main(int argc, char **argv)
{
    static fw_team_key team_key;
    static robot_config cfg;
    static stream_apps apps;
    static fw_stream_app app;
    static host_udp udp;
    static host_wifi wifi;
    static wlan_peer peer, gc_return, team_msg;
    struct sockaddr_in console, peer_addr;
    const char *console_arg = NULL, *peer_arg = NULL, *send_path = NULL, *gc_return_arg = NULL, *team_msg_arg = NULL;
    const char *boot_path = NULL;
    char name[32];
    long port = 3838;
    bool wifi_sim = false, have_id = false;
    uint32_t seed = 0, baud = 0;
    int i, fd, actual;
    struct sigaction sa;

    memset(&cfg, 0, sizeof cfg);
    cfg.team_id = 13;
    cfg.framing = FW_FRAMING_LEGACY;
    cfg.rate_hz = 10;
    cfg.reliable_modulus = RS_DEFAULT_MODULUS;
    cfg.name = NULL;
    cfg.gc_return_period_ms = FW_GC_RETURN_PERIOD_MS;
    cfg.team_msg_period_ms = 1000; /* 1 Hz a robot: a few a second over a team */
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
#define NEED_VALUE() do { if (v == NULL) usage("missing value"); i++; } while (0)
        if (strcmp(a, "--id") == 0) { NEED_VALUE(); cfg.robot_id = (int32_t)strtol(v, NULL, 10); have_id = true; }
        else if (strcmp(a, "--team") == 0) { NEED_VALUE(); cfg.team_id = (uint32_t)strtoul(v, NULL, 10); }
        else if (strcmp(a, "--name") == 0) { NEED_VALUE(); cfg.name = v; }
        else if (strcmp(a, "--console") == 0) { NEED_VALUE(); console_arg = v; }
        else if (strcmp(a, "--port") == 0) { NEED_VALUE(); port = strtol(v, NULL, 10); }
        else if (strcmp(a, "--framing") == 0) {
            NEED_VALUE();
            if (strcmp(v, "legacy") == 0) cfg.framing = FW_FRAMING_LEGACY;
            else if (strcmp(v, "length") == 0) cfg.framing = FW_FRAMING_LENGTH;
            else usage("--framing must be legacy or length");
        }
        else if (strcmp(a, "--wifi-sim") == 0) wifi_sim = true;
        else if (strcmp(a, "--baud") == 0) { NEED_VALUE(); baud = (uint32_t)strtoul(v, NULL, 10); }
        else if (strcmp(a, "--rate") == 0) {
            long r;
            NEED_VALUE();
            r = strtol(v, NULL, 10);
            if (r < 1 || r > 1000) usage("--rate must be 1..1000");
            cfg.rate_hz = (uint16_t)r;
        }
        else if (strcmp(a, "--reliable") == 0) cfg.reliable_enabled = true;
        else if (strcmp(a, "--reliable-print") == 0) { cfg.reliable_enabled = true; apps.print = true; }
        else if (strcmp(a, "--reliable-send") == 0) { NEED_VALUE(); cfg.reliable_enabled = true; send_path = v; }
        else if (strcmp(a, "--mathe") == 0) {
            NEED_VALUE();
            cfg.reliable_enabled = true;
            apps.mathe_on = true;
            mathe_init(&apps.mathe, (uint32_t)strtoul(v, NULL, 10), 0);
        }
        else if (strcmp(a, "--reliable-peer") == 0) { NEED_VALUE(); cfg.reliable_enabled = true; peer_arg = v; }
        else if (strcmp(a, "--seed") == 0) { NEED_VALUE(); seed = (uint32_t)strtoul(v, NULL, 10); }
        else if (strcmp(a, "--rto") == 0) { NEED_VALUE(); cfg.reliable_rto_ms = (uint32_t)strtoul(v, NULL, 10); }
        else if (strcmp(a, "--gc-return") == 0) { NEED_VALUE(); gc_return_arg = v; }
        else if (strcmp(a, "--gc-return-rate") == 0) {
            NEED_VALUE();
            cfg.gc_return_period_ms = period_of(v, 0.5, 2.0, "--gc-return-rate must be 0 (off) or 0.5..2");
        }
        else if (strcmp(a, "--team-msg-rate") == 0) {
            NEED_VALUE();
            cfg.team_msg_period_ms = period_of(v, 0.05, 50.0, "--team-msg-rate must be 0 (off) or 0.05..50");
        }
        else if (strcmp(a, "--team-msg-to") == 0) { NEED_VALUE(); team_msg_arg = v; }
        else if (strcmp(a, "--team-key") == 0) {
            NEED_VALUE();
            read_team_key(v, &team_key);
            cfg.team_key = &team_key;
        }
        else if (strcmp(a, "--boot-file") == 0) { NEED_VALUE(); boot_path = v; }
        else if (strcmp(a, "--match-budget") == 0) {
            long b;
            NEED_VALUE();
            b = strtol(v, NULL, 10);
            if (b < 64 || b > (long)FW_MAX_DATAGRAM) usage("--match-budget must be 64..1400");
            cfg.match_budget = (uint16_t)b;
        }
        else if (strcmp(a, "--match-sends") == 0) {
            long n;
            NEED_VALUE();
            n = strtol(v, NULL, 10);
            if (n < 1 || n > 10) usage("--match-sends must be 1..10");
            cfg.match_sends_per_period = (uint8_t)n;
        }
        else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) usage("help");
        else usage("unknown argument");
#undef NEED_VALUE
    }
    if (!have_id) usage("--id is required");
    if (cfg.team_key != NULL) cfg.boot_id = next_boot(boot_path);
    if (console_arg == NULL) usage("--console HOST:PORT is required");
    if (port < 0 || port > 65535) usage("--port must be 0..65535");
    if (host_parse_address(console_arg, &console) != 0) usage("cannot resolve --console address");
    g_robot_id = cfg.robot_id;
    if (cfg.name == NULL) {
        snprintf(name, sizeof name, "robot-%ld", (long)cfg.robot_id);
        cfg.name = name;
    }
    if (apps.mathe_on) mathe_init(&apps.mathe, apps.mathe.total, seed ? seed : (uint32_t)cfg.robot_id * 2654435761u + 1u);
    if (send_path != NULL) {
        apps.send_data = read_file(send_path, &apps.send_len);
        if (apps.send_data == NULL) usage("cannot read --reliable-send file");
        apps.send_chunk = 1000;
    }
    if (peer_arg != NULL) {
        if (host_parse_address(peer_arg, &peer_addr) != 0) usage("cannot resolve --reliable-peer address");
        memcpy(peer.ip, &peer_addr.sin_addr.s_addr, 4);
        peer.port = ntohs(peer_addr.sin_port);
        cfg.reliable_peer = &peer;
    }
    if (gc_return_arg != NULL) {
        if (parse_peer(gc_return_arg, FW_GC_RETURN_PORT, &gc_return) != 0) usage("cannot resolve --gc-return address");
        cfg.gc_return_to = &gc_return;
    }
    if (cfg.team_id < 1 || cfg.team_id > 255) usage("--team must be 1..255 (a GameController team number)");
    {
        /* Team messages go to UDP broadcast on the field; to 127.0.0.1 when the console is on
         * this machine (loopback has no broadcast), so its budget guard hears them. */
        char dflt[16];
        uint32_t host = ntohl(console.sin_addr.s_addr);
        snprintf(dflt, sizeof dflt, "%s", (host >> 24) == 127u ? "127.0.0.1" : "255.255.255.255");
        if (parse_peer(team_msg_arg != NULL ? team_msg_arg : dflt, (uint16_t)(FW_TEAM_MSG_PORT_BASE + cfg.team_id),
                       &team_msg) != 0) {
            usage("cannot resolve --team-msg-to address");
        }
        cfg.team_msg_to = &team_msg;
    }
    cfg.ball = sim_world_ball;
    app.receive = apps_receive;
    app.poll = apps_poll;
    app.ctx = &apps;
    cfg.stream_app = &app;

    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    signal(SIGPIPE, SIG_IGN);

    fd = host_udp_bind((uint16_t)port);
    if (fd < 0) {
        fprintf(stderr, "touchline-robot: cannot bind UDP port %ld: %s\n", port, strerror(errno));
        return 1;
    }
    {
        struct sockaddr_in a;
        socklen_t alen = sizeof a;
        getsockname(fd, (struct sockaddr *)&a, &alen);
        actual = ntohs(a.sin_port);
    }

    sim_world_init(cfg.robot_id);
    cfg.options = sim_world_options(&cfg.option_count);
    cfg.position = sim_world_position;

    if (wifi_sim) {
        if (host_wifi_open(&wifi, fd, &console, (uint16_t)actual, baud) != 0) {
            fprintf(stderr, "touchline-robot: cannot start the simulated GS1500M\n");
            return 1;
        }
        wlan_use(&wifi.driver);
    } else {
        host_udp_open(&udp, fd, &console);
        wlan_use(&udp.driver);
    }
    printf("listening on port %d\n", actual);
    fflush(stdout);
    fprintf(stderr, "robot %ld: sending to %s every %u ms (during READY/SET/PLAYING every %u ms, %u ms under an SPL GameController), %s framing, %s\n",
            (long)cfg.robot_id, console_arg, FW_KEEPALIVE_MS, FW_MATCH_DEBUG_PERIOD_MS, FW_MATCH_DEBUG_PERIOD_SPL_MS, cfg.framing == FW_FRAMING_LEGACY ? "legacy" : "length",
            wifi_sim ? "through the simulated GS1500M" : "direct UDP");
    {
        char to[INET_ADDRSTRLEN];
        inet_ntop(AF_INET, team_msg.ip, to, sizeof to);
        fprintf(stderr, "robot %ld: team messages to %s:%u every %u ms (0 = off), return packets every %u ms\n",
                (long)cfg.robot_id, to, (unsigned)team_msg.port, (unsigned)cfg.team_msg_period_ms,
                (unsigned)cfg.gc_return_period_ms);
    }

    if (cfg.team_key != NULL) {
        fprintf(stderr, "robot %ld: team key %02x%02x%02x%02x: console datagrams checked, own datagrams tagged "
                "(boot %lu)\n", (long)cfg.robot_id, team_key.key_id[0], team_key.key_id[1], team_key.key_id[2],
                team_key.key_id[3], (unsigned long)cfg.boot_id);
    } else {
        fprintf(stderr, "robot %ld: no team key: lab mode (nothing checked or tagged)\n", (long)cfg.robot_id);
    }
    robot_init(&cfg, now_ms());
    while (!g_stop) {
        struct pollfd p;
        robot_poll(now_ms());
        p.fd = wifi_sim ? host_wifi_poll_fd(&wifi) : fd;
        p.events = POLLIN;
        p.revents = 0;
        (void)poll(&p, 1, 2);
    }
    {
        const robot_counters *c = robot_stats();
        fprintf(stderr,
                "robot %ld: stopping; in %lu, handled %lu, malformed %lu, unknown extensions %lu, gc %lu (rejected %lu, "
                "other team %lu, other source %lu), reliable %lu, out %lu (%lu bytes, %lu failed), held in play %lu, "
                "return packets %lu, team messages %lu (held %lu)\n",
                (long)cfg.robot_id, (unsigned long)c->datagrams_in, (unsigned long)c->messages_handled,
                (unsigned long)c->malformed, (unsigned long)c->unknown_ext, (unsigned long)c->gc_packets,
                (unsigned long)c->gc_rejected, (unsigned long)c->gc_other_team, (unsigned long)c->gc_other_source,
                (unsigned long)c->reliable_segments,
                (unsigned long)c->messages_out, (unsigned long)c->bytes_out, (unsigned long)c->send_failures,
                (unsigned long)c->debug_held, (unsigned long)c->gc_returns_out, (unsigned long)c->team_msgs_out,
                (unsigned long)c->team_msgs_held);
        if (cfg.team_key != NULL) {
            const fw_auth_counters *ac = robot_auth_stats();
            fprintf(stderr,
                    "robot %ld: authenticated %lu; rejected: %lu no tag, %lu truncated, %lu wrong key, %lu bad tag, "
                    "%lu replayed\n",
                    (long)cfg.robot_id, (unsigned long)ac->accepted, (unsigned long)ac->missing,
                    (unsigned long)ac->truncated, (unsigned long)ac->wrong_key, (unsigned long)ac->bad_tag,
                    (unsigned long)ac->replayed);
        }
    }
    if (wifi_sim) {
        gs_sim_stats ms;
        const gs_parser_stats *ps = &wifi.gs.parser.stats;
        host_wifi_close(&wifi, &ms);
        fprintf(stderr,
                "robot %ld: GS1500M: serial parser %lu datagrams, %lu lines, %lu garbage lines, %lu resyncs, "
                "%lu oversize; module %lu udp in (%lu dropped), %lu out, %lu failed, %lu bytes lost in %lu overflows\n",
                (long)cfg.robot_id, (unsigned long)ps->datagrams, (unsigned long)ps->lines,
                (unsigned long)ps->garbage_lines, (unsigned long)ps->resyncs, (unsigned long)ps->oversize,
                (unsigned long)ms.udp_in, (unsigned long)ms.udp_dropped, (unsigned long)ms.udp_out,
                (unsigned long)ms.send_failed, (unsigned long)ms.overflow_bytes, (unsigned long)ms.overflow_events);
    }
    close(fd);
    free(apps.send_data);
    return 0;
}
