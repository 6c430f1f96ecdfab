/* The robot's communication core: one polled step (robot_poll) receives and dispatches
 * every waiting datagram, sends the Status keep-alive every 200 ms and the data of every
 * debug option that is switched on, and drives the reliable stream. During a game (the
 * GameController it follows says READY, SET or PLAYING, and for 2 s after) it keeps to the
 * league's limit on debug traffic: one datagram a second to the console, the match digest
 * (Status + the chosen options' newest data, fw_digest.h) or, with nothing chosen, the bare
 * Status. When it hears an HSL (or
 * SPL) GameController it also sends return packets to it and, if configured, team messages.
 * Static memory only; the platform supplies the network driver (fw_wlan.h), the clock
 * (passed in) and fw_log(). */
#ifndef FW_ROBOT_H
#define FW_ROBOT_H

#include <stdbool.h>
#include <stdint.h>
#include "fumanoid.pb.h"
#include "fw_auth.h"
#include "fw_framing.h"
#include "fw_gamecontroller.h"
#include "fw_reliable.h"
#include "fw_wlan.h"

#define FW_KEEPALIVE_MS 200u
/* HSL 2026 rules, "Debug Communication": a robot may send debug information at most once
 * every second, in a single UDP packet (README.md cites the rule). */
#define FW_MATCH_DEBUG_PERIOD_MS 1000u
/* SPL 2025: once every 2 s. Used while the GameController the robot follows is SPL's (v18). */
#define FW_MATCH_DEBUG_PERIOD_SPL_MS 2000u
#define FW_GC_RETURN_PERIOD_MS 1000u    /* the GameController wants 0.5-2 Hz */
#define FW_GC_SILENT_MS 5000u           /* no return packets once the GameController is gone */
#define FW_TEAM_MSG_PORT_BASE 10000u    /* team messages: UDP 10000 + team number */
#define FW_TEAM_MSG_MAX 512u            /* HSL limit on a team message's payload */
#define FW_TEAM_MSG_RESERVE 10u         /* messages of the team budget a robot never uses */
#define FW_MAX_OPTIONS 16u

/* One outgoing message: the extension type and its submessage. Only one message is
 * encoded at a time, so all types share one static union. */
typedef struct {
    const pb_extension_type_t *type;
    union {
        fumanoid_Status status;
        fumanoid_DebugOptionList option_list;
        fumanoid_DebugText text;
        fumanoid_DebugPlot plot;
        fumanoid_DebugTable table;
        fumanoid_RegionGrowing regions;
        fumanoid_Grid grid;
        fumanoid_RelativePositions relative;
        fumanoid_DebugImage image;
        fumanoid_FieldObjects field;
    } m;
} fw_outgoing;

/* Fills out (type and message) with the option's next data; false = nothing to send. */
typedef bool (*fw_produce_fn)(uint32_t now, fw_outgoing *out);

typedef struct {
    const char *name;
    const char *description;
    uint32_t kind; /* a fumanoid_DebugKind value */
    fw_produce_fn produce;
} fw_option_def;

/* What the world (simulation or real sensors) tells the keep-alive. `now` is the robot's
 * motion clock: it stands still while the robot may not move (penalised, SET, stopped...). */
typedef void (*fw_position_fn)(uint32_t now, fumanoid_Position *p);
/* The ball relative to the robot at self (mm); returns seconds since it was seen, -1 never. */
typedef float (*fw_ball_fn)(uint32_t now, const fumanoid_Position *self, float rel[2]);

/* An application on the reliable stream (e.g. the Lorem and Mathe tests). */
typedef struct {
    void (*receive)(void *ctx, const uint8_t *payload, uint16_t n);
    void (*poll)(void *ctx, rs_stream *s, uint32_t now);
    void *ctx;
} fw_stream_app;

