/* Framing, the extension registry (processData) and the robot's dispatch, keep-alive,
 * option list, option data and GameController receiver, against a fake network driver. */
#include <string.h>
#include <pb_decode.h>
#include "fw_framing.h"
#include "fw_gamecontroller.h"
#include "fw_registry.h"
#include "fw_robot.h"
#include "sim_world.h"
#include "test_util.h"

/* ---- a fake network driver: an inbox of datagrams and a log of what was sent ---- */
#define MAX_SENT 256
static uint8_t sent[MAX_SENT][FW_MAX_DATAGRAM];
static uint16_t sent_len[MAX_SENT];
static int sent_count;
static uint8_t inbox[8][FW_MAX_DATAGRAM];
static uint16_t inbox_len[8];
static int inbox_head, inbox_tail;

static bool fake_init(void *ctx, uint32_t now) { (void)ctx; (void)now; return true; }
static bool fake_recv(void *ctx, uint8_t *buf, uint16_t cap, uint16_t *len, wlan_peer *from)
{
    (void)ctx;
    if (inbox_head == inbox_tail) return false;
    CHECK(inbox_len[inbox_head] <= cap);
    memcpy(buf, inbox[inbox_head], inbox_len[inbox_head]);
    *len = inbox_len[inbox_head];
    memset(from, 0, sizeof *from);
    inbox_head = (inbox_head + 1) % 8;
    return true;
}
static bool fake_send_con(void *ctx, const uint8_t *msg, uint16_t len, char cid)
{
    (void)ctx; (void)cid;
    CHECK(len <= FW_MAX_DATAGRAM);
    if (sent_count < MAX_SENT) {
        memcpy(sent[sent_count], msg, len);
        sent_len[sent_count] = len;
        sent_count++;
    }
    return true;
}
static bool fake_send_peer(void *ctx, const wlan_peer *to, const uint8_t *msg, uint16_t len)
{
    (void)to;
    return fake_send_con(ctx, msg, len, 0);
}
static const wlan_driver fake = {fake_init, fake_recv, fake_send_con, fake_send_peer, NULL};

static void deliver(const uint8_t *d, uint16_t n)
{
    memcpy(inbox[inbox_tail], d, n);
    inbox_len[inbox_tail] = n;
    inbox_tail = (inbox_tail + 1) % 8;
}

/* Decodes a sent datagram with nanopb's own extension support (a cross-check of ours). */
static int decode_sent(int i, const pb_extension_type_t *type, void *dest, int32_t *robot_id)
{
    fw_datagram_info info;
    fumanoid_Message m = fumanoid_Message_init_zero;
    pb_extension_t ext;
    pb_istream_t s;
    fw_classify(sent[i], sent_len[i], &info);
    if (info.kind != FW_DGRAM_FUMANOID) return 0;
    ext.type = type;
    ext.dest = dest;
    ext.next = NULL;
    ext.found = false;
    m.extensions = &ext;
    s = pb_istream_from_buffer(sent[i] + info.payload_off, info.payload_len);
    if (!pb_decode(&s, fumanoid_Message_fields, &m)) return 0;
    if (robot_id) *robot_id = m.robotID;
    return ext.found ? 1 : 0;
}

static fumanoid_Status st;
static int last_status(void)
{
    int i;
    for (i = sent_count - 1; i >= 0; i--)
        if (decode_sent(i, &fumanoid_status, &st, NULL)) return 1;
    return 0;
}

/* ---- processData against a test registry ---- */
static fumanoid_DebugOptionRequest req_dest;
static int req_calls;
static int32_t req_sender;
static void on_req(int32_t sender, const void *msg)
{
    (void)msg;
    req_calls++;
    req_sender = sender;
}

static void test_golden_status(void)
{
    /* The worked example of the thesis: robotID 1, Status{teamID 1, activeRole "AgentTest"}.
     * The brief prints the submessage length as 0x0E, but its own header says 18 payload
     * bytes, which only adds up with 13 = 0x0D (2 + 2 + 9): 0x0D is the correct encoding. */
    static const uint8_t expected[] = {0, 42, 0, 0, 0, 0, 0, 0, 0, 0, 0, 18,
                                       0x08, 0x01, 0xBA, 0x01, 0x0D, 0x10, 0x01, 0x7A, 0x09,
                                       'A', 'g', 'e', 'n', 't', 'T', 'e', 's', 't'};
    static uint8_t out[FW_MAX_DATAGRAM];
    fumanoid_Status s = fumanoid_Status_init_zero;
    uint16_t n;
    s.has_teamID = true;
    s.teamID = 1;
    s.has_activeRole = true;
    strcpy(s.activeRole, "AgentTest");
    n = fw_encode_message(out, sizeof out, FW_FRAMING_LEGACY, 1, &fumanoid_status, &s);
    CHECK_EQ(n, sizeof expected);
    CHECK(memcmp(out, expected, sizeof expected) == 0);
    if (memcmp(out, expected, sizeof expected) != 0) {
        uint16_t k;
        for (k = 0; k < n; k++) fprintf(stderr, "%02X ", out[k]);
        fprintf(stderr, "\n");
    }
    n = fw_encode_message(out, sizeof out, FW_FRAMING_LENGTH, 1, &fumanoid_status, &s);
    CHECK_EQ(n, 4 + 18);
    CHECK(out[0] == 0 && out[1] == 0 && out[2] == 0 && out[3] == 18 && out[4] == 0x08);
    /* too small a buffer: no partial datagram */
    CHECK_EQ(fw_encode_message(out, 20, FW_FRAMING_LEGACY, 1, &fumanoid_status, &s), 0);
}

