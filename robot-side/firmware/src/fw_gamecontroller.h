/* GameController receiver: the robot accepts the RoboCupGameControlData ("RGme") layouts a
 * small robot meets, each by magic + version + exact length (robots drop any other size):
 * HSL v20 (158 bytes, GameController 7.x, RoboCup 2026), HSL v19 (198 bytes, 6.0.x),
 * HL v12 (688 / 640 bytes), 2014 v8 (158 bytes: the same size as v20, the version byte
 * decides), SPL v18 (118 bytes) and 2013 v7 (116 bytes).
 *
 * For every layout the robot reads the state; for v18/v19/v20, whose headers share offsets
 * 0-17, it also reads the game fields and looks its own team up by team number in either
 * slot (the slots swap at half time) and its own player by jersey number. */
#ifndef FW_GAMECONTROLLER_H
#define FW_GAMECONTROLLER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define FW_GC_RETURN_PORT 3939u
#define FW_GC_RETURN_SIZE 32u
#define FW_GC_MAX_PLAYERS 20u
#define FW_GC_KICKING_TEAM_NONE 255u

/* HSL states (v19/v20; the older formats use the same numbers, SPL adds 5 STANDBY) */
enum { FW_GC_INITIAL = 0, FW_GC_READY = 1, FW_GC_SET = 2, FW_GC_PLAYING = 3, FW_GC_FINISHED = 4 };
/* HSL penalties that matter to the robot itself: SUBSTITUTE is "not on the field" */
enum { FW_GC_PHASE_PENALTY_SHOOT_OUT = 1 };
enum { FW_GC_PENALTY_NONE = 0, FW_GC_V20_SENT_OFF = 12, FW_GC_V20_SUBSTITUTE = 13, FW_GC_V19_SUBSTITUTE = 11 };

typedef enum {
    FW_GC_OK = 0,
    FW_GC_BAD_MAGIC,
    FW_GC_BAD_VERSION,   /* known magic, unknown version */
    FW_GC_BAD_LENGTH,    /* known version, wrong datagram size */
    FW_GC_BAD_VALUE      /* right size, but a field out of its range (state, stopped, ...) */
} fw_gc_result;

typedef struct {
    uint8_t version;
    uint8_t state;        /* 0 INITIAL 1 READY 2 SET 3 PLAYING 4 FINISHED (5 STANDBY, SPL) */
    uint8_t packet_number;
    uint8_t team_numbers[2];
    /* v18/v19/v20 only (has_game_fields); zero for the older layouts */
    bool has_game_fields;
    uint8_t players_per_team;
    uint8_t stopped;      /* v19/v20: 1 = play is stopped; always 0 for v18 */
    uint8_t game_phase;   /* 0 NORMAL 1 PENALTY_SHOOT_OUT 2 EXTRA_TIME 3 TIMEOUT */
    uint8_t set_play;     /* v19/v20: 0 NONE 1 DIRECT_FREE_KICK 2 INDIRECT 3 PENALTY_KICK 4 THROW_IN
                             5 GOAL_KICK 6 CORNER_KICK (v18: SPL numbering) */
    uint8_t first_half;
    uint8_t kicking_team; /* team number, 255 = none (dropped ball) */
    int16_t secs_remaining;
    int16_t secondary_time;
    /* the robot's own team and player, when asked for and present */
    bool own_team_found;
    uint8_t own_side;     /* 0 = teams[0] (left goal from the operator's view), 1 = teams[1] */
    uint8_t own_score;
    uint16_t message_budget;
    bool own_player_found;
    uint8_t penalty;      /* code of the packet's version (v19 and v20 number them differently) */
    uint8_t secs_till_unpenalised;
} fw_gc_info;

/* Parses one datagram. team/player: the robot's team number and jersey number (1-20), used
 * to fill the own_* fields of v18/v19/v20 packets; 0 = do not look up. */
fw_gc_result fw_gc_parse(const uint8_t *d, size_t len, uint8_t team, uint8_t player, fw_gc_info *out);
const char *fw_gc_state_name(uint8_t state);
const char *fw_gc_result_name(fw_gc_result r);
/* True when the packet's version has a return packet "RGrt" v4 (SPL v18, HSL v19/v20). */
bool fw_gc_wants_return_v4(uint8_t version);
/* True when the own player is penalised (any penalty, including SUBSTITUTE and SENT_OFF). */
bool fw_gc_penalised(const fw_gc_info *g);

/* Which GameController the robot believes: the rule of the console's (docs/security.md,
 * "GameController spoofing"). The first source heard in a game is pinned by address and port
 * until the game is over (it said FINISHED, then fell silent FW_GC_GAME_OVER_SILENT_MS: closed
 * after the game) or it has been silent FW_GC_PIN_SILENT_MS;
 * packets from any other source are counted and never believed. The debug limit ends only
 * after the believed GameController said a non-play state for FW_GC_PLAY_MEMORY_MS, so a
 * forger on the GameController's own address cannot lift it between two real packets. */
#define FW_GC_PIN_SILENT_MS 30000u
#define FW_GC_GAME_OVER_SILENT_MS 2000u
#define FW_GC_PLAY_MEMORY_MS 2000u

typedef struct {
    bool pinned;
    bool finished;          /* the pinned source's last state was FINISHED */
    uint8_t ip[4];
    uint16_t port;
    uint32_t heard_at;
    bool play_heard;
    bool in_play;           /* the believed source's last state was READY/SET/PLAYING */
    uint32_t play_at;       /* its last READY/SET/PLAYING, or its first other state after one */
} fw_gc_follow;

/* One parsed packet from ip:port at now: true = believe it (it comes from the pinned source,
 * or pins its source); false = another source (the caller counts it). */
bool fw_gc_follow_take(fw_gc_follow *f, const uint8_t ip[4], uint16_t port, uint8_t state, uint32_t now);
/* The believed GameController said READY, SET or PLAYING, or has said another state for less
 * than FW_GC_PLAY_MEMORY_MS. */
bool fw_gc_follow_play_recent(const fw_gc_follow *f, uint32_t now);
bool fw_gc_in_play(uint8_t state);

/* Robot -> GameController return packet "RGrt" version 4, 32 bytes, little-endian. */
typedef struct {
    uint8_t player;
    uint8_t team;
    uint8_t fallen;       /* 0 can play, 1 fallen */
    float pose[3];        /* x mm, y mm (field frame, +x towards the opponent goal), theta rad */
    float ball_age;       /* s since the ball was last seen, -1 = never */
    float ball[2];        /* x, y mm relative to the robot */
} fw_gc_return;

/* Writes the 32 bytes into out (at least FW_GC_RETURN_SIZE bytes); returns 32. */
uint16_t fw_gc_write_return(const fw_gc_return *r, uint8_t *out);
/* One IEEE-754 single, little-endian (the wire order of the GameController structs). */
void fw_gc_put_f32(uint8_t *p, float f);

#endif
