#include "fw_auth.h"
#include "crypto_auth_hmacsha256.h"
#include "crypto_verify_16.h"
#include "utils.h"

static const uint8_t k_magic[4] = {'T', 'L', 'A', '2'};
/* static: the HMAC state is 208 bytes, which the receive path's stack need not carry */
static crypto_auth_hmacsha256_state g_hmac;

void fw_auth_init(fw_auth_state *s, const fw_team_key *key, uint32_t boot)
{
    s->key = key;
    s->boot = boot;
    s->highest = 0;
    s->seen = false;
    s->count = (fw_auth_counters){0};
}

static void put_u64(uint8_t *p, uint64_t v)
{
    int i;
    for (i = 7; i >= 0; i--) {
        p[i] = (uint8_t)v;
        v >>= 8;
    }
}

static uint64_t get_u64(const uint8_t *p)
{
    uint64_t v = 0;
    int i;
    for (i = 0; i < 8; i++) v = (v << 8) | p[i];
    return v;
}

/* The tag over dir ‖ robot ‖ boot (console → robot only) ‖ id_counter (key-id and big-endian
 * counter, 12 bytes, as in the trailer) ‖ payload: the trailer's own bytes are hashed, nothing is
 * rebuilt. */
static void mac(const fw_team_key *k, uint8_t dir, uint8_t robot, uint32_t boot, const uint8_t *id_counter,
                const uint8_t *payload, uint16_t n, uint8_t tag[FW_AUTH_TAG_SIZE])
{
    uint8_t head[6];
    uint8_t full[crypto_auth_hmacsha256_BYTES];
    uint8_t i;
    head[0] = dir;
    head[1] = robot;
    head[2] = (uint8_t)(boot >> 24);
    head[3] = (uint8_t)(boot >> 16);
    head[4] = (uint8_t)(boot >> 8);
    head[5] = (uint8_t)boot;
    crypto_auth_hmacsha256_init(&g_hmac, k->key, FW_AUTH_KEY_SIZE);
    crypto_auth_hmacsha256_update(&g_hmac, head, dir == FW_AUTH_DIR_CONSOLE ? 6u : 2u);
    crypto_auth_hmacsha256_update(&g_hmac, id_counter, FW_AUTH_KEY_ID_SIZE + 8u);
    crypto_auth_hmacsha256_update(&g_hmac, payload, n);
    crypto_auth_hmacsha256_final(&g_hmac, full);
    for (i = 0; i < FW_AUTH_TAG_SIZE; i++) tag[i] = full[i];
    sodium_memzero(full, sizeof full);
}

static void put_id_counter(const fw_team_key *k, uint64_t counter, uint8_t *p)
{
    uint8_t i;
    for (i = 0; i < FW_AUTH_KEY_ID_SIZE; i++) p[i] = k->key_id[i];
    put_u64(p + FW_AUTH_KEY_ID_SIZE, counter);
}

void fw_auth_tag(const fw_team_key *k, uint8_t dir, uint8_t robot, uint32_t boot, uint64_t counter,
                 const uint8_t *payload, uint16_t n, uint8_t tag[FW_AUTH_TAG_SIZE])
{
    uint8_t id_counter[FW_AUTH_KEY_ID_SIZE + 8];
    put_id_counter(k, counter, id_counter);
    mac(k, dir, robot, boot, id_counter, payload, n, tag);
}

uint16_t fw_auth_append(const fw_team_key *k, uint8_t dir, uint8_t robot, uint32_t boot, uint64_t counter, uint8_t *d,
                        uint16_t n, uint16_t cap)
{
    uint8_t i;
    if ((uint32_t)n + FW_AUTH_TRAILER > cap) return 0;
    for (i = 0; i < 4; i++) d[n + i] = k_magic[i];
    put_id_counter(k, counter, d + n + 4);
    mac(k, dir, robot, boot, d + n + 4, d, n, d + n + 16);
    return (uint16_t)(n + FW_AUTH_TRAILER);
}

