#include "fw_robot.h"
#include "fw_registry.h"
#include "fw_digest.h"

/* All buffers are static: nothing of message size ever lives on the stack. */
static uint8_t g_rx[FW_MAX_DATAGRAM];
static uint8_t g_tx[FW_MAX_DATAGRAM];
static fw_outgoing g_out;
static fumanoid_DebugOptionListRequest g_list_request;
static fumanoid_DebugOptionRequest g_option_request;

static const robot_config *g_cfg;
static robot_counters g_count;
static bool g_net_ready;
static bool g_send_list;
static uint8_t g_game_state;
static uint32_t g_started_at;
static uint32_t g_next_keepalive;
static bool g_enabled[FW_MAX_OPTIONS];
static uint8_t g_rank[FW_MAX_OPTIONS]; /* place in the match digest, 1 = first; 0 = not in it */
static uint32_t g_next_due[FW_MAX_OPTIONS];
static rs_stream g_stream;
static wlan_peer g_stream_peer;
static bool g_have_stream_peer;
static uint32_t g_now; /* time of the current poll or dispatch */
/* team key: the console's datagrams checked, ours tagged (docs/security.md) */
static fw_auth_state g_auth;
static uint32_t g_out_seq;
/* GameController */
static fw_gc_info g_gc;
static bool g_gc_heard;
static uint32_t g_gc_heard_at;
static wlan_peer g_gc_from;
static fw_gc_follow g_gc_follow;
static uint32_t g_next_return;
static bool g_returning;
/* game limits and the motion clock */
static uint32_t g_last_debug_at;
static bool g_debug_sent;
static uint32_t g_motion_ms;
static uint32_t g_last_poll;
/* team messages */
static uint32_t g_next_team_msg;
static uint16_t g_team_msg_seq;

static void copy_str(char *dst, uint32_t cap, const char *src)
{
    uint32_t i = 0;
    if (src != 0) {
        for (; i + 1 < cap && src[i] != '\0'; i++) dst[i] = src[i];
    }
    dst[i] = '\0';
}

static bool str_eq(const char *a, const char *b)
{
    while (*a != '\0' && *a == *b) {
        a++;
        b++;
    }
    return *a == *b;
}

/* The robot's own counter: the boot id in the high word, a sequence in the low word. */
static uint64_t next_counter(void)
{
    return ((uint64_t)g_cfg->boot_id << 32) | (uint64_t)(++g_out_seq);
}

/* With a team key: appends the trailer to g_tx[0..n); the new length, 0 = no room. */
static uint16_t tag_outgoing(uint16_t n)
{
    if (g_cfg->team_key == 0 || n == 0) return n;
    return fw_auth_append(g_cfg->team_key, FW_AUTH_DIR_ROBOT, (uint8_t)g_cfg->robot_id, 0, next_counter(), g_tx, n,
                          FW_MAX_DATAGRAM);
}

/* Tags and sends g_tx[0..n) to the console; n = 0: it did not fit. */
static void transmit(uint16_t n)
{
    n = tag_outgoing(n);
    if (n == 0) {
        g_count.send_failures++;
        fw_log("message does not fit into one datagram", 0, 0);
        return;
    }
    g_last_debug_at = g_now;
    g_debug_sent = true;
    if (sendMsgToCon(g_tx, n, WLAN_CID_CONSOLE)) {
        g_count.messages_out++;
        g_count.bytes_out += n;
    } else {
        g_count.send_failures++;
    }
}

static uint16_t trailer_room(void)
{
    return g_cfg->team_key != 0 ? FW_AUTH_TRAILER : 0u;
}

static void send_outgoing(void)
{
    /* the trailer must fit into the 1400 bytes too (the Wi-Fi module's buffer) */
    uint16_t room = (uint16_t)(sizeof g_tx - trailer_room());
    transmit(fw_encode_message(g_tx, room, g_cfg->framing, g_cfg->robot_id, g_out.type, &g_out.m));
}

static const char *role_of(int32_t id)
{
    switch (((id % 3) + 3) % 3) {
    case 1: return "goalie";
    case 2: return "defender";
    default: return "striker";
    }
}

static const char *behaviour_of(uint8_t state)
{
    static const char *const names[] = {"standing", "walkToPosition", "waitForKickoff", "playing", "sitDown"};
    if (g_gc_heard && fw_gc_penalised(&g_gc)) return "penalized";
    if (g_gc_heard && g_gc.stopped) return "stopped";
    return state < 5 ? names[state] : "standing";
}