static void test_classify(void)
{
    static const uint8_t legacy[] = {0, 42, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0x08, 0x01};
    static const uint8_t legacy_bad[] = {0, 42, 0, 0, 0, 0, 0, 0, 0, 0, 0, 9, 0x08, 0x01};
    static const uint8_t length[] = {0, 0, 0, 2, 0x08, 0x01};
    static const uint8_t gc[] = {'R', 'G', 'm', 'e', 12, 0};
    static const uint8_t seg[] = {3, 7, 'h', 'i'};
    static const uint8_t junk[] = {0xFF, 0xFE, 0xFD};
    static uint8_t big[FW_MAX_DATAGRAM + 1];
    fw_datagram_info i;
    fw_classify(legacy, sizeof legacy, &i);
    CHECK_EQ(i.kind, FW_DGRAM_FUMANOID);
    CHECK_EQ(i.framing, FW_FRAMING_LEGACY);
    CHECK_EQ(i.payload_off, 12);
    CHECK_EQ(i.payload_len, 2);
    fw_classify(legacy_bad, sizeof legacy_bad, &i);
    CHECK_EQ(i.kind, FW_DGRAM_BAD_LENGTH);
    CHECK_EQ(i.declared_len, 9);
    fw_classify(legacy, 7, &i);
    CHECK_EQ(i.kind, FW_DGRAM_TOO_SHORT);
    fw_classify(length, sizeof length, &i);
    CHECK_EQ(i.kind, FW_DGRAM_FUMANOID);
    CHECK_EQ(i.framing, FW_FRAMING_LENGTH);
    CHECK_EQ(i.payload_len, 2);
    fw_classify(gc, sizeof gc, &i);
    CHECK_EQ(i.kind, FW_DGRAM_GAMECONTROLLER);
    fw_classify(seg, sizeof seg, &i);
    CHECK_EQ(i.kind, FW_DGRAM_RELIABLE);
    fw_classify(junk, sizeof junk, &i);
    CHECK_EQ(i.kind, FW_DGRAM_UNKNOWN);
    fw_classify(junk, 1, &i);
    CHECK_EQ(i.kind, FW_DGRAM_TOO_SHORT);
    fw_classify(big, sizeof big, &i);
    CHECK_EQ(i.kind, FW_DGRAM_TOO_LONG);
}

