/* The firmware core through the simulated GS1500M over real loopback UDP: start-up with
 * AT commands, keep-alives reach the console, a flood overflows the module's 1400-byte
 * buffer (cut-off headers reach the parser), the robot survives and still answers, and a
 * dropped connection (DISCONNECT) is re-opened. */
#define _POSIX_C_SOURCE 200809L
#include <arpa/inet.h>
#include <poll.h>
#include <string.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>
#include "fw_robot.h"
#include "host_udp.h"
#include "host_wifi.h"
#include "sim_world.h"
#include "test_util.h"

static uint32_t now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint32_t)((uint64_t)ts.tv_sec * 1000u + (uint64_t)ts.tv_nsec / 1000000u);
}

static int console_fd;
static struct sockaddr_in robot_addr;
static int status_seen, text_seen;

/* Runs the robot for ms milliseconds, counting Status (ext 23) and DebugText (ext 43). */
static void run(host_wifi *w, uint32_t ms)
{
    uint32_t end = now_ms() + ms;
    (void)w;
    while ((int32_t)(now_ms() - end) < 0) {
        uint8_t buf[2048];
        ssize_t n;
        struct pollfd p = {host_wifi_poll_fd(w), POLLIN, 0};
        robot_poll(now_ms());
        (void)poll(&p, 1, 1);
        while ((n = recv(console_fd, buf, sizeof buf, MSG_DONTWAIT)) > 0) {
            /* legacy header, then 08 <id> then the extension tag: 0xBA 0x01 = 23, 0xDA 0x02 = 43 */
            if (n > 15 && buf[12] == 0x08 && buf[14] == 0xBA && buf[15] == 0x01) status_seen++;
            if (n > 15 && buf[12] == 0x08 && buf[14] == 0xDA && buf[15] == 0x02) text_seen++;
        }
    }
}

/* Runs the robot until *count reaches want, or for at most limit_ms: a condition, not a sleep
 * (a loaded machine slows the simulated serial line, it does not change what arrives). */
static void run_until(host_wifi *w, const int *count, int want, uint32_t limit_ms)
{
    uint32_t end = now_ms() + limit_ms;
    while (*count < want && (int32_t)(now_ms() - end) < 0) {
        run(w, 50);
    }
}

int main(void)
{
    static host_wifi w;
    static robot_config cfg;
    struct sockaddr_in console;
    socklen_t l = sizeof console;
    uint16_t port;
    int udp_fd, flood_fd, i;
    gs_sim_stats ms;

    console_fd = socket(AF_INET, SOCK_DGRAM, 0);
    memset(&console, 0, sizeof console);
    console.sin_family = AF_INET;
    console.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    bind(console_fd, (struct sockaddr *)&console, sizeof console);
    getsockname(console_fd, (struct sockaddr *)&console, &l);
    udp_fd = host_udp_bind(0);
    CHECK(udp_fd >= 0);
    l = sizeof robot_addr;
    getsockname(udp_fd, (struct sockaddr *)&robot_addr, &l);
    port = ntohs(robot_addr.sin_port);
    robot_addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    CHECK_EQ(host_wifi_open(&w, udp_fd, &console, port, 0), 0);
    wlan_use(&w.driver);

    memset(&cfg, 0, sizeof cfg);
    cfg.robot_id = 4;
    cfg.team_id = 13;
    cfg.name = "wifi";
    cfg.rate_hz = 10;
    sim_world_init(4);
    cfg.options = sim_world_options(&cfg.option_count);
    robot_init(&cfg, now_ms());

    run_until(&w, &status_seen, 3, 10000);
    CHECK(robot_network_ready());
    CHECK(status_seen >= 3);

    /* flood: 400 GameController packets of 688 bytes (275 kB) as fast as possible */
    flood_fd = socket(AF_INET, SOCK_DGRAM, 0);
    {
        static uint8_t gc[688];
        memcpy(gc, "RGme", 4);
        gc[4] = 12;
        for (i = 0; i < 400; i++) {
            /* INITIAL and FINISHED only: in READY/SET/PLAYING the robot would keep to the
             * game's debug limit, and the checks below count lab-rate traffic */
            gc[9] = (uint8_t)((i % 2) * 4);
            (void)sendto(flood_fd, gc, sizeof gc, 0, (struct sockaddr *)&robot_addr, sizeof robot_addr);
            if (i % 50 == 0) robot_poll(now_ms());
        }
    }
    run(&w, 1500);
    CHECK(robot_stats()->gc_packets > 0);
    /* cut-off headers were seen and survived; the frame already on the line is never
     * torn, so no mixture of two datagrams reaches the decoder */
    CHECK(w.gs.parser.stats.resyncs + w.gs.parser.stats.garbage_lines > 0);
    CHECK_EQ(robot_stats()->malformed, 0);

    /* still answering: switch demo.text on from the console */
    {
        static const uint8_t req[] = {0, 42, 0, 0, 0, 0, 0, 0, 0, 0, 0, 18,
                                      0x08, 0x64, 0xD2, 0x02, 0x0D, 0x0A, 0x09, 'd', 'e', 'm', 'o', '.', 't', 'e', 'x', 't', 0x10, 0x01};
        text_seen = 0;
        sendto(console_fd, req, sizeof req, 0, (struct sockaddr *)&robot_addr, sizeof robot_addr);
        run_until(&w, &text_seen, 5, 10000);
        CHECK(robot_option_enabled("demo.text"));
        CHECK(text_seen >= 5);
    }

    /* the module drops the console connection: the driver re-opens it, keep-alives resume */
    gs_sim_disconnect(w.module, '1');
    run(&w, 300);
    status_seen = 0;
    run_until(&w, &status_seen, 4, 10000);
    CHECK(w.gs.stats.disconnects == 1);
    CHECK(robot_network_ready());
    CHECK(status_seen >= 4);

    host_wifi_close(&w, &ms);
    printf("module: %u udp in, %u dropped, %u bytes lost in %u overflows; parser: %u datagrams, %u resyncs, "
           "%u garbage lines; robot: %u gc packets, %u malformed\n",
           ms.udp_in, ms.udp_dropped, ms.overflow_bytes, ms.overflow_events, w.gs.parser.stats.datagrams,
           w.gs.parser.stats.resyncs, w.gs.parser.stats.garbage_lines, robot_stats()->gc_packets,
           robot_stats()->malformed);
    CHECK(ms.overflow_events > 0);
    close(udp_fd);
    close(flood_fd);
    close(console_fd);
    TEST_DONE();
}
