/* libFuzzer target: an arbitrary datagram on the robot port, through the whole receive
 * path: demultiplexing, both framings, processData and the extension registry, the
 * GameController receiver and the reliable stream. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "fw_registry.h"
#include "fw_robot.h"
#include "sim_world.h"

void fw_log(const char *what, const char *detail, int32_t value) { (void)what; (void)detail; (void)value; }

static bool drv_init(void *ctx, uint32_t now) { (void)ctx; (void)now; return true; }
static bool drv_recv(void *ctx, uint8_t *b, uint16_t cap, uint16_t *len, wlan_peer *from)
{
    (void)ctx; (void)b; (void)cap; (void)len; (void)from;
    return false;
}
static bool drv_send(void *ctx, const uint8_t *m, uint16_t n, char cid)
{
    (void)ctx; (void)m; (void)cid;
    if (n > FW_MAX_DATAGRAM) abort();
    return true;
}
static bool drv_peer(void *ctx, const wlan_peer *to, const uint8_t *m, uint16_t n)
{
    (void)to;
    return drv_send(ctx, m, n, 0);
}
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
        cfg.robot_id = 1;
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
    /* and the bare decoder on the same bytes */
    (void)processData(copy, (uint16_t)size);
    robot_poll(now += 50); /* whatever the input switched on is encoded and sent */
    free(copy);
    return 0;
}
