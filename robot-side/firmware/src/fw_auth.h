/* Message authentication of the small-robot link (docs/security.md): a 32-byte trailer
 *
 *   payload ‖ "TLA2" ‖ key-id (4) ‖ counter (8, big-endian) ‖ tag (16)
 *
 * where tag = the first 16 bytes of HMAC-SHA-256(team key,
 *   direction (1: 'C' console→robot, 'R' robot→console) ‖ robot id (1) ‖ [boot (4)] ‖ key-id ‖ counter ‖ payload).
 * Console → robot tags are bound to the robot's current boot (its boot number, big-endian, hashed
 * but not sent): a request captured in an earlier boot fails after a reboot. Robot → console tags
 * carry the boot in the counter's high word and hash no boot field.
 * HMAC-SHA-256 is libsodium's (third_party/libsodium, crypto_auth_hmacsha256), never our own.
 * Trailer version 2: version 1 ("TLA1", Touchline 0.5) was HMAC-SHA-512 and is not accepted (a
 * datagram with it counts as "no tag"). Static memory only. */
#ifndef FW_AUTH_H
#define FW_AUTH_H

#include <stdbool.h>
#include <stdint.h>

#define FW_AUTH_KEY_SIZE 32u
#define FW_AUTH_KEY_ID_SIZE 4u
#define FW_AUTH_TAG_SIZE 16u
#define FW_AUTH_TRAILER 32u /* magic 4 + key-id 4 + counter 8 + tag 16 */
#define FW_AUTH_DIR_CONSOLE 0x43u /* 'C': console → robot */
#define FW_AUTH_DIR_ROBOT 0x52u   /* 'R': robot → console */

typedef struct {
    uint8_t key[FW_AUTH_KEY_SIZE];
    uint8_t key_id[FW_AUTH_KEY_ID_SIZE];
} fw_team_key;

typedef enum {
    FW_AUTH_OK,        /* tag right, counter newer: dispatch the payload */
    FW_AUTH_LAB,       /* no key configured: the payload (trailer stripped if any) as today */
    FW_AUTH_MISSING,   /* key configured, datagram without a trailer */
    FW_AUTH_TRUNCATED, /* a trailer cut short (magic found, fewer than 32 bytes after it) */
    FW_AUTH_WRONG_KEY, /* trailer of another key-id */
    FW_AUTH_BAD_TAG,   /* tag does not match */
    FW_AUTH_REPLAYED   /* tag right, counter not newer than the highest seen */
} fw_auth_result;

typedef struct {
    uint32_t accepted;
    uint32_t missing;
    uint32_t truncated;
    uint32_t wrong_key;
    uint32_t bad_tag;
    uint32_t replayed;
} fw_auth_counters;

/* What a receiver remembers: the key (NULL = lab mode), its own boot (console requests are
 * bound to it) and the highest counter accepted in this boot. */
typedef struct {
    const fw_team_key *key;
    uint32_t boot;
    uint64_t highest;
    bool seen;
    fw_auth_counters count;
} fw_auth_state;

void fw_auth_init(fw_auth_state *s, const fw_team_key *key, uint32_t boot);
/* The 16-byte tag over direction, robot id, the robot's boot (console → robot only), key-id,
 * counter and payload. */
void fw_auth_tag(const fw_team_key *k, uint8_t dir, uint8_t robot, uint32_t boot, uint64_t counter,
                 const uint8_t *payload, uint16_t n, uint8_t tag[FW_AUTH_TAG_SIZE]);
/* Appends the trailer to d[0..n) (d holds cap bytes); returns the new length, 0 if it does not fit. */
uint16_t fw_auth_append(const fw_team_key *k, uint8_t dir, uint8_t robot, uint32_t boot, uint64_t counter, uint8_t *d,
                        uint16_t n, uint16_t cap);
/* True when d ends with a whole trailer (magic at len - 32). */
bool fw_auth_has_trailer(const uint8_t *d, uint16_t len);
/* Checks a datagram from the console addressed to robot (dir 'C', bound to s->boot); on OK or LAB *payload_len
 * is the length without the trailer. Counts every result in s->count. */
fw_auth_result fw_auth_check(fw_auth_state *s, uint8_t dir, uint8_t robot, const uint8_t *d, uint16_t len,
                             uint16_t *payload_len);
const char *fw_auth_result_name(fw_auth_result r);
/* "team-key = <64 hex>" text or raw 36-byte blob (key ‖ key-id) → key; 0 on success. */
int fw_auth_parse_hex(const char *hex64, const char *hex8, fw_team_key *out);

#endif