static bool magic_at(const uint8_t *d, uint16_t len, uint16_t at)
{
    return (uint32_t)at + 4u <= len && d[at] == k_magic[0] && d[at + 1] == k_magic[1] && d[at + 2] == k_magic[2] &&
           d[at + 3] == k_magic[3];
}

bool fw_auth_has_trailer(const uint8_t *d, uint16_t len)
{
    return len >= FW_AUTH_TRAILER && magic_at(d, len, (uint16_t)(len - FW_AUTH_TRAILER));
}

/* A trailer cut short: the magic within the last 31..4 bytes. */
static bool cut_trailer(const uint8_t *d, uint16_t len)
{
    uint16_t back;
    for (back = FW_AUTH_TRAILER - 1u; back >= 4u; back--) {
        if (back <= len && magic_at(d, len, (uint16_t)(len - back))) return true;
    }
    return false;
}

fw_auth_result fw_auth_check(fw_auth_state *s, uint8_t dir, uint8_t robot, const uint8_t *d, uint16_t len,
                             uint16_t *payload_len)
{
    uint8_t tag[FW_AUTH_TAG_SIZE];
    const uint8_t *t;
    uint64_t counter;
    uint16_t n;
    uint8_t i;
    bool whole = fw_auth_has_trailer(d, len);
    if (s->key == 0) {
        *payload_len = whole ? (uint16_t)(len - FW_AUTH_TRAILER) : len;
        return FW_AUTH_LAB;
    }
    if (!whole) {
        if (cut_trailer(d, len)) {
            s->count.truncated++;
            return FW_AUTH_TRUNCATED;
        }
        s->count.missing++;
        return FW_AUTH_MISSING;
    }
    n = (uint16_t)(len - FW_AUTH_TRAILER);
    t = d + n;
    for (i = 0; i < FW_AUTH_KEY_ID_SIZE; i++) {
        if (t[4 + i] != s->key->key_id[i]) {
            s->count.wrong_key++;
            return FW_AUTH_WRONG_KEY;
        }
    }
    counter = get_u64(t + 8);
    mac(s->key, dir, robot, s->boot, t + 4, d, n, tag);
    if (crypto_verify_16(tag, t + 16) != 0) {
        s->count.bad_tag++;
        return FW_AUTH_BAD_TAG;
    }
    if (s->seen && counter <= s->highest) {
        s->count.replayed++;
        return FW_AUTH_REPLAYED;
    }
    s->seen = true;
    s->highest = counter;
    s->count.accepted++;
    *payload_len = n;
    return FW_AUTH_OK;
}

const char *fw_auth_result_name(fw_auth_result r)
{
    /* short: flash wherever they are logged (not on the board: FW_LOG_NONE compiles the logs away) */
    static const char *const names[] = {"ok", "lab", "no tag", "truncated tag", "other key", "bad tag", "replayed"};
    return (unsigned)r < sizeof names / sizeof names[0] ? names[r] : "?";
}

static int hex_nibble(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

static int parse_hex(const char *hex, uint8_t *out, uint8_t n)
{
    uint8_t i;
    for (i = 0; i < n; i++) {
        int hi, lo;
        if (hex[2 * i] == '\0' || hex[2 * i + 1] == '\0') return -1;
        hi = hex_nibble(hex[2 * i]);
        lo = hex_nibble(hex[2 * i + 1]);
        if (hi < 0 || lo < 0) return -1;
        out[i] = (uint8_t)(hi << 4 | lo);
    }
    return hex[2 * n] == '\0' ? 0 : -1;
}

int fw_auth_parse_hex(const char *hex64, const char *hex8, fw_team_key *out)
{
    if (parse_hex(hex64, out->key, FW_AUTH_KEY_SIZE) != 0) return -1;
    return parse_hex(hex8, out->key_id, FW_AUTH_KEY_ID_SIZE);
}