static void fill_status(uint32_t now)
{
    fumanoid_Status *st = &g_out.m.status;
    uint32_t online_s = (now - g_started_at) / 1000u;
    uint32_t drained = online_s / 30u; /* one percent every 30 s, then "recharged" */
    *st = (fumanoid_Status)fumanoid_Status_init_zero;
    g_out.type = &fumanoid_status;
    st->has_timestamp = true;
    st->timestamp = now;
    st->has_teamID = true;
    st->teamID = g_cfg->team_id;
    st->has_timeOnline = true;
    st->timeOnline = online_s;
    if (g_cfg->position != 0) {
        st->has_robotPosition = true;
        g_cfg->position(g_motion_ms, &st->robotPosition);
        st->has_robotPositionBelief = true;
        st->robotPositionBelief = 0.8;
    }
    st->has_activeAgent = st->has_activeRole = st->has_currentState = st->has_robotName = st->has_gameState = true;
    copy_str(st->activeAgent, sizeof st->activeAgent, "SoccerAgent");
    copy_str(st->activeRole, sizeof st->activeRole, role_of(g_cfg->robot_id));
    copy_str(st->currentState, sizeof st->currentState, behaviour_of(g_game_state));
    copy_str(st->robotName, sizeof st->robotName, g_cfg->name);
    st->has_batteryPercent = true;
    st->batteryPercent = 100u - (drained % 90u);
    copy_str(st->gameState, sizeof st->gameState, fw_gc_state_name(g_game_state));
    st->has_gcOtherSource = true;
    st->gcOtherSource = g_count.gc_other_source;
    if (g_cfg->team_key != 0) {
        const fw_auth_counters *c = &g_auth.count;
        st->has_auth = true;
        st->auth = (fumanoid_AuthCounters){true, c->accepted, true, c->missing, true, c->truncated, true, c->wrong_key,
                                           true, c->bad_tag, true, c->replayed, true, g_cfg->boot_id};
    }
}

static void send_status(uint32_t now)
{
    fill_status(now);
    send_outgoing();
}

static bool has_match_items(void)
{
    uint8_t i;
    for (i = 0; i < FW_MAX_OPTIONS; i++) {
        if (g_rank[i] != 0) return true;
    }
    return false;
}

/* The match digest: the Status, then each chosen option's newest data in rank order, as much
 * as the budget (one MTU after the tag, and the module's 1400 bytes) holds. */
static void send_digest(uint32_t now)
{
    fw_digest d;
    uint16_t budget = g_cfg->match_budget != 0 ? g_cfg->match_budget : FW_DIGEST_MTU_PAYLOAD;
    uint8_t rank, i;
    if (budget > FW_MAX_DATAGRAM) budget = FW_MAX_DATAGRAM;
    fill_status(now);
    fw_digest_begin(&d, g_tx, (uint16_t)(budget - trailer_room()), g_cfg->framing, g_cfg->robot_id);
    if (!fw_digest_status(&d, &g_out.m.status)) {
        transmit(0);
        return;
    }
    for (rank = 1; rank <= FW_MAX_OPTIONS; rank++) {
        for (i = 0; i < g_cfg->option_count && i < FW_MAX_OPTIONS; i++) {
            if (g_rank[i] != rank || g_cfg->options[i].produce == 0 || !g_cfg->options[i].produce(now, &g_out)) continue;
            if (!fw_digest_item(&d, g_cfg->robot_id, g_out.type, &g_out.m)) g_count.digest_omitted++;
        }
    }
    g_count.digests_out++;
    transmit(fw_digest_end(&d));
}

static void send_option_list(void)
{
    fumanoid_DebugOptionList *l = &g_out.m.option_list;
    uint8_t i;
    g_out.type = &fumanoid_debugOptionList;
    l->options_count = 0;
    for (i = 0; i < g_cfg->option_count && i < FW_MAX_OPTIONS; i++) {
        fumanoid_DebugOption *o = &l->options[l->options_count++];
        copy_str(o->name, sizeof o->name, g_cfg->options[i].name);
        o->has_description = true;
        copy_str(o->description, sizeof o->description, g_cfg->options[i].description);
        o->has_kind = true;
        o->kind = g_cfg->options[i].kind;
        o->has_enabled = true;
        o->enabled = g_enabled[i];
        o->has_matchRank = g_rank[i] != 0;
        o->matchRank = g_rank[i];
    }
    send_outgoing();
}

static void on_list_request(int32_t sender, const void *msg)
{
    (void)sender;
    (void)msg;
    g_send_list = true;
}

