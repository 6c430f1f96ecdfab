#include "fw_gamecontroller.h"

typedef struct {
    uint8_t version;
    uint8_t version_width;  /* bytes of the little-endian version field at offset 4 */
    uint16_t size;
    uint16_t state_at, packet_at, team0_at, team1_at;
} gc_layout;

/* Offsets from the official headers (see the GameController brief); packet_at 0 = none. */
static const gc_layout k_layouts[] = {
    {12, 2, 688, 9, 6, 24, 24 + 332},  /* HL v12, since 2021 */
    {12, 2, 640, 9, 6, 24, 24 + 308},  /* HL v12, 2017-2021 (same version number) */
    {8, 1, 158, 7, 5, 18, 18 + 70},    /* 2014 SPL and HL */
    {18, 1, 118, 10, 5, 18, 18 + 50},  /* SPL 2023-2025 */
    {7, 4, 116, 9, 0, 20, 20 + 48},    /* 2013, and HL "compatibility" packets until 2017 */
};

fw_gc_result fw_gc_parse(const uint8_t *d, size_t len, fw_gc_info *out)
{
    size_t i;
    int version_known = 0;
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
        return FW_GC_OK;
    }
    return version_known ? FW_GC_BAD_LENGTH : FW_GC_BAD_VERSION;
}

const char *fw_gc_state_name(uint8_t state)
{
    static const char *const names[] = {"INITIAL", "READY", "SET", "PLAYING", "FINISHED", "STANDBY"};
    return state < 6 ? names[state] : "UNKNOWN";
}
