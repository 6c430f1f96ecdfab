#include "fw_registry.h"
#include <pb_decode.h>
#include <pb_encode.h>
#include "fumanoid.pb.h"

static const fw_registry_entry *g_table;
static size_t g_count;
static fw_process_report g_report;

void fw_registry_use(const fw_registry_entry *table, size_t count)
{
    g_table = table;
    g_count = count;
}

const fw_registry_entry *fw_registry_find(uint32_t ext)
{
    size_t i;
    for (i = 0; i < g_count; i++) {
        if (g_table[i].ext == ext) return &g_table[i];
    }
    return NULL;
}

const fw_process_report *fw_last_report(void) { return &g_report; }

static fw_result fail(fw_result r, uint32_t ext, const char *detail)
{
    g_report.result = r;
    g_report.ext = ext;
    g_report.detail = detail;
    return r;
}

fw_result processData(const uint8_t *buf, uint16_t len)
{
    pb_istream_t s = pb_istream_from_buffer(buf, len);
    const fw_registry_entry *found = NULL;
    uint32_t unknown_ext = 0;
    int have_id = 0;
    g_report.robot_id = -1;
    g_report.ext = 0;
    g_report.detail = NULL;

    while (s.bytes_left > 0) {
        pb_wire_type_t wt;
        uint32_t tag;
        bool eof;
        if (!pb_decode_tag(&s, &wt, &tag, &eof)) {
            if (eof) break;
            return fail(FW_ERR_DECODE, 0, PB_GET_ERROR(&s));
        }
        if (tag == fumanoid_Message_robotID_tag && wt == PB_WT_VARINT) {
            uint64_t v;
            if (!pb_decode_varint(&s, &v)) return fail(FW_ERR_DECODE, 0, PB_GET_ERROR(&s));
            g_report.robot_id = (int32_t)(uint32_t)v;
            have_id = 1;
            continue;
        }
        if (wt == PB_WT_STRING) {
            const fw_registry_entry *e = fw_registry_find(tag);
            if (e != NULL) {
                pb_istream_t sub;
                bool ok;
                if (!pb_make_string_substream(&s, &sub)) return fail(FW_ERR_DECODE, tag, PB_GET_ERROR(&s));
                ok = pb_decode(&sub, e->type, e->dest);
                if (!ok) {
                    const char *why = PB_GET_ERROR(&sub);
                    (void)pb_close_string_substream(&s, &sub);
                    return fail(FW_ERR_DECODE, tag, why);
                }
                if (!pb_close_string_substream(&s, &sub)) return fail(FW_ERR_DECODE, tag, PB_GET_ERROR(&s));
                found = e;
                continue;
            }
        }
        if (tag != fumanoid_Message_robotID_tag && unknown_ext == 0) unknown_ext = tag;
        if (!pb_skip_field(&s, wt)) return fail(FW_ERR_DECODE, tag, PB_GET_ERROR(&s));
    }
    if (!have_id) return fail(FW_ERR_NO_ROBOT_ID, found ? found->ext : unknown_ext, NULL);
    if (found == NULL) {
        return unknown_ext ? fail(FW_ERR_UNKNOWN_EXT, unknown_ext, NULL) : fail(FW_ERR_NO_EXTENSION, 0, NULL);
    }
    g_report.result = FW_OK;
    g_report.ext = found->ext;
    if (found->handler != NULL) found->handler(g_report.robot_id, found->dest);
    return FW_OK;
}

const char *fw_result_name(fw_result r)
{
    switch (r) {
    case FW_OK: return "ok";
    case FW_ERR_DECODE: return "protobuf decode error";
    case FW_ERR_NO_ROBOT_ID: return "message without robotID";
    case FW_ERR_NO_EXTENSION: return "message without extension";
    case FW_ERR_UNKNOWN_EXT: return "unknown extension";
    default: return "?";
    }
}

uint16_t fw_encode_payload(uint8_t *out, uint16_t cap, int32_t robot_id, const pb_extension_type_t *ext_type,
                           const void *msg)
{
    fumanoid_Message m;
    pb_extension_t ext;
    pb_ostream_t os;
    ext.type = ext_type;
    ext.dest = (void *)msg;
    ext.next = NULL;
    ext.found = true; /* nanopb encodes an optional extension only when "present" */
    m.robotID = robot_id;
    m.extensions = &ext;
    os = pb_ostream_from_buffer(out, cap);
    if (!pb_encode(&os, fumanoid_Message_fields, &m)) return 0;
    return (uint16_t)os.bytes_written;
}

uint16_t fw_encode_message(uint8_t *out, uint16_t cap, fw_framing framing, int32_t robot_id,
                           const pb_extension_type_t *ext_type, const void *msg)
{
    uint16_t hdr = fw_header_size(framing);
    uint16_t n;
    if (cap > FW_MAX_DATAGRAM) cap = FW_MAX_DATAGRAM;
    if (cap <= hdr) return 0;
    n = fw_encode_payload(out + hdr, (uint16_t)(cap - hdr), robot_id, ext_type, msg);
    if (n == 0) return 0;
    fw_write_header(framing, out, n);
    return (uint16_t)(hdr + n);
}