static void on_option_request(int32_t sender, const void *msg)
{
    const fumanoid_DebugOptionRequest *r = (const fumanoid_DebugOptionRequest *)msg;
    uint8_t i;
    (void)sender;
    for (i = 0; i < g_cfg->option_count; i++) {
        if (str_eq(g_cfg->options[i].name, r->name)) {
            if (g_enabled[i] != r->enable) {
                g_enabled[i] = r->enable;
                g_next_due[i] = 0;
                fw_log(r->enable ? "debug option on" : "debug option off", r->name, i);
            }
            if (r->has_matchRank && g_rank[i] != r->matchRank) {
                /* the console sends ranks outside play only (its match-mode gate) */
                g_rank[i] = r->matchRank <= FW_MAX_OPTIONS ? (uint8_t)r->matchRank : 0u;
                fw_log("match digest place", r->name, (int32_t)g_rank[i]);
            }
            g_send_list = true; /* the console sees the new state in a fresh list */
            return;
        }
    }
    fw_log("request for an unknown debug option", r->name, 0);
}

static const fw_registry_entry k_registry[] = {
    {40, fumanoid_DebugOptionListRequest_fields, &g_list_request, on_list_request},
    {42, fumanoid_DebugOptionRequest_fields, &g_option_request, on_option_request},
};

static int stream_output(void *ctx, const uint8_t hdr[2], const uint8_t *payload, uint16_t n)
{
    uint16_t i;
    uint16_t len;
    (void)ctx; /* n <= RS_MAX_PAYLOAD: header and payload fit into g_tx */
    g_tx[0] = hdr[0];
    g_tx[1] = hdr[1];
    for (i = 0; i < n; i++) g_tx[2 + i] = payload[i];
    len = tag_outgoing((uint16_t)(n + 2));
    if (len == 0) return 0; /* no room for the tag: the stream counts it as lost and sends again */
    if (g_have_stream_peer && g_stream_peer.port != 0) return sendMsgToPeer(&g_stream_peer, g_tx, len);
    return sendMsgToCon(g_tx, len, g_have_stream_peer ? g_stream_peer.cid : WLAN_CID_CONSOLE);
}

static void stream_deliver(void *ctx, const uint8_t *payload, uint16_t n)
{
    (void)ctx;
    if (g_cfg->stream_app != 0 && g_cfg->stream_app->receive != 0) {
        g_cfg->stream_app->receive(g_cfg->stream_app->ctx, payload, n);
    }
}

void robot_init(const robot_config *cfg, uint32_t now)
{
    uint8_t i;
    g_cfg = cfg;
    g_count = (robot_counters){0};
    g_net_ready = false;
    g_send_list = false;
    g_game_state = 0;
    g_started_at = now;
    g_next_keepalive = now;
    for (i = 0; i < FW_MAX_OPTIONS; i++) {
        g_enabled[i] = false;
        g_next_due[i] = 0;
        g_rank[i] = 0;
    }
    fw_registry_use(k_registry, sizeof k_registry / sizeof k_registry[0]);
    fw_auth_init(&g_auth, cfg->team_key, cfg->boot_id); /* the console's requests are bound to this boot */
    g_out_seq = 0;
    g_have_stream_peer = cfg->reliable_peer != 0;
    if (g_have_stream_peer) g_stream_peer = *cfg->reliable_peer;
    rs_init(&g_stream, cfg->reliable_modulus, cfg->reliable_rto_ms ? cfg->reliable_rto_ms : 100u, 250u,
            stream_output, stream_deliver, 0, now);
    g_now = now;
    g_gc = (fw_gc_info){0};
    g_gc_heard = false;
    g_gc_follow = (fw_gc_follow){0};
    g_returning = false;
    g_debug_sent = false;
    g_motion_ms = now;
    g_last_poll = now;
    g_team_msg_seq = 0;
    /* the team's messages spread over the period: robot n starts n/5 of a period later */
    g_next_team_msg = now + (uint32_t)cfg->team_msg_period_ms * (uint32_t)(((cfg->robot_id % 5) + 5) % 5) / 5u;
}

