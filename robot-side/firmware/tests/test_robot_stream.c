/* End to end over real UDP on loopback: starts touchline-robot (direct UDP or --wifi-sim)
 * and plays the thesis' "Lorem ipsum" and "Mathe" tests against it with this process as
 * the peer, through a lossy link (20% drop, 20% duplicates, 20% delayed/reordered in
 * each direction). Usage: fw_test_robot_stream PATH_TO_touchline-robot direct|wifi
 *
 * With "hsl GOLDEN_GAMECONTROLLER_DIR" instead it plays the HSL GameController (the
 * official v20 PLAYING datagram every 500 ms) and checks what the robot sends back: return
 * packets v4 to --gc-return, team messages to --team-msg-to, Status saying PLAYING. */
#define _POSIX_C_SOURCE 200809L
#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "fw_framing.h"
#include "fw_mathe.h"
#include "fw_reliable.h"
#include "test_util.h"

static const char *g_bin;
static int g_wifi;

static uint32_t now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint32_t)((uint64_t)ts.tv_sec * 1000u + (uint64_t)ts.tv_nsec / 1000000u);
}

static int udp_socket(uint16_t *port)
{
    struct sockaddr_in a;
    socklen_t l = sizeof a;
    int fd = socket(AF_INET, SOCK_DGRAM, 0);
    memset(&a, 0, sizeof a);
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (fd < 0 || bind(fd, (struct sockaddr *)&a, sizeof a) != 0) exit(3);
    getsockname(fd, (struct sockaddr *)&a, &l);
    *port = ntohs(a.sin_port);
    return fd;
}

typedef struct {
    pid_t pid;
    int out;   /* robot stdout, non-blocking */
    uint16_t port;
    char text[65536];
    size_t len;
} robot_proc;

static void start_robot(robot_proc *r, uint16_t console_port, const char *id, const char *const extra[])
{
    int p[2];
    char console[32];
    const char *argv[24];
    int n = 0, i;
    snprintf(console, sizeof console, "127.0.0.1:%u", console_port);
    argv[n++] = g_bin;
    argv[n++] = "--id";
    argv[n++] = id;
    argv[n++] = "--console";
    argv[n++] = console;
    argv[n++] = "--port";
    argv[n++] = "0";
    argv[n++] = "--rto";
    argv[n++] = "40";
    if (g_wifi) argv[n++] = "--wifi-sim";
    for (i = 0; extra[i] != NULL; i++) argv[n++] = extra[i];
    argv[n] = NULL;
    if (pipe(p) != 0) exit(3);
    r->pid = fork();
    if (r->pid == 0) {
        dup2(p[1], 1);
        close(p[0]);
        execv(g_bin, (char *const *)argv);
        _exit(127);
    }
    close(p[1]);
    r->out = p[0];
    r->len = 0;
    {
        /* first line: "listening on port N" */
        char line[64];
        size_t k = 0;
        while (k + 1 < sizeof line && read(r->out, line + k, 1) == 1 && line[k] != '\n') k++;
        line[k] = '\0';
        CHECK(strncmp(line, "listening on port ", 18) == 0);
        r->port = (uint16_t)atoi(line + 18);
    }
    fcntl(r->out, F_SETFL, O_NONBLOCK);
}

static void read_robot(robot_proc *r)
{
    ssize_t n;
    while (r->len + 1 < sizeof r->text && (n = read(r->out, r->text + r->len, sizeof r->text - 1 - r->len)) > 0) {
        r->len += (size_t)n;
    }
    r->text[r->len] = '\0';
}

