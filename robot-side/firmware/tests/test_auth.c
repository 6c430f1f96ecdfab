/* The firmware's verifier: the golden vector (the console's HmacSHA256 and Python's hmac give
 * the same tag for the same bytes, docs/security.md), and every way a datagram is refused. */
#include <string.h>
#include "fw_auth.h"
#include "test_util.h"

static fw_team_key golden_key(void)
{
    fw_team_key k;
    uint8_t i;
    for (i = 0; i < 32; i++) k.key[i] = i;
    /* key-id: the first 4 bytes of SHA-256(key) */
    k.key_id[0] = 0x63;
    k.key_id[1] = 0x0d;
    k.key_id[2] = 0xcd;
    k.key_id[3] = 0x29;
    return k;
}

static void test_golden_vector(void)
{
    /* the first 16 bytes of HMAC-SHA-256 (trailer version 2); console → robot for the robot's boot 7 */
    static const uint8_t to_robot[16] = {0xf8, 0x9a, 0xe0, 0xad, 0xf6, 0x49, 0xe6, 0xd7,
                                         0xc5, 0x78, 0x14, 0x0c, 0xb7, 0x9a, 0x8a, 0x5f};
    static const uint8_t from_robot[16] = {0x5c, 0x6b, 0x40, 0x99, 0xc5, 0x65, 0x82, 0x88,
                                           0xdf, 0xe0, 0x2f, 0x50, 0x62, 0x8d, 0xca, 0x73};
    fw_team_key k = golden_key();
    uint8_t tag[16];
    fw_auth_tag(&k, FW_AUTH_DIR_CONSOLE, 3, 7, 0x0123456789abcdefull, (const uint8_t *)"hello", 5, tag);
    CHECK(memcmp(tag, to_robot, 16) == 0);
    fw_auth_tag(&k, FW_AUTH_DIR_CONSOLE, 3, 8, 0x0123456789abcdefull, (const uint8_t *)"hello", 5, tag);
    CHECK(memcmp(tag, to_robot, 16) != 0); /* the robot's next boot: another tag */
    /* robot → console: the boot is in the counter, no boot field is hashed */
    fw_auth_tag(&k, FW_AUTH_DIR_ROBOT, 3, 0, 0x0123456789abcdefull, (const uint8_t *)"hello", 5, tag);
    CHECK(memcmp(tag, from_robot, 16) == 0);
    fw_auth_tag(&k, FW_AUTH_DIR_ROBOT, 3, 8, 0x0123456789abcdefull, (const uint8_t *)"hello", 5, tag);
    CHECK(memcmp(tag, from_robot, 16) == 0);
}

static uint16_t tagged(const fw_team_key *k, uint8_t robot, uint64_t counter, uint8_t *d, const char *payload)
{
    uint16_t n = (uint16_t)strlen(payload);
    memcpy(d, payload, n);
    return fw_auth_append(k, FW_AUTH_DIR_CONSOLE, robot, 7, counter, d, n, 200); /* for the robot's boot 7 */
}

static void test_check(void)
{
    fw_team_key k = golden_key(), other = golden_key();
    fw_auth_state s;
    uint8_t d[200], replay[200];
    uint16_t n, rn, payload = 0;
    other.key[0] ^= 1;
    fw_auth_init(&s, &k, 7);

    n = tagged(&k, 3, 100, d, "option on");
    CHECK_EQ(n, 9 + FW_AUTH_TRAILER);
    memcpy(replay, d, n);
    rn = n;
    CHECK_EQ(fw_auth_check(&s, FW_AUTH_DIR_CONSOLE, 3, d, n, &payload), FW_AUTH_OK);
    CHECK_EQ(payload, 9);
    /* the same datagram again, and an older counter: replays */
    CHECK_EQ(fw_auth_check(&s, FW_AUTH_DIR_CONSOLE, 3, replay, rn, &payload), FW_AUTH_REPLAYED);
    n = tagged(&k, 3, 99, d, "option on");
    CHECK_EQ(fw_auth_check(&s, FW_AUTH_DIR_CONSOLE, 3, d, n, &payload), FW_AUTH_REPLAYED);
    /* no trailer at all */
    CHECK_EQ(fw_auth_check(&s, FW_AUTH_DIR_CONSOLE, 3, (const uint8_t *)"option on", 9, &payload), FW_AUTH_MISSING);
    /* a version-1 trailer (Touchline 0.5's "TLA1", HMAC-SHA-512): not one this firmware checks */
    n = tagged(&k, 3, 100, d, "option on");
    d[9 + 3] = '1';
    CHECK_EQ(fw_auth_check(&s, FW_AUTH_DIR_CONSOLE, 3, d, n, &payload), FW_AUTH_MISSING);
    /* a trailer cut short by 8 bytes */
    n = tagged(&k, 3, 101, d, "option on");
    CHECK_EQ(fw_auth_check(&s, FW_AUTH_DIR_CONSOLE, 3, d, (uint16_t)(n - 8), &payload), FW_AUTH_TRUNCATED);
    /* another robot's datagram, a payload changed, a tag changed, a datagram of robot to console */
    n = tagged(&k, 4, 102, d, "option on");
    CHECK_EQ(fw_auth_check(&s, FW_AUTH_DIR_CONSOLE, 3, d, n, &payload), FW_AUTH_BAD_TAG);
    n = tagged(&k, 3, 103, d, "option on");
    d[0] ^= 0x20;
    CHECK_EQ(fw_auth_check(&s, FW_AUTH_DIR_CONSOLE, 3, d, n, &payload), FW_AUTH_BAD_TAG);
    n = tagged(&k, 3, 104, d, "option on");
    d[n - 1] ^= 1;
    CHECK_EQ(fw_auth_check(&s, FW_AUTH_DIR_CONSOLE, 3, d, n, &payload), FW_AUTH_BAD_TAG);
    n = (uint16_t)fw_auth_append(&k, FW_AUTH_DIR_ROBOT, 3, 7, 105, (uint8_t *)memcpy(d, "status", 6), 6, 200);
    CHECK_EQ(fw_auth_check(&s, FW_AUTH_DIR_CONSOLE, 3, d, n, &payload), FW_AUTH_BAD_TAG);
    /* the wrong key: same key-id forged → bad tag; another key-id → wrong key */
    n = tagged(&other, 3, 106, d, "option on");
    CHECK_EQ(fw_auth_check(&s, FW_AUTH_DIR_CONSOLE, 3, d, n, &payload), FW_AUTH_BAD_TAG);
    other.key_id[0] ^= 1;
    n = tagged(&other, 3, 107, d, "option on");
    CHECK_EQ(fw_auth_check(&s, FW_AUTH_DIR_CONSOLE, 3, d, n, &payload), FW_AUTH_WRONG_KEY);
    /* none of those moved the counter: the next right one is accepted */
    n = tagged(&k, 3, 101, d, "option off");
    CHECK_EQ(fw_auth_check(&s, FW_AUTH_DIR_CONSOLE, 3, d, n, &payload), FW_AUTH_OK);
    CHECK_EQ(s.count.accepted, 2u);
    CHECK_EQ(s.count.replayed, 2u);
    CHECK_EQ(s.count.missing, 2u);
    CHECK_EQ(s.count.truncated, 1u);
    CHECK_EQ(s.count.bad_tag, 5u);
    CHECK_EQ(s.count.wrong_key, 1u);
    /* no room for the trailer */
    CHECK_EQ(fw_auth_append(&k, FW_AUTH_DIR_CONSOLE, 3, 7, 1, d, 180, 200), 0);
}