static void test_process_data(void)
{
    static const fw_registry_entry table[] = {{42, fumanoid_DebugOptionRequest_fields, &req_dest, on_req}};
    static uint8_t out[FW_MAX_DATAGRAM];
    fumanoid_DebugOptionRequest r = fumanoid_DebugOptionRequest_init_zero;
    uint16_t n;
    /* Message{robotID 5, field 77 (unknown extension) = {}} */
    static const uint8_t unknown[] = {0x08, 0x05, 0xEA, 0x04, 0x00};
    static const uint8_t no_id[] = {0xEA, 0x04, 0x00};
    static const uint8_t garbage[] = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
    static const uint8_t only_id[] = {0x08, 0x05};
    fw_registry_use(table, 1);
    strcpy(r.name, "demo.image");
    r.enable = true;
    n = fw_encode_message(out, sizeof out, FW_FRAMING_LEGACY, -7, &fumanoid_debugOptionRequest, &r);
    CHECK(n > 12);
    CHECK_EQ(processData(out + 12, (uint16_t)(n - 12)), FW_OK);
    CHECK_EQ(req_calls, 1);
    CHECK_EQ(req_sender, -7);
    CHECK(strcmp(req_dest.name, "demo.image") == 0);
    CHECK(req_dest.enable);
    CHECK_EQ(processData(unknown, sizeof unknown), FW_ERR_UNKNOWN_EXT);
    CHECK_EQ(fw_last_report()->ext, 77);
    CHECK_EQ(processData(no_id, sizeof no_id), FW_ERR_NO_ROBOT_ID);
    CHECK_EQ(processData(garbage, sizeof garbage), FW_ERR_DECODE);
    CHECK_EQ(processData(only_id, sizeof only_id), FW_ERR_NO_EXTENSION);
    /* every truncation of a good message fails cleanly, never calls the handler */
    {
        uint16_t cut;
        for (cut = 0; cut + 12 < n; cut++) CHECK(processData(out + 12, cut) != FW_OK);
    }
    CHECK_EQ(req_calls, 1);
    /* an option name longer than the nanopb limit is a decode error, not an overflow */
    {
        static const uint8_t longname[] = {0x08, 0x01, 0xD2, 0x02, 0x24, 0x0A, 0x22,
                                           'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a',
                                           'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 'a', 0x10, 0x01};
        CHECK_EQ(processData(longname, sizeof longname), FW_ERR_DECODE);
    }
    CHECK_EQ(req_calls, 1);
}

static uint16_t encode_request(uint8_t *out, const pb_extension_type_t *t, const void *m, fw_framing f)
{
    return fw_encode_message(out, FW_MAX_DATAGRAM, f, 100, t, m);
}

static void test_robot(void)
{
    static robot_config cfg;
    static uint8_t out[FW_MAX_DATAGRAM];
    static uint8_t gc[688];
    static fumanoid_DebugOptionList list;
    static fumanoid_DebugImage img;
    static fumanoid_RegionGrowing reg;
    fumanoid_DebugOptionListRequest lr = fumanoid_DebugOptionListRequest_init_zero;
    fumanoid_DebugOptionRequest r = fumanoid_DebugOptionRequest_init_zero;
    uint32_t now = 1000;
    int i, images = 0, regions = 0, lists = 0;
    uint16_t n;

    memset(&cfg, 0, sizeof cfg);
    cfg.robot_id = 3;
    cfg.team_id = 13;
    cfg.name = "tester";
    cfg.framing = FW_FRAMING_LENGTH;
    cfg.rate_hz = 10;
    sim_world_init(3);
    cfg.options = sim_world_options(&cfg.option_count);
    cfg.position = sim_world_position;
    wlan_use(&fake);
    robot_init(&cfg, now);

    robot_poll(now);
    CHECK(last_status());
    CHECK(strcmp(st.gameState, "INITIAL") == 0);
    CHECK(strcmp(st.robotName, "tester") == 0);
    CHECK(strcmp(st.activeRole, "striker") == 0);
    CHECK_EQ(st.teamID, 13);
    CHECK(st.has_robotPosition);
    CHECK_EQ(sent[0][0], 0); /* length framing */
    CHECK_EQ(sent[0][1], 0);

    /* keep-alive every 200 ms: 5 in one second */
    sent_count = 0;
    for (i = 1; i <= 100; i++) robot_poll(now + (uint32_t)i * 10);
    CHECK_EQ(sent_count, 5);
    now += 1000;

    /* option list on request, in the requester's framing-independent way */
    n = encode_request(out, &fumanoid_debugOptionListRequest, &lr, FW_FRAMING_LEGACY);
    deliver(out, n);
    sent_count = 0;
    robot_poll(now);
    for (i = 0; i < sent_count; i++) {
        if (decode_sent(i, &fumanoid_debugOptionList, &list, NULL)) lists++;
    }
    CHECK_EQ(lists, 1);
    CHECK_EQ(list.options_count, 8);
    CHECK(strcmp(list.options[0].name, "demo.text") == 0);
    CHECK(strcmp(list.options[7].name, "havimo.grid") == 0);
    CHECK_EQ(list.options[3].kind, fumanoid_DebugKind_IMAGE);
    CHECK(!list.options[3].enabled);

    /* switch demo.image and havimo.region on: about 10 messages per second each */
    strcpy(r.name, "demo.image");
    r.enable = true;
    deliver(out, encode_request(out, &fumanoid_debugOptionRequest, &r, FW_FRAMING_LENGTH));
    strcpy(r.name, "havimo.region");
    deliver(out, encode_request(out, &fumanoid_debugOptionRequest, &r, FW_FRAMING_LEGACY));
    sent_count = 0;
    for (i = 0; i < 100; i++) robot_poll(now + (uint32_t)i * 10);
    now += 1000;
    CHECK(robot_option_enabled("demo.image"));
    for (i = 0; i < sent_count; i++) {
        CHECK(sent_len[i] <= FW_MAX_DATAGRAM);
        if (decode_sent(i, &fumanoid_debugImage, &img, NULL)) {
            images++;
            CHECK_EQ(img.width * img.height, img.data.size);
        }
        if (decode_sent(i, &fumanoid_regionGrowing, &reg, NULL)) {
            regions++;
            CHECK_EQ(reg.frameWidth, 160);
            CHECK(reg.regions_count >= 1);
        }
        if (decode_sent(i, &fumanoid_debugOptionList, &list, NULL)) lists++;
    }
    CHECK(images >= 9 && images <= 11);
    CHECK(regions >= 9 && regions <= 11);
    CHECK(lists >= 2); /* a fresh list after each switch */

    /* switched off: no more images */
    strcpy(r.name, "demo.image");
    r.enable = false;
    deliver(out, encode_request(out, &fumanoid_debugOptionRequest, &r, FW_FRAMING_LEGACY));
    robot_poll(now);
    sent_count = 0;
    images = 0;
    for (i = 1; i < 50; i++) robot_poll(now + (uint32_t)i * 10);
    now += 500;
    for (i = 0; i < sent_count; i++)
        if (decode_sent(i, &fumanoid_debugImage, &img, NULL)) images++;
    CHECK_EQ(images, 0);

    /* all options on at --rate 10: every datagram still <= 1400 bytes */
    for (i = 0; i < cfg.option_count; i++) {
        strcpy(r.name, cfg.options[i].name);
        r.enable = true;
        deliver(out, encode_request(out, &fumanoid_debugOptionRequest, &r, FW_FRAMING_LEGACY));
        robot_poll(now);
    }
    sent_count = 0;
    for (i = 0; i < 30; i++) robot_poll(now + (uint32_t)i * 10);
    now += 300;
    CHECK(sent_count >= 8 * 2); /* each option once per 100 ms (all were sent at "now") */
    CHECK_EQ(robot_stats()->send_failures, 0);

    /* GameController HL v12: 688 bytes, state PLAYING at offset 9 */
    memset(gc, 0, sizeof gc);
    memcpy(gc, "RGme", 4);
    gc[4] = 12;
    gc[9] = 3;
    deliver(gc, 688);
    robot_poll(now);
    sent_count = 0;
    robot_poll(now + 1000); /* during play the Status comes once a second (test_gamecontroller.c) */
    now += 1000;
    CHECK(last_status());
    CHECK(strcmp(st.gameState, "PLAYING") == 0);
    /* wrong length is rejected, state unchanged */
    gc[9] = 4;
    deliver(gc, 687);
    robot_poll(now);
    CHECK(strcmp(robot_game_state(), "PLAYING") == 0);
    CHECK_EQ(robot_stats()->gc_rejected, 1);
    /* 2014 v8: 158 bytes, state at offset 7 */
    memset(gc, 0, sizeof gc);
    memcpy(gc, "RGme", 4);
    gc[4] = 8;
    gc[7] = 2;
    deliver(gc, 158);
    robot_poll(now);
    CHECK(strcmp(robot_game_state(), "SET") == 0);

    /* malformed input is counted and the next good datagram still works */
    {
        static const uint8_t junk[] = {0xFF, 0x00, 0x13};
        static const uint8_t badlen[] = {0, 42, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0x08};
        static const uint8_t unknown[] = {0, 0, 0, 5, 0x08, 0x05, 0xEA, 0x04, 0x00};
        static const uint8_t notpb[] = {0, 0, 0, 3, 0xFF, 0xFF, 0xFF};
        static const uint8_t seg[] = {0, 0, 0, 9, 'x'}; /* looks like a segment, stream off */
        uint32_t before = robot_stats()->malformed;
        deliver(junk, sizeof junk);
        deliver(badlen, sizeof badlen);
        deliver(unknown, sizeof unknown);
        deliver(notpb, sizeof notpb);
        deliver(seg, sizeof seg);
        robot_poll(now);
        CHECK_EQ(robot_stats()->malformed, before + 4);
        CHECK_EQ(robot_stats()->unknown_ext, 1);
        strcpy(r.name, "demo.text");
        r.enable = false;
        deliver(out, encode_request(out, &fumanoid_debugOptionRequest, &r, FW_FRAMING_LEGACY));
        robot_poll(now);
        CHECK(!robot_option_enabled("demo.text"));
    }
}

int main(void)
{
    test_golden_status();
    test_classify();
    test_process_data();
    test_robot();
    {
        fw_gc_info info;
        static uint8_t p[688];
        memcpy(p, "RGme", 4);
        CHECK_EQ(fw_gc_parse(p, 5, 0, 0, &info), FW_GC_BAD_MAGIC);
        p[4] = 99;
        CHECK_EQ(fw_gc_parse(p, 688, 0, 0, &info), FW_GC_BAD_VERSION);
        p[4] = 18;
        p[10] = 1;
        CHECK_EQ(fw_gc_parse(p, 118, 0, 0, &info), FW_GC_OK);
        CHECK_EQ(info.state, 1);
        CHECK_EQ(fw_gc_parse(p, 117, 0, 0, &info), FW_GC_BAD_LENGTH);
    }
    TEST_DONE();
}