static void on_gamecontroller(const uint8_t *d, uint16_t len, const wlan_peer *from)
{
    static fw_gc_info info; /* static: keeps the receive path's stack small */
    uint8_t team = g_cfg->team_id <= 255u ? (uint8_t)g_cfg->team_id : 0u;
    uint8_t player = g_cfg->robot_id >= 1 && g_cfg->robot_id <= (int32_t)FW_GC_MAX_PLAYERS ? (uint8_t)g_cfg->robot_id : 0u;
    fw_gc_result r = fw_gc_parse(d, len, team, player, &info);
    if (r != FW_GC_OK) {
        g_count.gc_rejected++;
        fw_log(fw_gc_result_name(r), 0, len);
        return;
    }
    g_count.gc_packets++;
    {
        static const wlan_peer k_nobody;
        const wlan_peer *src = from != 0 ? from : &k_nobody;
        if (!fw_gc_follow_take(&g_gc_follow, src->ip, src->port, info.state, g_now)) {
            uint32_t n = ++g_count.gc_other_source;
            if ((n & (n - 1u)) == 0u) fw_log("gamecontroller packet from another source, not believed", 0, src->port);
            return;
        }
    }
    if (info.has_game_fields && !info.own_team_found) {
        /* another game's GameController, or a practice game without us: follow its state
         * (the console's demo does that), but there is no penalty of ours to read */
        if (g_count.gc_other_team++ == 0) fw_log("gamecontroller packet without our team number", 0, team);
    }
    if (!g_gc_heard || info.state != g_gc.state) fw_log("game state", fw_gc_state_name(info.state), info.version);
    if (g_gc_heard && info.stopped != g_gc.stopped) fw_log(info.stopped ? "play stopped" : "play resumed", 0, 0);
    if (g_gc_heard && fw_gc_penalised(&info) != fw_gc_penalised(&g_gc)) {
        fw_log(fw_gc_penalised(&info) ? "penalised" : "unpenalised", 0, info.penalty);
    }
    g_gc = info;
    g_game_state = info.state;
    g_gc_heard = true;
    g_gc_heard_at = g_now;
    if (from != 0) g_gc_from = *from;
    if (!g_returning && g_cfg->gc_return_period_ms != 0 && fw_gc_wants_return_v4(info.version) && info.own_team_found) {
        g_returning = true;
        g_next_return = g_now; /* the GameController sees us at once */
    }
}

/* One log line for the 1st, 2nd, 4th, 8th... rejection: a flood of forgeries cannot flood the log. */
static void log_rejected(fw_auth_result r, uint16_t len)
{
    static uint32_t n;
    n++;
    if ((n & (n - 1u)) == 0u) fw_log("rejected", fw_auth_result_name(r), len);
}

void robot_dispatch(const uint8_t *d, uint16_t len, const wlan_peer *from, uint32_t now)
{
    fw_datagram_info info;
    g_now = now;
    g_count.datagrams_in++;
    /* GameController packets are never tagged (league rules); everything else from the
     * console is checked before it is classified or dispatched */
    if (!(len >= 2 && d[0] == 'R' && d[1] == 'G')) {
        uint16_t payload_len = len;
        fw_auth_result a = fw_auth_check(&g_auth, FW_AUTH_DIR_CONSOLE, (uint8_t)g_cfg->robot_id, d, len, &payload_len);
        if (a != FW_AUTH_OK && a != FW_AUTH_LAB) {
            log_rejected(a, len);
            return;
        }
        len = payload_len;
    }
    fw_classify(d, len, &info);
    switch (info.kind) {
    case FW_DGRAM_FUMANOID: {
        fw_result r = processData(d + info.payload_off, info.payload_len);
        if (r == FW_OK) {
            g_count.messages_handled++;
        } else if (r == FW_ERR_UNKNOWN_EXT) {
            g_count.unknown_ext++;
            fw_log("unknown extension ignored", 0, (int32_t)fw_last_report()->ext);
        } else {
            g_count.malformed++;
            fw_log(fw_result_name(r), fw_last_report()->detail, (int32_t)fw_last_report()->ext);
        }
        break;
    }
    case FW_DGRAM_GAMECONTROLLER:
        on_gamecontroller(d, len, from);
        break;
    case FW_DGRAM_RELIABLE:
        if (g_cfg->reliable_enabled) {
            g_count.reliable_segments++;
            if (from != 0) {
                g_stream_peer = *from; /* answer whoever talks to us */
                g_have_stream_peer = true;
            }
            rs_input(&g_stream, d, len, now);
            break;
        }
        g_count.malformed++;
        fw_log("malformed datagram: not a FUmanoids frame (length field disagrees)", 0, len);
        break;
    default:
        g_count.malformed++;
        fw_log(fw_datagram_kind_name(info.kind), 0, len);
        break;
    }
}

