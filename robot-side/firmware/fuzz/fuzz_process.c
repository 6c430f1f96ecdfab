/* libFuzzer target: an arbitrary datagram on the robot port, through the whole receive
 * path: demultiplexing, both framings, processData and the extension registry, the
 * GameController receiver (all layouts incl. HSL v19/v20, own team and player, return
 * packets and team messages that follow) and the reliable stream. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "fw_gamecontroller.h"
#include "fw_registry.h"
#include "fw_robot.h"
#include "sim_world.h"
#include "fuzz_driver.h"

static bool drv_send(void *ctx, const uint8_t *m, uint16_t n, char cid)
{
    (void)ctx; (void)m; (void)cid;
    if (n > FW_MAX_DATAGRAM) abort();
    return true;
}
static bool drv_peer(void *ctx, const wlan_peer *to, const uint8_t *m, uint16_t n)
{
    if (to->port == 3939 && n != 32) abort();   /* return packets are exactly 32 bytes */
    if (to->port >= 10000 && n > 512) abort();  /* team messages within the HSL limit */
    return drv_send(ctx, m, n, 0);
}
static const wlan_peer team_to = {0, {127, 0, 0, 1}, 10005};
static const wlan_driver drv = {drv_init, drv_recv, drv_send, drv_peer, NULL};

static void sink(void *ctx, const uint8_t *p, uint16_t n) { (void)ctx; (void)p; (void)n; }
static const fw_stream_app app = {sink, NULL, NULL};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static robot_config cfg;
    static int ready;
    static uint32_t now = 1;
    uint8_t *copy;
    if (!ready) {
        memset(&cfg, 0, sizeof cfg);
        cfg.robot_id = 4; /* team 5's player 4 is penalised in the corpus' v20 "motion in stop" */
        cfg.team_id = 5;
        cfg.gc_return_period_ms = 1000;
        cfg.team_msg_period_ms = 100;
        cfg.team_msg_to = &team_to;
        cfg.ball = sim_world_ball;
        cfg.name = "fuzz";
        cfg.rate_hz = 10;
        sim_world_init(1);
        cfg.options = sim_world_options(&cfg.option_count);
        cfg.position = sim_world_position;
        cfg.reliable_enabled = true;
        cfg.stream_app = &app;
        wlan_use(&drv);
        robot_init(&cfg, now);
        ready = 1;
    }
    if (size > 0xFFFF) return 0;
    copy = malloc(size ? size : 1); /* exact size: ASan sees any overrun */
    memcpy(copy, data, size);
    robot_dispatch(copy, (uint16_t)size, NULL, now);
    {
        /* the bare GameController parser, looking up a team number taken from the input */
        fw_gc_info info;
        (void)fw_gc_parse(copy, size, size ? copy[size - 1] : 0, size > 1 ? copy[size - 2] : 0, &info);
    }
    /* and the bare decoder on the same bytes */
    (void)processData(copy, (uint16_t)size);
    robot_poll(now += 50); /* whatever the input switched on is encoded and sent */
    free(copy);
    return 0;
}
