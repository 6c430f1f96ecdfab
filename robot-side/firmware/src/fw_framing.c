#include "fw_framing.h"

static uint32_t read_be32(const uint8_t *p)
{
    return ((uint32_t)p[0] << 24) | ((uint32_t)p[1] << 16) | ((uint32_t)p[2] << 8) | p[3];
}

void fw_classify(const uint8_t *d, size_t len, fw_datagram_info *out)
{
    out->kind = FW_DGRAM_UNKNOWN;
    out->framing = FW_FRAMING_LEGACY;
    out->payload_off = 0;
    out->payload_len = 0;
    out->declared_len = 0;
    if (len > FW_MAX_DATAGRAM) {
        out->kind = FW_DGRAM_TOO_LONG;
        return;
    }
    if (len < 2) {
        out->kind = FW_DGRAM_TOO_SHORT;
        return;
    }
    if (d[0] == 0 && d[1] == FW_LEGACY_TYPE) {
        /* 0x00 0x2A cannot start a length-framed datagram (it would announce > 2 MB)
         * nor a reliable segment (ack < 42), so it is always a legacy header. */
        if (len < FW_LEGACY_HEADER) {
            out->kind = FW_DGRAM_TOO_SHORT;
            return;
        }
        out->declared_len = read_be32(d + 8);
        if (out->declared_len != len - FW_LEGACY_HEADER) {
            out->kind = FW_DGRAM_BAD_LENGTH;
            return;
        }
        out->kind = FW_DGRAM_FUMANOID;
        out->framing = FW_FRAMING_LEGACY;
        out->payload_off = FW_LEGACY_HEADER;
        out->payload_len = (uint16_t)(len - FW_LEGACY_HEADER);
        return;
    }
    if (d[0] == 'R' && d[1] == 'G') {
        out->kind = FW_DGRAM_GAMECONTROLLER;
        return;
    }
    if (len >= FW_LENGTH_HEADER && read_be32(d) == len - FW_LENGTH_HEADER) {
        out->kind = FW_DGRAM_FUMANOID;
        out->framing = FW_FRAMING_LENGTH;
        out->payload_off = FW_LENGTH_HEADER;
        out->payload_len = (uint16_t)(len - FW_LENGTH_HEADER);
        return;
    }
    if (d[0] < 42 && d[1] < 42) {
        out->declared_len = len >= 4 ? read_be32(d) : 0;
        out->kind = FW_DGRAM_RELIABLE;
        return;
    }
    out->kind = FW_DGRAM_UNKNOWN;
}

uint16_t fw_header_size(fw_framing f)
{
    return f == FW_FRAMING_LENGTH ? FW_LENGTH_HEADER : FW_LEGACY_HEADER;
}

void fw_write_header(fw_framing f, uint8_t *out, uint32_t payload_len)
{
    uint8_t *len_at = out;
    if (f == FW_FRAMING_LEGACY) {
        uint8_t i;
        for (i = 0; i < FW_LEGACY_HEADER; i++) out[i] = 0;
        out[1] = FW_LEGACY_TYPE;
        len_at = out + 8;
    }
    len_at[0] = (uint8_t)(payload_len >> 24);
    len_at[1] = (uint8_t)(payload_len >> 16);
    len_at[2] = (uint8_t)(payload_len >> 8);
    len_at[3] = (uint8_t)payload_len;
}

const char *fw_datagram_kind_name(fw_datagram_kind k)
{
    switch (k) {
    case FW_DGRAM_FUMANOID: return "fumanoid frame";
    case FW_DGRAM_GAMECONTROLLER: return "gamecontroller packet";
    case FW_DGRAM_RELIABLE: return "reliable segment";
    case FW_DGRAM_TOO_SHORT: return "datagram too short for its header";
    case FW_DGRAM_TOO_LONG: return "datagram longer than 1400 bytes";
    case FW_DGRAM_BAD_LENGTH: return "length field disagrees with the datagram size";
    default: return "unknown datagram type";
    }
}