bool robot_gc_heard(void) { return g_gc_heard; }
uint32_t robot_motion_clock(void) { return g_motion_ms; }
const fw_gc_info *robot_gamecontroller(void) { return &g_gc; }

bool robot_in_match(void)
{
    return g_gc_heard && fw_gc_follow_play_recent(&g_gc_follow, g_now);
}

bool robot_may_move(void)
{
    if (!g_gc_heard) return true; /* lab: no GameController, the robot does what it likes */
    if (fw_gc_penalised(&g_gc) || g_gc.stopped) return false;
    return g_gc.state == FW_GC_READY || g_gc.state == FW_GC_PLAYING;
}

/* Pose and ball as the world reports them at the motion clock. */
static float world_view(fumanoid_Position *self, float ball[2])
{
    *self = (fumanoid_Position)fumanoid_Position_init_zero;
    ball[0] = ball[1] = 0.0f;
    if (g_cfg->position != 0) g_cfg->position(g_motion_ms, self);
    return g_cfg->ball != 0 ? g_cfg->ball(g_now, self, ball) : -1.0f;
}

static void send_return(void)
{
    fw_gc_return r;
    fumanoid_Position self;
    wlan_peer to;
    uint16_t n;
    r.ball_age = world_view(&self, r.ball);
    r.player = (uint8_t)g_cfg->robot_id;
    r.team = (uint8_t)g_cfg->team_id;
    r.fallen = 0;
    r.pose[0] = self.x;
    r.pose[1] = self.y;
    r.pose[2] = self.theta;
    n = fw_gc_write_return(&r, g_tx);
    if (g_cfg->gc_return_to != 0) {
        to = *g_cfg->gc_return_to;
    } else {
        to = g_gc_from;
        to.port = FW_GC_RETURN_PORT;
    }
    if (sendMsgToPeer(&to, g_tx, n)) {
        g_count.gc_returns_out++;
    } else {
        g_count.send_failures++;
    }
}

/* The team message, our own format (the league fixes only port and size): "FUtm", version 1,
 * player, team, flags (bit 0 penalised, bit 1 may move), sequence (u16), pose x, y, theta,
 * ball age, ball x, y (f32, little-endian, the units of the return packet): 34 bytes. */
#define FW_TEAM_MSG_SIZE 34u

static bool team_budget_left(void)
{
    /* The budget counts in READY/SET/PLAYING, outside penalty shoot-outs; the GameController's
     * count lags by up to one packet interval, so each robot leaves a reserve untouched. */
    if (!g_gc_heard || !fw_gc_in_play(g_gc.state) || !g_gc.own_team_found ||
        g_gc.game_phase == FW_GC_PHASE_PENALTY_SHOOT_OUT) {
        return true;
    }
    return g_gc.message_budget > FW_TEAM_MSG_RESERVE;
}

static void send_team_message(void)
{
    fumanoid_Position self;
    float ball[2], age;
    uint8_t *m = g_tx;
    if (!team_budget_left()) {
        if (g_count.team_msgs_held++ == 0) fw_log("team message budget used up, team messages held", 0, g_gc.message_budget);
        return;
    }
    age = world_view(&self, ball);
    m[0] = 'F';
    m[1] = 'U';
    m[2] = 't';
    m[3] = 'm';
    m[4] = 1;
    m[5] = (uint8_t)g_cfg->robot_id;
    m[6] = (uint8_t)g_cfg->team_id;
    m[7] = (uint8_t)((g_gc_heard && fw_gc_penalised(&g_gc) ? 1u : 0u) | (robot_may_move() ? 2u : 0u));
    m[8] = (uint8_t)g_team_msg_seq;
    m[9] = (uint8_t)(g_team_msg_seq >> 8);
    g_team_msg_seq++;
    fw_gc_put_f32(m + 10, self.x);
    fw_gc_put_f32(m + 14, self.y);
    fw_gc_put_f32(m + 18, self.theta);
    fw_gc_put_f32(m + 22, age);
    fw_gc_put_f32(m + 26, ball[0]);
    fw_gc_put_f32(m + 30, ball[1]);
    if (sendMsgToPeer(g_cfg->team_msg_to, m, FW_TEAM_MSG_SIZE)) {
        g_count.team_msgs_out++;
    } else {
        g_count.send_failures++;
    }
}

/* A periodic schedule: true when its item is due at now, and then *next moves on by one
 * period (or to now + period if we fell behind, so a late poll does not cause a burst). */
