#include "fw_robot.h"
#include "fw_gamecontroller.h"
#include "fw_registry.h"

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
static uint32_t g_next_due[FW_MAX_OPTIONS];
static rs_stream g_stream;
static wlan_peer g_stream_peer;
static bool g_have_stream_peer;

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

static void send_outgoing(void)
{
    uint16_t n = fw_encode_message(g_tx, sizeof g_tx, g_cfg->framing, g_cfg->robot_id, g_out.type, &g_out.m);
    if (n == 0) {
        g_count.send_failures++;
        fw_log("message does not fit into one datagram", 0, 0);
        return;
    }
    if (sendMsgToCon(g_tx, n, WLAN_CID_CONSOLE)) {
        g_count.messages_out++;
        g_count.bytes_out += n;
    } else {
        g_count.send_failures++;
    }
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
    return state < 5 ? names[state] : "standing";
}

static void send_status(uint32_t now)
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
        g_cfg->position(now, &st->robotPosition);
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
    send_outgoing();
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
    (void)ctx;
    g_tx[0] = hdr[0];
    g_tx[1] = hdr[1];
    for (i = 0; i < n; i++) g_tx[2 + i] = payload[i];
    if (g_have_stream_peer && g_stream_peer.port != 0) return sendMsgToPeer(&g_stream_peer, g_tx, (uint16_t)(n + 2));
    return sendMsgToCon(g_tx, (uint16_t)(n + 2), g_have_stream_peer ? g_stream_peer.cid : WLAN_CID_CONSOLE);
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
    }
    fw_registry_use(k_registry, sizeof k_registry / sizeof k_registry[0]);
    g_have_stream_peer = cfg->reliable_peer != 0;
    if (g_have_stream_peer) g_stream_peer = *cfg->reliable_peer;
    rs_init(&g_stream, cfg->reliable_modulus, cfg->reliable_rto_ms ? cfg->reliable_rto_ms : 100u, 250u,
            stream_output, stream_deliver, 0, now);
}

static void on_gamecontroller(const uint8_t *d, uint16_t len)
{
    fw_gc_info info;
    fw_gc_result r = fw_gc_parse(d, len, &info);
    if (r != FW_GC_OK) {
        g_count.gc_rejected++;
        fw_log(r == FW_GC_BAD_LENGTH ? "gamecontroller packet of wrong length" : "not a known gamecontroller packet",
               0, len);
        return;
    }
    g_count.gc_packets++;
    if (info.state != g_game_state) {
        g_game_state = info.state;
        fw_log("game state", fw_gc_state_name(info.state), info.version);
    }
}

void robot_dispatch(const uint8_t *d, uint16_t len, const wlan_peer *from, uint32_t now)
{
    fw_datagram_info info;
    g_count.datagrams_in++;
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
        on_gamecontroller(d, len);
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

void robot_poll(uint32_t now)
{
    uint8_t i, budget;
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
    if (g_send_list) {
        g_send_list = false;
        send_option_list();
    }
    if ((int32_t)(now - g_next_keepalive) >= 0) {
        g_next_keepalive += FW_KEEPALIVE_MS;
        if ((int32_t)(now - g_next_keepalive) >= 0) g_next_keepalive = now + FW_KEEPALIVE_MS; /* we were late */
        send_status(now);
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
        if ((int32_t)(now - g_next_due[i]) < 0) continue;
        g_next_due[i] += period;
        if ((int32_t)(now - g_next_due[i]) >= 0) g_next_due[i] = now + period; /* we were late */
        if (g_next_due[i] == 0) g_next_due[i] = 1;
        if (g_cfg->options[i].produce != 0 && g_cfg->options[i].produce(now, &g_out)) send_outgoing();
    }
    if (g_cfg->reliable_enabled) {
        if (g_cfg->stream_app != 0 && g_cfg->stream_app->poll != 0) {
            g_cfg->stream_app->poll(g_cfg->stream_app->ctx, &g_stream, now);
        }
        rs_poll(&g_stream, now);
    }
}

const robot_counters *robot_stats(void) { return &g_count; }
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
