#include "fw_gamecontroller.h"

typedef struct {
    uint8_t version;
    uint8_t version_width;  /* bytes of the little-endian version field at offset 4 */
    uint16_t size;
    uint16_t state_at, packet_at, team0_at, team1_at;
    uint8_t robot_size;     /* v18/v19/v20: bytes per RobotInfo at team + 10; 0 = state only */
    uint8_t has_stopped;    /* v19/v20: offset 8 is `stopped` (in v18 it is competitionType) */
    uint8_t max_state, max_set_play;
} gc_layout;

/* Offsets from the official headers (see the GameController briefs); packet_at 0 = none.
 * v20 comes before v8: both are 158 bytes, the version byte decides. */
static const gc_layout k_layouts[] = {
    {20, 1, 158, 10, 5, 18, 18 + 70, 3, 1, 4, 6},   /* HSL 2026, GameController 7.x */
    {19, 1, 198, 10, 5, 18, 18 + 90, 4, 1, 4, 6},   /* HSL, GameController 6.0.x (German Open 2026) */
    {12, 2, 688, 9, 6, 24, 24 + 332, 0, 0, 0, 0},     /* HL v12, since 2021 */
    {12, 2, 640, 9, 6, 24, 24 + 308, 0, 0, 0, 0},     /* HL v12, 2017-2021 (same version number) */
    {8, 1, 158, 7, 5, 18, 18 + 70, 0, 0, 0, 0},       /* 2014 SPL and HL */
    {18, 1, 118, 10, 5, 18, 18 + 50, 2, 0, 5, 5},     /* SPL 2023-2025 */
    {7, 4, 116, 9, 0, 20, 20 + 48, 0, 0, 0, 0},       /* 2013, and HL "compatibility" packets until 2017 */
};

static uint16_t le16(const uint8_t *p) { return (uint16_t)(p[0] | (p[1] << 8)); }

/* Game fields shared by v18/v19/v20 (offsets 6-17), own team and player. */
static fw_gc_result read_game_fields(const gc_layout *l, const uint8_t *d, uint8_t team, uint8_t player,
                                     fw_gc_info *out)
{
    uint8_t t;
    out->has_game_fields = true;
    out->players_per_team = d[6];
    out->stopped = l->has_stopped ? d[8] : 0;
    out->game_phase = d[9];
    out->set_play = d[11];
    out->first_half = d[12];
    out->kicking_team = d[13];
    out->secs_remaining = (int16_t)le16(d + 14);
    out->secondary_time = (int16_t)le16(d + 16);
    /* a robot acting on a half-valid packet is worse than one that waits for the next */
    if (out->state > l->max_state || out->stopped > 1 || out->game_phase > 3 || out->set_play > l->max_set_play ||
        out->first_half > 1) {
        return FW_GC_BAD_VALUE;
    }
    if (team == 0) return FW_GC_OK;
    for (t = 0; t < 2; t++) {
        const uint8_t *ti = d + (t == 0 ? l->team0_at : l->team1_at);
        if (ti[0] != team) continue;
        out->own_team_found = true;
        out->own_side = t;
        out->own_score = ti[4];
        out->message_budget = le16(ti + 8);
        if (player >= 1 && player <= FW_GC_MAX_PLAYERS) {
            const uint8_t *ri = ti + 10 + (size_t)l->robot_size * (player - 1u);
            out->own_player_found = true;
            out->penalty = ri[0];
            out->secs_till_unpenalised = ri[1];
        }
        break;
    }
    return FW_GC_OK;
}