static bool due(uint32_t now, uint32_t *next, uint32_t period)
{
    if ((int32_t)(now - *next) < 0) return false;
    *next += period;
    if ((int32_t)(now - *next) >= 0) *next = now + period; /* we were late */
    return true;
}

void robot_poll(uint32_t now)
{
    uint8_t i, budget;
    bool match;
    g_now = now;
    if (robot_may_move()) g_motion_ms += now - g_last_poll;
    g_last_poll = now;
    /* Asked on every poll: a driver may lose its link (DISCONNECT) and re-open it. */
    if (!pollInitNetwork(now)) {
        if (g_net_ready) fw_log("network lost, re-initialising", 0, 0);
        g_net_ready = false;
        return;
    }
    if (!g_net_ready) {
        g_net_ready = true;
        fw_log("network ready", 0, 0);
        g_next_keepalive = now;
    }
    for (budget = 0; budget < 32; budget++) {
        uint16_t len = sizeof g_rx;
        if (!recvWlanData(g_rx, &len)) break;
        robot_dispatch(g_rx, len, wlanLastSender(), now);
    }
    g_now = now;
    match = robot_in_match();
    if (match) {
        /* The game's limit: one debug packet a period, the match digest (or the bare Status
         * when no item was chosen); the option list waits for the game to stop, option data
         * is produced only for the digest. */
        uint32_t period = g_cfg->match_debug_period_ms ? g_cfg->match_debug_period_ms
                          : g_gc.version == 18u ? FW_MATCH_DEBUG_PERIOD_SPL_MS : FW_MATCH_DEBUG_PERIOD_MS;
        if (!g_debug_sent || now - g_last_debug_at >= period) {
            uint8_t k, sends = g_cfg->match_sends_per_period > 1u ? g_cfg->match_sends_per_period : 1u;
            for (k = 0; k < sends; k++) {
                if (has_match_items()) {
                    send_digest(now);
                } else {
                    send_status(now);
                }
            }
        }
        g_next_keepalive = now;
    } else {
        if (g_send_list) {
            g_send_list = false;
            send_option_list();
        }
        if (due(now, &g_next_keepalive, FW_KEEPALIVE_MS)) send_status(now);
    }
    for (i = 0; i < g_cfg->option_count && i < FW_MAX_OPTIONS; i++) {
        uint32_t period = 1000u / (g_cfg->rate_hz ? g_cfg->rate_hz : 10u);
        if (!g_enabled[i]) continue;
        if (g_next_due[i] == 0) {
            /* just switched on: each option gets its own phase, so options switched on
             * together do not all hit the serial line in the same poll */
            g_next_due[i] = now + (period * i) / (g_cfg->option_count ? g_cfg->option_count : 1u);
            if (g_next_due[i] == 0) g_next_due[i] = 1;
        }
        if (!due(now, &g_next_due[i], period)) continue;
        if (g_next_due[i] == 0) g_next_due[i] = 1; /* 0 means "just switched on" */
        if (match) {
            g_count.debug_held++;
            continue;
        }
        if (g_cfg->options[i].produce != 0 && g_cfg->options[i].produce(now, &g_out)) send_outgoing();
    }
    if (g_returning && now - g_gc_heard_at > FW_GC_SILENT_MS) {
        g_returning = false;
        fw_log("gamecontroller silent, return packets stopped", 0, 0);
    }
    if (g_returning && due(now, &g_next_return, g_cfg->gc_return_period_ms)) send_return();
    if (g_cfg->team_msg_period_ms != 0 && g_cfg->team_msg_to != 0 &&
        due(now, &g_next_team_msg, g_cfg->team_msg_period_ms)) {
        send_team_message();
    }
    if (g_cfg->reliable_enabled) {
        if (g_cfg->stream_app != 0 && g_cfg->stream_app->poll != 0) {
            g_cfg->stream_app->poll(g_cfg->stream_app->ctx, &g_stream, now);
        }
        rs_poll(&g_stream, now);
    }
}

const robot_counters *robot_stats(void) { return &g_count; }
const fw_auth_counters *robot_auth_stats(void) { return &g_auth.count; }
const char *robot_game_state(void) { return fw_gc_state_name(g_game_state); }
bool robot_network_ready(void) { return g_net_ready; }
rs_stream *robot_stream(void) { return &g_stream; }

bool robot_option_enabled(const char *name)
{
    uint8_t i;
    for (i = 0; i < g_cfg->option_count; i++) {
        if (str_eq(g_cfg->options[i].name, name)) return g_enabled[i];
    }
    return false;
}
