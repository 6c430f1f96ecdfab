/* The match digest builder (fw_digest.c) against the golden vector the console's Java test
 * reads too (src/test/resources/golden/fumanoid/match-digest.bin, encoded by protoc from
 * match-digest.txt): the same Status and items under a 200-byte budget give the same bytes,
 * the long third item is left out and counted, and no budget is ever exceeded. */
#include <string.h>
#include "fw_digest.h"
#include "fw_registry.h"
#include "test_util.h"

static uint8_t g_golden[2048];
static uint8_t g_buf[FW_MAX_DATAGRAM];

static size_t read_golden(const char *dir)
{
    char path[1024];
    FILE *f;
    size_t n;
    snprintf(path, sizeof path, "%s/match-digest.bin", dir);
    f = fopen(path, "rb");
    if (f == NULL) {
        fprintf(stderr, "cannot open %s\n", path);
        exit(1);
    }
    n = fread(g_golden, 1, sizeof g_golden, f);
    fclose(f);
    return n;
}

static void golden_status(fumanoid_Status *st)
{
    *st = (fumanoid_Status)fumanoid_Status_init_zero;
    st->has_timestamp = true;
    st->timestamp = 123456;
    st->has_teamID = true;
    st->teamID = 13;
    st->has_timeOnline = true;
    st->timeOnline = 42;
    st->has_robotPosition = true;
    st->robotPosition = (fumanoid_Position){true, 1000.5f, true, -250.0f, true, 0.75f};
    st->has_robotPositionBelief = true;
    st->robotPositionBelief = 0.8;
    st->has_activeAgent = st->has_activeRole = st->has_currentState = st->has_robotName = st->has_gameState = true;
    strcpy(st->activeAgent, "SoccerAgent");
    strcpy(st->activeRole, "striker");
    strcpy(st->currentState, "playing");
    strcpy(st->robotName, "robot-3");
    st->has_batteryPercent = true;
    st->batteryPercent = 97;
    strcpy(st->gameState, "PLAYING");
    st->has_gcOtherSource = true;
    st->gcOtherSource = 0;
}

/* Builds the golden digest under budget; returns the datagram length. */
static uint16_t build(uint16_t budget, uint8_t *omitted)
{
    static fumanoid_Status st;
    static fumanoid_DebugPlot plot;
    static fumanoid_FieldObjects field;
    static fumanoid_DebugText text;
    fw_digest d;
    uint16_t n;
    golden_status(&st);
    plot = (fumanoid_DebugPlot)fumanoid_DebugPlot_init_zero;
    strcpy(plot.option, "demo.plotter");
    plot.has_timestamp = true;
    plot.timestamp = 123456;
    plot.samples_count = 2;
    strcpy(plot.samples[0].series, "sin");
    plot.samples[0].has_value = true;
    plot.samples[0].value = 0.5;
    strcpy(plot.samples[1].series, "cos");
    plot.samples[1].has_value = true;
    plot.samples[1].value = -0.25;
    field = (fumanoid_FieldObjects)fumanoid_FieldObjects_init_zero;
    strcpy(field.option, "demo.field");
    field.objects_count = 1;
    field.objects[0].has_label = field.objects[0].has_x = field.objects[0].has_y = true;
    strcpy(field.objects[0].label, "ball");
    field.objects[0].x = 1200.0f;
    field.objects[0].y = -300.0f;
    text = (fumanoid_DebugText)fumanoid_DebugText_init_zero;
    strcpy(text.option, "demo.text");
    text.has_text = true;
    memset(text.text, 'x', 300);
    text.text[300] = '\0';

    memset(g_buf, 0xEE, sizeof g_buf);
    fw_digest_begin(&d, g_buf, budget, FW_FRAMING_LENGTH, 3);
    CHECK(fw_digest_status(&d, &st));
    fw_digest_item(&d, 3, &fumanoid_debugPlot, &plot);
    fw_digest_item(&d, 3, &fumanoid_fieldObjects, &field);
    fw_digest_item(&d, 3, &fumanoid_debugText, &text);
    *omitted = d.omitted;
    n = fw_digest_end(&d);
    CHECK(n <= budget);
    return n;
}

int main(int argc, char **argv)
{
    size_t golden;
    uint16_t n, budget;
    uint8_t omitted;
    fw_datagram_info info;
    if (argc < 2) {
        fprintf(stderr, "usage: fw_test_digest GOLDEN_DIR\n");
        return 2;
    }
    golden = read_golden(argv[1]);

    /* the golden vector, byte for byte */
    n = build(200, &omitted);
    CHECK_EQ(omitted, 1);
    CHECK_EQ(n, golden);
    CHECK(n == golden && memcmp(g_buf, g_golden, golden) == 0);
    if (n == golden && memcmp(g_buf, g_golden, golden) != 0) {
        size_t i;
        for (i = 0; i < golden; i++) {
            if (g_buf[i] != g_golden[i]) {
                fprintf(stderr, "first difference at byte %zu: %02x, golden %02x\n", i, g_buf[i], g_golden[i]);
                break;
            }
        }
    }
    fw_classify(g_buf, n, &info);
    CHECK_EQ(info.kind, FW_DGRAM_FUMANOID);

    /* every budget holds: the datagram never grows past it, items drop out whole */
    for (budget = 120; budget <= FW_MAX_DATAGRAM; budget++) {
        n = build(budget, &omitted);
        if (n > budget) {
            fprintf(stderr, "budget %u: %u bytes\n", budget, n);
            break;
        }
        fw_classify(g_buf, n, &info);
        CHECK_EQ(info.kind, FW_DGRAM_FUMANOID);
        CHECK_EQ(info.payload_len + 4u, n);
        if (budget < sizeof g_buf) CHECK(g_buf[budget] == 0xEE); /* nothing written past the budget */
    }
    n = build(FW_MAX_DATAGRAM, &omitted);
    CHECK_EQ(omitted, 0);
    TEST_DONE();
}