fw_gc_result fw_gc_parse(const uint8_t *d, size_t len, uint8_t team, uint8_t player, fw_gc_info *out)
{
    size_t i;
    int version_known = 0;
    static const fw_gc_info k_empty;
    *out = k_empty;
    if (len < 8 || d[0] != 'R' || d[1] != 'G' || d[2] != 'm' || d[3] != 'e') return FW_GC_BAD_MAGIC;
    for (i = 0; i < sizeof k_layouts / sizeof k_layouts[0]; i++) {
        const gc_layout *l = &k_layouts[i];
        uint32_t v = d[4];
        uint8_t b;
        for (b = 1; b < l->version_width; b++) v |= (uint32_t)d[4 + b] << (8 * b);
        if (v != l->version) continue;
        version_known = 1;
        if (len != l->size) continue;
        out->version = l->version;
        out->state = d[l->state_at];
        out->packet_number = l->packet_at ? d[l->packet_at] : 0;
        out->team_numbers[0] = d[l->team0_at];
        out->team_numbers[1] = d[l->team1_at];
        return l->robot_size ? read_game_fields(l, d, team, player, out) : FW_GC_OK;
    }
    return version_known ? FW_GC_BAD_LENGTH : FW_GC_BAD_VERSION;
}

const char *fw_gc_state_name(uint8_t state)
{
    static const char *const names[] = {"INITIAL", "READY", "SET", "PLAYING", "FINISHED", "STANDBY"};
    return state < 6 ? names[state] : "UNKNOWN";
}

const char *fw_gc_result_name(fw_gc_result r)
{
    switch (r) {
    case FW_GC_OK: return "ok";
    case FW_GC_BAD_MAGIC: return "not a gamecontroller packet";
    case FW_GC_BAD_VERSION: return "gamecontroller packet of unknown version";
    case FW_GC_BAD_LENGTH: return "gamecontroller packet of wrong length";
    default: return "gamecontroller packet with a value out of range";
    }
}

bool fw_gc_wants_return_v4(uint8_t version) { return version == 18 || version == 19 || version == 20; }

bool fw_gc_penalised(const fw_gc_info *g) { return g->own_player_found && g->penalty != FW_GC_PENALTY_NONE; }

bool fw_gc_in_play(uint8_t state)
{
    return state == FW_GC_READY || state == FW_GC_SET || state == FW_GC_PLAYING;
}

bool fw_gc_follow_take(fw_gc_follow *f, const uint8_t ip[4], uint16_t port, uint8_t state, uint32_t now)
{
    uint8_t i;
    if (f->pinned && now - f->heard_at >= (f->finished ? FW_GC_GAME_OVER_SILENT_MS : FW_GC_PIN_SILENT_MS)) {
        f->pinned = false;
    }
    if (!f->pinned) {
        for (i = 0; i < 4; i++) f->ip[i] = ip[i];
        f->port = port;
        f->pinned = true;
    }
    for (i = 0; i < 4; i++) {
        if (f->ip[i] != ip[i]) break;
    }
    if (i < 4 || f->port != port) return false;
    f->heard_at = now;
    if (fw_gc_in_play(state) || f->in_play) {
        f->play_heard = true;
        f->play_at = now;
    }
    f->in_play = fw_gc_in_play(state);
    f->finished = state == FW_GC_FINISHED; /* silent after it: the next game's may be another */
    return true;
}

bool fw_gc_follow_play_recent(const fw_gc_follow *f, uint32_t now)
{
    return f->in_play || (f->play_heard && now - f->play_at < FW_GC_PLAY_MEMORY_MS);
}

void fw_gc_put_f32(uint8_t *p, float f)
{
    union { float f; uint32_t u; } v;
    v.f = f;
    p[0] = (uint8_t)v.u;
    p[1] = (uint8_t)(v.u >> 8);
    p[2] = (uint8_t)(v.u >> 16);
    p[3] = (uint8_t)(v.u >> 24);
}

uint16_t fw_gc_write_return(const fw_gc_return *r, uint8_t *out)
{
    out[0] = 'R';
    out[1] = 'G';
    out[2] = 'r';
    out[3] = 't';
    out[4] = 4;
    out[5] = r->player;
    out[6] = r->team;
    out[7] = r->fallen;
    fw_gc_put_f32(out + 8, r->pose[0]);
    fw_gc_put_f32(out + 12, r->pose[1]);
    fw_gc_put_f32(out + 16, r->pose[2]);
    fw_gc_put_f32(out + 20, r->ball_age);
    fw_gc_put_f32(out + 24, r->ball[0]);
    fw_gc_put_f32(out + 28, r->ball[1]);
    return FW_GC_RETURN_SIZE;
}