typedef struct {
    int32_t robot_id;
    uint32_t team_id;
    const char *name;
    fw_framing framing;
    uint16_t rate_hz;                /* data messages per second per enabled option */
    const fw_option_def *options;
    uint8_t option_count;
    fw_position_fn position;         /* may be NULL */
    bool reliable_enabled;           /* else datagrams that look like segments are errors */
    uint8_t reliable_modulus;
    uint32_t reliable_rto_ms;
    const wlan_peer *reliable_peer;  /* first peer of the stream; NULL = the console */
    const fw_stream_app *stream_app; /* may be NULL */
    /* 2026 field (all optional: zero = off / default) */
    uint16_t gc_return_period_ms;    /* "RGrt" v4 to the GameController; 0 = none, else 500..2000 */
    const wlan_peer *gc_return_to;   /* NULL = the GameController's own address, port 3939 */
    uint16_t team_msg_period_ms;     /* this robot's team messages; 0 = none */
    const wlan_peer *team_msg_to;    /* broadcast (or 127.0.0.1) port 10000 + team; NULL = none */
    uint16_t match_debug_period_ms;  /* console traffic in READY/SET/PLAYING; 0 = the league's: FW_MATCH_DEBUG_PERIOD_MS,
                                      * FW_MATCH_DEBUG_PERIOD_SPL_MS under an SPL GameController */
    fw_ball_fn ball;                 /* may be NULL: ball never seen */
    uint16_t match_budget;           /* a match digest's datagram incl. the tag; 0 = one MTU (capped at 1400) */
    uint8_t match_sends_per_period;  /* 0/1 = the rule; more only to test the console's rule check */
    /* Team key (docs/security.md): NULL = lab mode, as before keys. With a key every datagram
     * from the console must carry a right tag and a newer counter (GameController packets are
     * not tagged: league rules), and the robot tags everything it sends to the console. */
    const fw_team_key *team_key;
    uint32_t boot_id;                /* counted up every boot (kept in flash): the high word of the robot's own
                                      * counter; the console's requests are bound to it */
} robot_config;

typedef struct {
    uint32_t datagrams_in;
    uint32_t messages_handled;
    uint32_t malformed;        /* framing errors and undecodable protobuf */
    uint32_t unknown_ext;
    uint32_t gc_packets;
    uint32_t gc_rejected;
    uint32_t gc_other_team;    /* accepted packets (v18-v20) without our team number */
    uint32_t gc_other_source;  /* good packets from another GameController than the one followed */
    uint32_t gc_returns_out;
    uint32_t team_msgs_out;
    uint32_t team_msgs_held;   /* not sent: the team's message budget is (nearly) used up */
    uint32_t debug_held;       /* option data and lists held back by the game's debug limit */
    uint32_t digests_out;      /* match digests sent */
    uint32_t digest_omitted;   /* chosen items left out of a digest for want of room */
    uint32_t reliable_segments;
    uint32_t messages_out;
    uint32_t send_failures;
    uint32_t bytes_out;
} robot_counters;

void robot_init(const robot_config *cfg, uint32_t now);
void robot_poll(uint32_t now);
/* Classifies one received datagram and hands it to processData, the GameController
 * receiver or the reliable stream. Public for tests and fuzzing. */
void robot_dispatch(const uint8_t *d, uint16_t len, const wlan_peer *from, uint32_t now);
const robot_counters *robot_stats(void);
/* What the verifier did with the console's datagrams (all zero in lab mode). */
const fw_auth_counters *robot_auth_stats(void);
const char *robot_game_state(void);
/* The last GameController packet accepted (valid once robot_gc_heard()). */
const fw_gc_info *robot_gamecontroller(void);
bool robot_gc_heard(void);
/* The game's debug limit applies: the GameController followed says READY, SET or PLAYING, or
 * said it within FW_GC_PLAY_MEMORY_MS. */
bool robot_in_match(void);
/* False while the GameController forbids locomotion (penalised, INITIAL, SET, stopped...). */
bool robot_may_move(void);
/* Milliseconds the robot has been allowed to move: the world's clock for its own pose. */
uint32_t robot_motion_clock(void);
bool robot_option_enabled(const char *name);
bool robot_network_ready(void);
rs_stream *robot_stream(void);

/* Platform hook: one line of diagnostics (stderr on the host). A platform without a console (the
 * board: FW_LOG_NONE) gets an empty inline one, so the calls and their text are compiled away
 * rather than kept in flash for nobody; the counters say what happened there. */
#ifdef FW_LOG_NONE
static inline void fw_log(const char *what, const char *detail, int32_t value)
{
    (void)what;
    (void)detail;
    (void)value;
}
#else
void fw_log(const char *what, const char *detail, int32_t value);
#endif

#endif