static int stop_robot(robot_proc *r)
{
    int status = 0;
    kill(r->pid, SIGTERM);
    waitpid(r->pid, &status, 0);
    close(r->out);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

/* ---- the peer: an rs_stream on a UDP socket, with loss injected both ways ---- */
#define DELAYED 256
typedef struct {
    uint32_t due;
    uint16_t n;
    int inbound;
    uint8_t d[1400];
} delayed_pkt;

static struct {
    int fd;
    struct sockaddr_in robot;
    rs_stream s;
    uint32_t rng;
    delayed_pkt q[DELAYED];
    int qn;
    uint32_t dropped, duplicated, delayed;
} P;

static uint32_t rnd(void)
{
    P.rng ^= P.rng << 13;
    P.rng ^= P.rng >> 17;
    P.rng ^= P.rng << 5;
    return P.rng;
}

static void deliver_now(const uint8_t *d, uint16_t n, int inbound);

/* 20% dropped, 20% duplicated, 20% held back 5..40 ms (so later ones overtake them). */
static void lossy(const uint8_t *d, uint16_t n, int inbound)
{
    int copies = 1, c;
    if (rnd() % 100u < 20u) {
        P.dropped++;
        return;
    }
    if (rnd() % 100u < 20u) {
        P.duplicated++;
        copies = 2;
    }
    for (c = 0; c < copies; c++) {
        if (rnd() % 100u < 20u && P.qn < DELAYED) {
            delayed_pkt *k = &P.q[P.qn++];
            k->due = now_ms() + 5u + rnd() % 36u;
            k->n = n;
            k->inbound = inbound;
            memcpy(k->d, d, n);
            P.delayed++;
        } else {
            deliver_now(d, n, inbound);
        }
    }
}

static void deliver_now(const uint8_t *d, uint16_t n, int inbound)
{
    if (inbound) rs_input(&P.s, d, n, now_ms());
    else (void)sendto(P.fd, d, n, 0, (struct sockaddr *)&P.robot, sizeof P.robot);
}

static int peer_output(void *ctx, const uint8_t hdr[2], const uint8_t *p, uint16_t n)
{
    uint8_t seg[1400];
    (void)ctx;
    seg[0] = hdr[0];
    seg[1] = hdr[1];
    if (n) memcpy(seg + 2, p, n);
    lossy(seg, (uint16_t)(n + 2), 0);
    return 1;
}

static void peer_pump(void)
{
    uint8_t buf[1500];
    int i = 0;
    struct pollfd pf = {P.fd, POLLIN, 0};
    (void)poll(&pf, 1, 1);
    for (;;) {
        ssize_t n = recv(P.fd, buf, sizeof buf, MSG_DONTWAIT);
        fw_datagram_info info;
        if (n <= 0) break;
        fw_classify(buf, (size_t)n, &info);
        if (info.kind == FW_DGRAM_RELIABLE) lossy(buf, (uint16_t)n, 1); /* keep-alives etc. ignored */
    }
    while (i < P.qn) {
        if ((int32_t)(now_ms() - P.q[i].due) >= 0) {
            delayed_pkt k = P.q[i];
            P.q[i] = P.q[--P.qn];
            deliver_now(k.d, k.n, k.inbound);
        } else {
            i++;
        }
    }
    rs_poll(&P.s, now_ms());
}

static void peer_init(int fd, uint16_t robot_port, rs_deliver_fn deliver, void *ctx, uint32_t seed)
{
    memset(&P, 0, sizeof P);
    P.fd = fd;
    P.rng = seed;
    P.robot.sin_family = AF_INET;
    P.robot.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    P.robot.sin_port = htons(robot_port);
    rs_init(&P.s, RS_DEFAULT_MODULUS, 40, 250, peer_output, deliver, ctx, now_ms());
}

/* ---- Lorem ipsum: the peer sends, the robot prints ---- */
static void test_lorem(void)
{
    static robot_proc r;
    static uint8_t text[6000];
    static const char *const extra[] = {"--reliable-print", NULL};
    const char *words = "Lorem ipsum dolor sit amet, consectetur adipiscing elit. ";
    uint16_t console_port, peer_port;
    int console_fd = udp_socket(&console_port), peer_fd = udp_socket(&peer_port);
    size_t i, off = 0, wl = strlen(words);
    uint32_t deadline;
    for (i = 0; i < sizeof text; i++) text[i] = (uint8_t)words[i % wl];
    for (i = 0; i + 6 < sizeof text; i += 200) {
        char tag[8];
        snprintf(tag, sizeof tag, "<%04zu>", i / 200);
        memcpy(text + i, tag, 6);
    }
    start_robot(&r, console_port, "7", extra);
    /* a separate peer address: in --wifi-sim this is the module's UDP-server path
     * (ESC y in, ESC Y out); the console's own address would use ESC Z */
    peer_init(peer_fd, r.port, NULL, NULL, 0x1234567u);
    deadline = now_ms() + 30000u;
    while ((int32_t)(now_ms() - deadline) < 0) {
        if (off < sizeof text && rs_can_send(&P.s)) {
            size_t n = sizeof text - off < 700 ? sizeof text - off : 700;
            if (rs_send(&P.s, text + off, (uint16_t)n, now_ms())) off += n;
        }
        peer_pump();
        read_robot(&r);
        if (r.len >= sizeof text) break;
    }
    CHECK_EQ(r.len, sizeof text);
    CHECK(memcmp(r.text, text, sizeof text) == 0);
    CHECK(P.dropped > 0);
    printf("lorem (%s): %zu bytes in order; peer dropped %u, duplicated %u, delayed %u, retransmitted %u\n",
           g_wifi ? "wifi-sim" : "direct", r.len, P.dropped, P.duplicated, P.delayed, P.s.stats.retransmissions);
    CHECK_EQ(stop_robot(&r), 0);
    close(console_fd);
    close(peer_fd);
}

/* ---- Mathe: both sides at once ---- */
static mathe_game game;
static void to_game(void *ctx, const uint8_t *p, uint16_t n)
{
    (void)ctx;
    mathe_receive(&game, p, n);
}

static void test_mathe(void)
{
    static robot_proc r;
    static const char *const extra[] = {"--mathe", "60", "--seed", "99", NULL};
    uint16_t console_port;
    int console_fd = udp_socket(&console_port);
    uint32_t deadline;
    start_robot(&r, console_port, "7", extra);
    /* the robot starts the game towards the console address: play it from there */
    peer_init(console_fd, r.port, to_game, NULL, 0x7654321u);
    mathe_init(&game, 50, 4242);
    deadline = now_ms() + 40000u;
    while ((int32_t)(now_ms() - deadline) < 0) {
        mathe_poll(&game, &P.s, now_ms());
        peer_pump();
        read_robot(&r);
        if (mathe_done(&game) && (strstr(r.text, "MATHE OK\n") || strstr(r.text, "MATHE MISMATCH\n"))) break;
    }
    CHECK(mathe_done(&game));
    CHECK(mathe_agrees(&game));
    CHECK_EQ(game.peer_count, 60);
    CHECK(strstr(r.text, "MATHE OK") != NULL);
    CHECK(strstr(r.text, "MATHE MISMATCH") == NULL);
    {
        char expect[64];
        snprintf(expect, sizeof expect, "received count=50 result=%lu", (unsigned long)game.sent_result);
        CHECK(strstr(r.text, expect) != NULL);
    }
    printf("mathe (%s): peer got %u operands, result %u; robot says:\n%s", g_wifi ? "wifi-sim" : "direct",
           game.recv_count, game.recv_result, r.text);
    CHECK_EQ(stop_robot(&r), 0);
    close(console_fd);
}

/* ---- an HSL game: the official v20 datagram in, return packets and team messages out ---- */
static void test_hsl(const char *golden_dir)
{
    static robot_proc r;
    static uint8_t playing[256], buf[2048];
    char path[1024], ret_arg[32], team_arg[32];
    uint16_t console_port, gc_port, ret_port, team_port;
    int console_fd = udp_socket(&console_port), gc_fd = udp_socket(&gc_port);
    int ret_fd = udp_socket(&ret_port), team_fd = udp_socket(&team_port);
    int returns = 0, team_msgs = 0, playing_status = 0;
    size_t np;
    uint32_t deadline, next_gc = 0;
    struct sockaddr_in robot;
    FILE *f;
    const char *extra[] = {"--team", "5", "--gc-return", ret_arg, "--team-msg-to", team_arg,
                           "--team-msg-rate", "10", "--gc-return-rate", "2", NULL};
    snprintf(path, sizeof path, "%s/hsl20/07-playing-after-delay.bin", golden_dir);
    f = fopen(path, "rb");
    if (f == NULL) exit(3);
    np = fread(playing, 1, sizeof playing, f);
    fclose(f);
    CHECK_EQ(np, 158);
    snprintf(ret_arg, sizeof ret_arg, "127.0.0.1:%u", ret_port);
    snprintf(team_arg, sizeof team_arg, "127.0.0.1:%u", team_port);
    start_robot(&r, console_port, "3", extra);
    memset(&robot, 0, sizeof robot);
    robot.sin_family = AF_INET;
    robot.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    robot.sin_port = htons(r.port);
    deadline = now_ms() + 30000u;
    while ((int32_t)(now_ms() - deadline) < 0 && (returns < 3 || team_msgs < 5 || playing_status < 1)) {
        struct pollfd p[3] = {{console_fd, POLLIN, 0}, {ret_fd, POLLIN, 0}, {team_fd, POLLIN, 0}};
        ssize_t n;
        if ((int32_t)(now_ms() - next_gc) >= 0) { /* the GameController's own cadence */
            sendto(gc_fd, playing, np, 0, (struct sockaddr *)&robot, sizeof robot);
            next_gc = now_ms() + 500u;
        }
        (void)poll(p, 3, 50);
        while ((n = recv(console_fd, buf, sizeof buf, MSG_DONTWAIT)) > 0) {
            size_t i;
            for (i = 0; i + 7 <= (size_t)n; i++) {
                if (memcmp(buf + i, "PLAYING", 7) == 0) playing_status++;
            }
        }
        while ((n = recv(ret_fd, buf, sizeof buf, MSG_DONTWAIT)) > 0) {
            returns++;
            CHECK_EQ(n, 32);
            CHECK(memcmp(buf, "RGrt", 4) == 0);
            CHECK_EQ(buf[4], 4);
            CHECK_EQ(buf[5], 3);
            CHECK_EQ(buf[6], 5);
            CHECK_EQ(buf[7], 0);
        }
        while ((n = recv(team_fd, buf, sizeof buf, MSG_DONTWAIT)) > 0) {
            team_msgs++;
            CHECK(n <= 512);
            CHECK(memcmp(buf, "FUtm", 4) == 0);
            CHECK_EQ(buf[5], 3);
            CHECK_EQ(buf[6], 5);
        }
    }
    CHECK(returns >= 3);
    CHECK(team_msgs >= 5);
    CHECK(playing_status >= 1);
    printf("hsl (%s): %d return packets, %d team messages, %d Status saying PLAYING\n", g_wifi ? "wifi-sim" : "direct",
           returns, team_msgs, playing_status);
    CHECK_EQ(stop_robot(&r), 0);
    close(console_fd);
    close(gc_fd);
    close(ret_fd);
    close(team_fd);
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: %s TOUCHLINE_ROBOT direct|wifi [hsl GOLDEN_GAMECONTROLLER_DIR]\n", argv[0]);
        return 2;
    }
    signal(SIGPIPE, SIG_IGN);
    g_bin = argv[1];
    g_wifi = strcmp(argv[2], "wifi") == 0;
    if (argc == 5 && strcmp(argv[3], "hsl") == 0) {
        test_hsl(argv[4]);
        TEST_DONE();
    }
    test_lorem();
    test_mathe();
    TEST_DONE();
}