/* A reboot: the requests of the earlier boot, captured and played in counter order, are refused. */
static void test_captures_of_an_earlier_boot(void)
{
    fw_team_key k = golden_key();
    fw_auth_state before, after;
    uint8_t d[200];
    uint16_t n, payload = 0;
    fw_auth_init(&before, &k, 7);
    n = tagged(&k, 3, 500, d, "option on");
    CHECK_EQ(fw_auth_check(&before, FW_AUTH_DIR_CONSOLE, 3, d, n, &payload), FW_AUTH_OK);
    fw_auth_init(&after, &k, 8); /* the robot restarted: boot 8, no counter remembered */
    CHECK_EQ(fw_auth_check(&after, FW_AUTH_DIR_CONSOLE, 3, d, n, &payload), FW_AUTH_BAD_TAG);
    CHECK_EQ(after.count.bad_tag, 1u);
    n = fw_auth_append(&k, FW_AUTH_DIR_CONSOLE, 3, 8, 400, (uint8_t *)memcpy(d, "option on", 9), 9, 200);
    CHECK_EQ(fw_auth_check(&after, FW_AUTH_DIR_CONSOLE, 3, d, n, &payload), FW_AUTH_OK);
}

static void test_lab_mode(void)
{
    fw_team_key k = golden_key();
    fw_auth_state s;
    uint8_t d[200];
    uint16_t n, payload = 0;
    fw_auth_init(&s, 0, 7);
    CHECK_EQ(fw_auth_check(&s, FW_AUTH_DIR_CONSOLE, 3, (const uint8_t *)"plain", 5, &payload), FW_AUTH_LAB);
    CHECK_EQ(payload, 5);
    n = tagged(&k, 3, 1, d, "tagged");
    CHECK_EQ(fw_auth_check(&s, FW_AUTH_DIR_CONSOLE, 3, d, n, &payload), FW_AUTH_LAB);
    CHECK_EQ(payload, 6); /* a tagged datagram from a keyed console: trailer stripped */
}

static void test_parse_hex(void)
{
    fw_team_key k;
    CHECK_EQ(fw_auth_parse_hex("000102030405060708090a0b0c0d0e0f101112131415161718191a1b1c1d1e1f", "630dcd29", &k), 0);
    CHECK_EQ(k.key[31], 0x1f);
    CHECK_EQ(k.key_id[3], 0x29);
    CHECK_EQ(fw_auth_parse_hex("0001", "630dcd29", &k), -1);                     /* too short */
    CHECK_EQ(fw_auth_parse_hex("000102030405060708090a0b0c0d0e0f101112131415161718191a1b1c1d1e1f00", "630dcd29", &k), -1);
    CHECK_EQ(fw_auth_parse_hex("zz0102030405060708090a0b0c0d0e0f101112131415161718191a1b1c1d1e1f", "630dcd29", &k), -1);
}

int main(void)
{
    test_golden_vector();
    test_captures_of_an_earlier_boot();
    test_check();
    test_lab_mode();
    test_parse_hex();
    TEST_DONE();
}
