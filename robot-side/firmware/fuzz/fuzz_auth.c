/* libFuzzer target: the verifier in front of the robot's receive path. Each input goes in
 * twice: as it is (a forgery: must be refused before dispatch, whatever its bytes), and tagged
 * with the robot's own team key and a newer counter (so the fuzzer also reaches everything
 * behind the verifier); then the robot polls, tagging what it sends. Checks: the trailer is
 * refused unless the tag is right, a tagged datagram never grows past the 1400-byte limit. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "fw_auth.h"
#include "fw_robot.h"
#include "sim_world.h"
#include "fuzz_driver.h"

static bool drv_send(void *ctx, const uint8_t *m, uint16_t n, char cid)
{
    (void)ctx; (void)cid;
    if (n > FW_MAX_DATAGRAM) abort();
    if (n < FW_AUTH_TRAILER || !fw_auth_has_trailer(m, n)) abort(); /* with a key everything is tagged */
    return true;
}
static bool drv_peer(void *ctx, const wlan_peer *to, const uint8_t *m, uint16_t n)
{
    (void)ctx; (void)to; (void)m;
    if (n > FW_MAX_DATAGRAM) abort();
    return true;
}
static const wlan_driver drv = {drv_init, drv_recv, drv_send, drv_peer, NULL};
static void sink(void *ctx, const uint8_t *p, uint16_t n) { (void)ctx; (void)p; (void)n; }
static const fw_stream_app app = {sink, NULL, NULL};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static robot_config cfg;
    static fw_team_key key;
    static int ready;
    static uint32_t now = 1;
    static uint64_t counter = 1;
    static uint8_t tagged[FW_MAX_DATAGRAM + FW_AUTH_TRAILER];
    uint8_t *copy;
    uint32_t accepted_before;
    fw_auth_state probe;
    uint16_t payload_len;
    if (!ready) {
        uint8_t i;
        for (i = 0; i < 32; i++) key.key[i] = (uint8_t)(i * 7 + 1);
        key.key_id[0] = 1; key.key_id[1] = 2; key.key_id[2] = 3; key.key_id[3] = 4;
        memset(&cfg, 0, sizeof cfg);
        cfg.robot_id = 3;
        cfg.team_id = 5;
        cfg.name = "fuzz";
        cfg.rate_hz = 10;
        sim_world_init(1);
        cfg.options = sim_world_options(&cfg.option_count);
        cfg.position = sim_world_position;
        cfg.reliable_enabled = true;
        cfg.stream_app = &app;
        cfg.team_key = &key;
        cfg.boot_id = 0x12345678u;
        wlan_use(&drv);
        robot_init(&cfg, now);
        ready = 1;
    }
    if (size > 0xFFFF) return 0;
    copy = malloc(size ? size : 1); /* exact size: ASan sees any overrun */
    memcpy(copy, data, size);
    /* 1. as a forgery: nothing the fuzzer makes up passes the verifier */
    accepted_before = robot_auth_stats()->accepted;
    robot_dispatch(copy, (uint16_t)size, NULL, now);
    if (!(size >= 2 && copy[0] == 'R' && copy[1] == 'G') && robot_auth_stats()->accepted != accepted_before) abort();
    /* the bare verifier with a fresh state (counter check passes; the tag must still fail) */
    fw_auth_init(&probe, &key, 0);
    if (fw_auth_check(&probe, FW_AUTH_DIR_CONSOLE, 3, copy, (uint16_t)size, &payload_len) == FW_AUTH_OK) abort();
    free(copy);
    /* 2. the same bytes tagged right: they reach the whole receive path */
    if (size <= FW_MAX_DATAGRAM) {
        uint16_t n;
        memcpy(tagged, data, size);
        n = fw_auth_append(&key, FW_AUTH_DIR_CONSOLE, 3, 0x12345678u, ++counter, tagged, (uint16_t)size, sizeof tagged);
        copy = malloc(n);
        memcpy(copy, tagged, n);
        robot_dispatch(copy, n, NULL, now);
        free(copy);
    }
    robot_poll(now += 50);
    return 0;
}
