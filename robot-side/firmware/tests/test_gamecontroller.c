/* The GameController receiver on the official HSL GameController's own datagrams (the golden
 * step files of src/test/resources/golden/gamecontroller/hsl20 and hsl19, path passed by
 * CMake), and the robot following an HSL game against a fake network driver: the debug
 * limit during play, standing still while penalised or stopped, return packets v4 to the
 * GameController, team messages and their budget, bad datagrams rejected and counted.
 *
 * usage: fw_test_gamecontroller GOLDEN_GAMECONTROLLER_DIR */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fw_gamecontroller.h"
#include "fw_registry.h"
#include "fw_robot.h"
#include "sim_world.h"
#include "test_util.h"

static const char *g_golden_dir;

/* Reads one golden file (e.g. "hsl20/07-playing-after-delay.bin"); aborts if it is missing. */
static size_t golden(const char *name, uint8_t *buf, size_t cap)
{
    char path[1024];
    FILE *f;
    size_t n;
    snprintf(path, sizeof path, "%s/%s", g_golden_dir, name);
    f = fopen(path, "rb");
    if (f == NULL) {
        fprintf(stderr, "missing golden file %s\n", path);
        exit(1);
    }
    n = fread(buf, 1, cap, f);
    fclose(f);
    return n;
}

static float get_f32(const uint8_t *p)
{
    union { float f; uint32_t u; } v;
    v.u = (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
    return v.f;
}

/* ---- the parser on the official bytes ---- */

static void test_v20_fields(void)
{
    static uint8_t d[256];
    fw_gc_info g;
    size_t n = golden("hsl20/07-playing-after-delay.bin", d, sizeof d);
    CHECK_EQ(n, 158);
    CHECK_EQ(fw_gc_parse(d, n, 5, 1, &g), FW_GC_OK);
    CHECK_EQ(g.version, 20);
    CHECK_EQ(g.state, FW_GC_PLAYING);
    CHECK_EQ(g.packet_number, 91);
    CHECK(g.has_game_fields);
    CHECK_EQ(g.players_per_team, 5);
    CHECK_EQ(g.stopped, 0);
    CHECK_EQ(g.game_phase, 0);
    CHECK_EQ(g.set_play, 0);
    CHECK_EQ(g.first_half, 1);
    CHECK_EQ(g.kicking_team, 255);
    CHECK_EQ(g.secs_remaining, 590);
    CHECK_EQ(g.secondary_time, 0);
    CHECK_EQ(g.team_numbers[0], 5);
    CHECK_EQ(g.team_numbers[1], 14);
    CHECK(g.own_team_found);
    CHECK_EQ(g.own_side, 0);
    CHECK_EQ(g.message_budget, 11997);
    CHECK(g.own_player_found);
    CHECK_EQ(g.penalty, 0);
    CHECK(!fw_gc_penalised(&g));
    /* the other team, in the other slot */
    CHECK_EQ(fw_gc_parse(d, n, 14, 1, &g), FW_GC_OK);
    CHECK_EQ(g.own_side, 1);
    CHECK_EQ(g.message_budget, 11999);
    /* a team that does not play: state yes, own fields no */
    CHECK_EQ(fw_gc_parse(d, n, 13, 1, &g), FW_GC_OK);
    CHECK_EQ(g.state, FW_GC_PLAYING);
    CHECK(!g.own_team_found);
    CHECK(!g.own_player_found);
    /* players 6-20 are substitutes: not on the field is penalised too */
    CHECK_EQ(fw_gc_parse(d, n, 5, 6, &g), FW_GC_OK);
    CHECK_EQ(g.penalty, FW_GC_V20_SUBSTITUTE);
    CHECK(fw_gc_penalised(&g));
}

static void test_v20_game_steps(void)
{
    static uint8_t d[256];
    fw_gc_info g;
    size_t n;
    /* after the kick-off whistle robots see SET for 10 s ("fake SET") */
    n = golden("hsl20/05-playing-delayed.bin", d, sizeof d);
    CHECK_EQ(fw_gc_parse(d, n, 5, 1, &g), FW_GC_OK);
    CHECK_EQ(g.state, FW_GC_SET);
    CHECK_EQ(g.kicking_team, 5);
    /* the monitors' true copy of the same instant is not for robots */
    n = golden("hsl20/05-playing-delayed.monitor.bin", d, sizeof d);
    CHECK_EQ(n, 158);
    CHECK_EQ(fw_gc_parse(d, n, 5, 1, &g), FW_GC_BAD_MAGIC);
    /* corner kick: play stopped */
    n = golden("hsl20/08-corner-kick-team14-stopped.bin", d, sizeof d);
    CHECK_EQ(fw_gc_parse(d, n, 14, 1, &g), FW_GC_OK);
    CHECK_EQ(g.state, FW_GC_PLAYING);
    CHECK_EQ(g.stopped, 1);
    CHECK_EQ(g.set_play, 6);
    CHECK_EQ(g.kicking_team, 14);
    CHECK_EQ(g.secondary_time, 45);
    n = golden("hsl20/10-corner-kick-resumed.bin", d, sizeof d);
    CHECK_EQ(fw_gc_parse(d, n, 14, 1, &g), FW_GC_OK);
    CHECK_EQ(g.stopped, 0);
    CHECK_EQ(g.set_play, 6);
    /* team timeout: INITIAL with game phase TIMEOUT */
    n = golden("hsl20/14-timeout-team14.bin", d, sizeof d);
    CHECK_EQ(fw_gc_parse(d, n, 14, 1, &g), FW_GC_OK);
    CHECK_EQ(g.state, FW_GC_INITIAL);
    CHECK_EQ(g.game_phase, 3);
    /* motion in set: penalised with its 15 s */
    n = golden("hsl20/18-motion-in-set-team14-player2.bin", d, sizeof d);
    CHECK_EQ(fw_gc_parse(d, n, 14, 2, &g), FW_GC_OK);
    CHECK_EQ(g.penalty, 2);
    CHECK_EQ(g.secs_till_unpenalised, 15);
    CHECK_EQ(fw_gc_parse(d, n, 14, 3, &g), FW_GC_OK);
    CHECK_EQ(g.penalty, 0);
    /* pushing: 0 s until the operator starts the timer, then 45 s, and penalised at 0 */
    n = golden("hsl20/22-pushing-team14-player3.bin", d, sizeof d);
    CHECK_EQ(fw_gc_parse(d, n, 14, 3, &g), FW_GC_OK);
    CHECK_EQ(g.penalty, 10);
    CHECK_EQ(g.secs_till_unpenalised, 0);
    n = golden("hsl20/23-pushing-timer-started.bin", d, sizeof d);
    CHECK_EQ(fw_gc_parse(d, n, 14, 3, &g), FW_GC_OK);
    CHECK_EQ(g.secs_till_unpenalised, 45);
    n = golden("hsl20/25-pushing-timer-elapsed.bin", d, sizeof d);
    CHECK_EQ(fw_gc_parse(d, n, 14, 3, &g), FW_GC_OK);
    CHECK_EQ(g.secs_till_unpenalised, 0);
    CHECK(fw_gc_penalised(&g));
    /* second half: the teams swapped slots; team 5's player 2 stays sent off */
    n = golden("hsl20/39-second-half-initial.bin", d, sizeof d);
    CHECK_EQ(fw_gc_parse(d, n, 5, 2, &g), FW_GC_OK);
    CHECK_EQ(g.first_half, 0);
    CHECK_EQ(g.own_side, 1);
    CHECK_EQ(g.message_budget, 12597);
    CHECK_EQ(g.penalty, FW_GC_V20_SENT_OFF);
    /* dropped ball: nobody kicks */
    n = golden("hsl20/47-dropped-ball-playing.bin", d, sizeof d);
    CHECK_EQ(fw_gc_parse(d, n, 5, 1, &g), FW_GC_OK);
    CHECK_EQ(g.kicking_team, FW_GC_KICKING_TEAM_NONE);
    CHECK_EQ(g.state, FW_GC_PLAYING);
}

static void test_v19(void)
{
    static uint8_t d[256];
    fw_gc_info g;
    size_t n = golden("hsl19/07-playing-after-delay.bin", d, sizeof d);
    CHECK_EQ(n, 198);
    CHECK_EQ(fw_gc_parse(d, n, 5, 1, &g), FW_GC_OK);
    CHECK_EQ(g.version, 19);
    CHECK_EQ(g.state, FW_GC_PLAYING);
    CHECK_EQ(g.secs_remaining, 590);
    CHECK_EQ(g.message_budget, 11997);
    /* RobotInfo is 4 bytes in v19: player 3 of the second team is at 18 + 90 + 10 + 8 */
    n = golden("hsl19/23-pushing-after-20s.bin", d, sizeof d);
    CHECK_EQ(fw_gc_parse(d, n, 14, 3, &g), FW_GC_OK);
    CHECK_EQ(g.penalty, 9); /* PUSHING is 9 in v19, 10 in v20 */
    CHECK_EQ(g.secs_till_unpenalised, 10);
    CHECK_EQ(fw_gc_parse(d, n, 14, 2, &g), FW_GC_OK);
    CHECK_EQ(g.penalty, 0);
    CHECK_EQ(fw_gc_parse(d, n, 14, 4, &g), FW_GC_OK);
    CHECK_EQ(g.penalty, 0);
    n = golden("hsl19/39-second-half-set.bin", d, sizeof d);
    CHECK_EQ(fw_gc_parse(d, n, 14, 1, &g), FW_GC_OK);
    CHECK_EQ(g.state, FW_GC_SET);
    CHECK_EQ(g.own_side, 0);
    CHECK_EQ(g.message_budget, 12599);
}

static void test_rejected(void)
{
    static uint8_t d[256], v19[256];
    fw_gc_info g;
    size_t n = golden("hsl20/07-playing-after-delay.bin", d, sizeof d);
    (void)golden("hsl19/07-playing-after-delay.bin", v19, sizeof v19);
    CHECK_EQ(fw_gc_parse(d, n - 1, 5, 1, &g), FW_GC_BAD_LENGTH);
    CHECK_EQ(fw_gc_parse(d, n + 1, 5, 1, &g), FW_GC_BAD_LENGTH);
    CHECK_EQ(fw_gc_parse(d, 118, 5, 1, &g), FW_GC_BAD_LENGTH); /* SPL v18's size with version 20 */
    CHECK_EQ(fw_gc_parse(v19, 158, 5, 1, &g), FW_GC_BAD_LENGTH); /* v19 cut to v20's size */
    d[4] = 21;
    CHECK_EQ(fw_gc_parse(d, n, 5, 1, &g), FW_GC_BAD_VERSION);
    /* 158 bytes with version 8 are the 2014 packet: state at offset 7 (here: competitionType 1) */
    d[4] = 8;
    CHECK_EQ(fw_gc_parse(d, n, 5, 1, &g), FW_GC_OK);
    CHECK_EQ(g.version, 8);
    CHECK_EQ(g.state, 1);
    CHECK(!g.has_game_fields);
    CHECK(!g.own_team_found);
    d[4] = 20;
    /* values out of range */
    d[10] = 5; /* no STANDBY in HSL */
    CHECK_EQ(fw_gc_parse(d, n, 5, 1, &g), FW_GC_BAD_VALUE);
    d[10] = 3;
    d[8] = 2;
    CHECK_EQ(fw_gc_parse(d, n, 5, 1, &g), FW_GC_BAD_VALUE);
    d[8] = 0;
    d[11] = 7;
    CHECK_EQ(fw_gc_parse(d, n, 5, 1, &g), FW_GC_BAD_VALUE);
    d[11] = 0;
    d[9] = 4;
    CHECK_EQ(fw_gc_parse(d, n, 5, 1, &g), FW_GC_BAD_VALUE);
    d[9] = 0;
    CHECK_EQ(fw_gc_parse(d, n, 5, 1, &g), FW_GC_OK);
    /* SPL v18 keeps its STANDBY (5) */
    {
        static uint8_t spl[118];
        memcpy(spl, "RGme", 4);
        spl[4] = 18;
        spl[10] = 5;
        CHECK_EQ(fw_gc_parse(spl, sizeof spl, 0, 0, &g), FW_GC_OK);
        CHECK_EQ(g.state, 5);
    }
}

static void test_return_packet(void)
{
    static uint8_t want[64];
    uint8_t got[FW_GC_RETURN_SIZE];
    fw_gc_return r;
    size_t n = golden("hsl20/return/r01-team5-player1-upright.bin", want, sizeof want);
    CHECK_EQ(n, 32);
    /* r01: player 1, team 5, fallen 0, pose (1000, -500, 1.5), ballAge 0.5, ball (250, 30) */
    r.player = 1;
    r.team = 5;
    r.fallen = 0;
    r.pose[0] = 1000.0f;
    r.pose[1] = -500.0f;
    r.pose[2] = 1.5f;
    r.ball_age = 0.5f;
    r.ball[0] = 250.0f;
    r.ball[1] = 30.0f;
    CHECK_EQ(fw_gc_write_return(&r, got), 32);
    CHECK(memcmp(got, want, 32) == 0);
    n = golden("hsl20/return/r02-team14-player20-fallen-no-ball.bin", want, sizeof want);
    memset(&r, 0, sizeof r);
    r.player = 20;
    r.team = 14;
    r.fallen = 1;
    r.ball_age = -1.0f;
    CHECK_EQ(fw_gc_write_return(&r, got), 32);
    CHECK(memcmp(got, want, 32) == 0);
}

/* ---- the robot following a game, against a fake network driver ---- */

#define MAX_OUT 4096
typedef struct {
    uint32_t at;
    bool to_console;
    wlan_peer to;
    uint16_t len;
    uint8_t head[40];
} sent_datagram;

static sent_datagram g_sent[MAX_OUT];
static int g_sent_n;
static uint32_t g_clock;
static const uint8_t *g_inbox;
static uint16_t g_inbox_len;
static const wlan_peer k_gc_addr = {0, {127, 0, 0, 1}, 40123};
static const wlan_peer *g_inbox_from = &k_gc_addr;

static bool fake_init(void *ctx, uint32_t now) { (void)ctx; (void)now; return true; }
static bool fake_recv(void *ctx, uint8_t *buf, uint16_t cap, uint16_t *len, wlan_peer *from)
{
    (void)ctx;
    if (g_inbox == NULL || g_inbox_len > cap) return false;
    memcpy(buf, g_inbox, g_inbox_len);
    *len = g_inbox_len;
    *from = *g_inbox_from;
    g_inbox = NULL;
    return true;
}
static void record(bool console, const wlan_peer *to, const uint8_t *msg, uint16_t len)
{
    sent_datagram *s;
    if (g_sent_n >= MAX_OUT) return;
    s = &g_sent[g_sent_n++];
    s->at = g_clock;
    s->to_console = console;
    if (to != NULL) s->to = *to;
    s->len = len;
    memcpy(s->head, msg, len < sizeof s->head ? len : sizeof s->head);
}
static bool fake_send_con(void *ctx, const uint8_t *msg, uint16_t len, char cid)
{
    (void)ctx;
    (void)cid;
    record(true, NULL, msg, len);
    return true;
}
static bool fake_send_peer(void *ctx, const wlan_peer *to, const uint8_t *msg, uint16_t len)
{
    (void)ctx;
    record(false, to, msg, len);
    return true;
}
static const wlan_driver k_fake = {fake_init, fake_recv, fake_send_con, fake_send_peer, NULL};

/* One datagram from `from`, then one poll (10 ms after the last). */
static void hear_from(const wlan_peer *from, const uint8_t *d, size_t n)
{
    g_clock += 10;
    g_inbox = d;
    g_inbox_len = (uint16_t)n;
    g_inbox_from = from;
    robot_poll(g_clock);
}

/* One datagram from the GameController's address. */
static void hear(const uint8_t *d, size_t n) { hear_from(&k_gc_addr, d, n); }

static void run_until(uint32_t end)
{
    while ((int32_t)(end - g_clock) > 0) {
        g_clock += 10;
        robot_poll(g_clock);
    }
}

static int count(bool console, uint16_t port, uint32_t from, uint32_t to)
{
    int i, c = 0;
    for (i = 0; i < g_sent_n; i++) {
        const sent_datagram *s = &g_sent[i];
        if (s->at < from || s->at >= to || s->to_console != console) continue;
        if (!console && s->to.port != port) continue;
        c++;
    }
    return c;
}

/* The shortest gap between two datagrams to the console sent in [from, to). */
static uint32_t min_console_gap(uint32_t from, uint32_t to)
{
    int i;
    uint32_t last = 0, gap = 0xFFFFFFFFu;
    bool have = false;
    for (i = 0; i < g_sent_n; i++) {
        if (!g_sent[i].to_console || g_sent[i].at < from || g_sent[i].at >= to) continue;
        if (have && g_sent[i].at - last < gap) gap = g_sent[i].at - last;
        last = g_sent[i].at;
        have = true;
    }
    return gap;
}

static robot_config g_cfg;
static wlan_peer g_team_to = {0, {127, 0, 0, 1}, 10005};

static void start_robot(int32_t id, uint32_t team)
{
    memset(&g_cfg, 0, sizeof g_cfg);
    g_cfg.robot_id = id;
    g_cfg.team_id = team;
    g_cfg.name = "hsl";
    g_cfg.framing = FW_FRAMING_LEGACY;
    g_cfg.rate_hz = 10;
    sim_world_init(id);
    g_cfg.options = sim_world_options(&g_cfg.option_count);
    g_cfg.position = sim_world_position;
    g_cfg.ball = sim_world_ball;
    g_cfg.gc_return_period_ms = FW_GC_RETURN_PERIOD_MS;
    g_cfg.team_msg_period_ms = 250;
    g_team_to.port = (uint16_t)(FW_TEAM_MSG_PORT_BASE + team);
    g_cfg.team_msg_to = &g_team_to;
    wlan_use(&k_fake);
    g_sent_n = 0;
    g_clock = 100000;
    robot_init(&g_cfg, g_clock);
    robot_poll(g_clock);
}

static void enable_all_options(void)
{
    /* a request as the console sends it: Message{robotID 100, DebugOptionRequest{name, enable}} */
    static uint8_t buf[FW_MAX_DATAGRAM];
    uint8_t i;
    for (i = 0; i < g_cfg.option_count; i++) {
        fumanoid_DebugOptionRequest r = fumanoid_DebugOptionRequest_init_zero;
        strcpy(r.name, g_cfg.options[i].name);
        r.enable = true;
        hear(buf, fw_encode_message(buf, sizeof buf, FW_FRAMING_LEGACY, 100, &fumanoid_debugOptionRequest, &r));
    }
}

static void test_robot_debug_limit(void)
{
    static uint8_t playing[256], initial[256];
    size_t np = golden("hsl20/07-playing-after-delay.bin", playing, sizeof playing);
    size_t ni = golden("hsl20/00-initial.bin", initial, sizeof initial);
    uint32_t t0, t1;
    start_robot(1, 5);
    enable_all_options();
    run_until(g_clock + 1000);
    /* the lab: Status every 200 ms and every option at 10 Hz */
    CHECK(count(true, 0, g_clock - 1000, g_clock) >= 5 + 8 * 9);

    hear(playing, np);
    CHECK(robot_in_match());
    CHECK_EQ(robot_gamecontroller()->message_budget, 11997);
    t0 = g_clock;
    run_until(t0 + 10000);
    /* in play: at most one debug packet a second, and that is the Status */
    CHECK(min_console_gap(t0, g_clock) >= FW_MATCH_DEBUG_PERIOD_MS);
    CHECK(count(true, 0, t0, g_clock) >= 9);
    CHECK(count(true, 0, t0, g_clock) <= 10);
    CHECK(robot_stats()->debug_held >= 8 * 90);
    CHECK(robot_option_enabled("demo.text")); /* held, not switched off */

    /* the game stops (INITIAL): after 2 s of it, back to the lab rate, option data flows again */
    hear(initial, ni);
    CHECK(robot_in_match());
    run_until(g_clock + FW_GC_PLAY_MEMORY_MS - 20);
    CHECK(robot_in_match());
    run_until(g_clock + 20);
    CHECK(!robot_in_match());
    t1 = g_clock;
    run_until(t1 + 1000);
    CHECK(count(true, 0, t1, g_clock) >= 5 + 8 * 9);
}

/* Under an SPL GameController (v18) the period is SPL 2025's: one debug packet every 2 s. */
static void test_robot_debug_limit_spl(void)
{
    static uint8_t spl_playing[118];
    uint32_t t0;
    memcpy(spl_playing, "RGme", 4);
    spl_playing[4] = 18;
    spl_playing[10] = FW_GC_PLAYING;
    start_robot(2, 5);
    enable_all_options();
    hear(spl_playing, sizeof spl_playing);
    CHECK(robot_in_match());
    t0 = g_clock;
    run_until(t0 + 10000);
    CHECK(min_console_gap(t0, g_clock) >= FW_MATCH_DEBUG_PERIOD_SPL_MS);
    CHECK(count(true, 0, t0, g_clock) >= 4);
    CHECK(count(true, 0, t0, g_clock) <= 5);
}

static void test_robot_return_packets(void)
{
    static uint8_t playing[256];
    size_t np = golden("hsl20/07-playing-after-delay.bin", playing, sizeof playing);
    static const wlan_peer elsewhere = {0, {127, 0, 0, 2}, 3940};
    uint32_t t0;
    int i, returns = 0;
    start_robot(2, 14);
    /* none before a GameController is heard */
    run_until(g_clock + 3000);
    CHECK_EQ(count(false, FW_GC_RETURN_PORT, 0, g_clock), 0);

    t0 = g_clock;
    hear(playing, np);
    /* the GameController keeps sending every 500 ms */
    while (g_clock < t0 + 10000) {
        run_until(g_clock + 500);
        hear(playing, np);
    }
    for (i = 0; i < g_sent_n; i++) {
        const sent_datagram *s = &g_sent[i];
        if (s->to_console || s->to.port != FW_GC_RETURN_PORT) continue;
        returns++;
        CHECK(memcmp(s->to.ip, k_gc_addr.ip, 4) == 0); /* to the GameController's own address */
        CHECK_EQ(s->len, 32);
        CHECK(memcmp(s->head, "RGrt", 4) == 0);
        CHECK_EQ(s->head[4], 4);
        CHECK_EQ(s->head[5], 2);
        CHECK_EQ(s->head[6], 14);
        CHECK_EQ(s->head[7], 0);
        CHECK(get_f32(s->head + 8) > -5000.0f && get_f32(s->head + 8) < 5000.0f);
        CHECK(get_f32(s->head + 20) >= 0.0f);
    }
    /* 1 Hz: 10 or 11 in 10 s (the first at once) */
    CHECK(returns >= 10 && returns <= 11);
    CHECK_EQ(robot_stats()->gc_returns_out, (uint32_t)returns);

    /* the GameController falls silent: no more return packets after 5 s */
    run_until(g_clock + FW_GC_SILENT_MS + 100);
    t0 = g_clock;
    run_until(t0 + 3000);
    CHECK_EQ(count(false, FW_GC_RETURN_PORT, t0, g_clock), 0);

    /* --gc-return: an address given by the user */
    g_cfg.gc_return_to = &elsewhere;
    robot_init(&g_cfg, g_clock);
    g_sent_n = 0;
    hear(playing, np);
    run_until(g_clock + 1500);
    CHECK(count(false, 3940, 0, g_clock) >= 1);
    CHECK_EQ(count(false, FW_GC_RETURN_PORT, 0, g_clock), 0);
    for (i = 0; i < g_sent_n; i++) {
        if (!g_sent[i].to_console && g_sent[i].to.port == 3940) CHECK(memcmp(g_sent[i].to.ip, elsewhere.ip, 4) == 0);
    }

    /* a robot whose team does not play sends none */
    start_robot(2, 13);
    hear(playing, np);
    run_until(g_clock + 3000);
    CHECK_EQ(count(false, FW_GC_RETURN_PORT, 0, g_clock), 0);
    CHECK_EQ(robot_stats()->gc_other_team, 1);
    CHECK(robot_in_match()); /* but it follows the game's state */
}

/* ---- which GameController the robot follows ---- */

static void test_follow_rule(void)
{
    static const uint8_t gc[4] = {10, 0, 0, 2}, forger[4] = {10, 0, 0, 66};
    fw_gc_follow f = {0};
    uint32_t t = 5000;
    CHECK(fw_gc_follow_take(&f, gc, 40000, FW_GC_PLAYING, t));          /* the first heard is pinned */
    CHECK(!fw_gc_follow_take(&f, forger, 40000, FW_GC_FINISHED, t + 10)); /* another address */
    CHECK(!fw_gc_follow_take(&f, gc, 40001, FW_GC_FINISHED, t + 20));     /* another port of its address */
    CHECK(fw_gc_follow_play_recent(&f, t + 60000)); /* silent in PLAYING: still in play */
    /* the GameController's own FINISHED: in play 2 s more; the pin goes when it falls silent
     * after it (closed after the game), not while it keeps sending */
    t += 500;
    CHECK(fw_gc_follow_take(&f, gc, 40000, FW_GC_FINISHED, t));
    CHECK(fw_gc_follow_play_recent(&f, t + FW_GC_PLAY_MEMORY_MS - 1));
    CHECK(!fw_gc_follow_play_recent(&f, t + FW_GC_PLAY_MEMORY_MS));
    CHECK(!fw_gc_follow_take(&f, forger, 40000, FW_GC_INITIAL, t + 100));
    CHECK(fw_gc_follow_take(&f, gc, 40000, FW_GC_FINISHED, t + 500));
    t += 500;
    CHECK(!fw_gc_follow_take(&f, forger, 40000, FW_GC_INITIAL, t + FW_GC_GAME_OVER_SILENT_MS - 1));
    CHECK(fw_gc_follow_take(&f, forger, 40000, FW_GC_INITIAL, t + FW_GC_GAME_OVER_SILENT_MS)); /* the next game's */
    CHECK(!fw_gc_follow_take(&f, gc, 40000, FW_GC_INITIAL, t + FW_GC_GAME_OVER_SILENT_MS + 100));
    t += FW_GC_GAME_OVER_SILENT_MS; /* the forger's last packet */
    /* silent 30 s (no FINISHED): the next source heard is followed */
    CHECK(!fw_gc_follow_take(&f, gc, 40000, FW_GC_READY, t + FW_GC_PIN_SILENT_MS - 1));
    CHECK(fw_gc_follow_take(&f, gc, 40000, FW_GC_READY, t + FW_GC_PIN_SILENT_MS));
    CHECK(!fw_gc_follow_take(&f, forger, 40000, FW_GC_INITIAL, t + FW_GC_PIN_SILENT_MS + 10));
}

/* 10 s of a real GameController saying `playing` every 500 ms and a forger at `forger` sending
 * `forged` in every poll between; returns in how many polls the robot was out of its limit. */
static int play_against_forger(const uint8_t *playing, const uint8_t *forged, size_t n, const wlan_peer *forger)
{
    uint32_t t0 = g_clock, next_real = g_clock + 500;
    int lifted = 0;
    while (g_clock < t0 + 10000) {
        if (g_clock >= next_real) {
            hear(playing, n);
            next_real += 500;
        } else {
            hear_from(forger, forged, n);
        }
        if (!robot_in_match()) lifted++;
    }
    return lifted;
}

/* A real GameController says PLAYING every 500 ms; a forger floods FINISHED, from another
 * port and from the GameController's own address and port: the limit stays, the forgeries
 * from another source are counted. */
static void test_robot_forged_finished(void)
{
    static uint8_t playing[256], finished[256];
    static const wlan_peer forger = {0, {127, 0, 0, 1}, 40999};
    size_t np = golden("hsl20/07-playing-after-delay.bin", playing, sizeof playing);
    uint32_t t0;
    start_robot(1, 5);
    enable_all_options();
    memcpy(finished, playing, np);
    finished[10] = FW_GC_FINISHED;
    hear(playing, np);
    t0 = g_clock;
    CHECK_EQ(play_against_forger(playing, finished, np, &forger), 0);
    CHECK(strcmp(robot_game_state(), "PLAYING") == 0);
    CHECK(robot_stats()->gc_other_source >= 900);
    CHECK(count(true, 0, t0, g_clock) <= 10); /* the Status once a second, no option data */
    CHECK(min_console_gap(t0, g_clock) >= FW_MATCH_DEBUG_PERIOD_MS);

    t0 = g_clock;
    CHECK_EQ(play_against_forger(playing, finished, np, &k_gc_addr), 0);
    CHECK(count(true, 0, t0, g_clock) <= 10);
}

static void test_robot_penalised_and_stopped(void)
{
    static uint8_t d[256];
    size_t n;
    uint32_t m0;
    fumanoid_Position p0, p1;
    start_robot(3, 14);
    /* lab: the motion clock runs */
    m0 = robot_motion_clock();
    run_until(g_clock + 500);
    CHECK_EQ(robot_motion_clock() - m0, 500);

    n = golden("hsl20/22-pushing-team14-player3.bin", d, sizeof d);
    hear(d, n);
    CHECK(fw_gc_penalised(robot_gamecontroller()));
    CHECK(!robot_may_move());
    m0 = robot_motion_clock();
    sim_world_position(robot_motion_clock(), &p0);
    run_until(g_clock + 3000);
    sim_world_position(robot_motion_clock(), &p1);
    CHECK_EQ(robot_motion_clock(), m0);
    CHECK(p0.x == p1.x && p0.y == p1.y && p0.theta == p1.theta);

    n = golden("hsl20/26-pushing-unpenalized.bin", d, sizeof d);
    hear(d, n);
    CHECK(robot_may_move());
    run_until(g_clock + 1000);
    CHECK(robot_motion_clock() - m0 >= 990);

    /* the corner kick stops play: stand still although the state is PLAYING */
    n = golden("hsl20/08-corner-kick-team14-stopped.bin", d, sizeof d);
    hear(d, n);
    CHECK(!robot_may_move());
    m0 = robot_motion_clock();
    run_until(g_clock + 1000);
    CHECK_EQ(robot_motion_clock(), m0);
    n = golden("hsl20/10-corner-kick-resumed.bin", d, sizeof d);
    hear(d, n);
    CHECK(robot_may_move());

    /* the fake SET after the whistle: robots see SET and stand */
    n = golden("hsl20/05-playing-delayed.bin", d, sizeof d);
    hear(d, n);
    CHECK(!robot_may_move());
    CHECK(strcmp(robot_game_state(), "SET") == 0);
}

static void test_robot_team_messages(void)
{
    static uint8_t d[256];
    size_t n = golden("hsl20/07-playing-after-delay.bin", d, sizeof d);
    uint32_t t0;
    int i, msgs = 0;
    start_robot(4, 5);
    t0 = g_clock;
    run_until(t0 + 10000);
    for (i = 0; i < g_sent_n; i++) {
        const sent_datagram *s = &g_sent[i];
        if (s->to_console || s->to.port != 10005) continue;
        msgs++;
        CHECK(s->len <= FW_TEAM_MSG_MAX);
        CHECK(memcmp(s->to.ip, g_team_to.ip, 4) == 0);
        CHECK(memcmp(s->head, "FUtm", 4) == 0);
        CHECK_EQ(s->head[5], 4);
        CHECK_EQ(s->head[6], 5);
    }
    CHECK(msgs >= 39 && msgs <= 41); /* 4 Hz */

    /* the budget left by the GameController nearly used up: the robot holds its messages */
    d[18 + 8] = FW_TEAM_MSG_RESERVE; /* team 5's messageBudget, low byte */
    d[18 + 9] = 0;
    hear(d, n);
    t0 = g_clock;
    run_until(t0 + 2000);
    CHECK_EQ(count(false, 10005, t0, g_clock), 0);
    CHECK(robot_stats()->team_msgs_held >= 7);
    /* outside READY/SET/PLAYING messages do not count: they flow again */
    d[10] = FW_GC_INITIAL;
    hear(d, n);
    t0 = g_clock;
    run_until(t0 + 2000);
    CHECK(count(false, 10005, t0, g_clock) >= 7);
}

static void test_robot_rejects(void)
{
    static uint8_t d[256], playing[256];
    size_t n = golden("hsl20/04-set.bin", d, sizeof d);
    size_t np = golden("hsl20/07-playing-after-delay.bin", playing, sizeof playing);
    int logs;
    start_robot(1, 5);
    hear(d, n);
    CHECK(strcmp(robot_game_state(), "SET") == 0);
    logs = g_log_lines;
    hear(playing, np - 1);               /* wrong length */
    playing[4] = 21;
    hear(playing, np);                   /* wrong version */
    playing[4] = 20;
    playing[10] = 9;
    hear(playing, np);                   /* state out of range */
    playing[10] = 3;
    CHECK_EQ(robot_stats()->gc_rejected, 3);
    CHECK(g_log_lines >= logs + 3);
    CHECK(strcmp(robot_game_state(), "SET") == 0);
    hear(playing, np);                   /* the next good one is used */
    CHECK(strcmp(robot_game_state(), "PLAYING") == 0);
    CHECK_EQ(robot_stats()->gc_packets, 2);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s GOLDEN_GAMECONTROLLER_DIR\n", argv[0]);
        return 2;
    }
    g_golden_dir = argv[1];
    test_v20_fields();
    test_v20_game_steps();
    test_v19();
    test_rejected();
    test_return_packet();
    test_robot_debug_limit();
    test_robot_debug_limit_spl();
    test_follow_rule();
    test_robot_forged_finished();
    test_robot_return_packets();
    test_robot_penalised_and_stopped();
    test_robot_team_messages();
    test_robot_rejects();
    TEST_DONE();
}
