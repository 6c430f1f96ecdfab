#include "fw_digest.h"
#include <pb_encode.h>
#include "fw_registry.h"

#define DIGEST_EXT 51u
#define LEN_ROOM 2u /* a length of up to 16383 bytes: two varint bytes */
#define OMITTED_ROOM 2u /* field 3, one varint byte (at most FW_MAX_OPTIONS items) */

static uint8_t put_varint(uint8_t *out, uint32_t v)
{
    uint8_t n = 0;
    while (v >= 0x80u) {
        out[n++] = (uint8_t)(v | 0x80u);
        v >>= 7;
    }
    out[n++] = (uint8_t)v;
    return n;
}

/* A length whose value was written at at + LEN_ROOM: writes the length at at and closes the
 * gap a one-byte length leaves; the value's end. */
static uint16_t close_len(uint8_t *buf, uint16_t at, uint16_t len)
{
    uint8_t n = put_varint(buf + at, len);
    uint16_t i;
    if (n < LEN_ROOM) {
        for (i = 0; i < len; i++) buf[at + n + i] = buf[at + LEN_ROOM + i];
    }
    return (uint16_t)(at + n + len);
}

void fw_digest_begin(fw_digest *d, uint8_t *buf, uint16_t budget, fw_framing framing, int32_t robot_id)
{
    uint16_t p = fw_header_size(framing);
    if (budget > FW_MAX_DATAGRAM) budget = FW_MAX_DATAGRAM;
    d->buf = buf;
    d->framing = framing;
    buf[p++] = 0x08u; /* robotID, field 1 varint (negative: ten bytes, as protobuf has it) */
    if (robot_id < 0) {
        uint64_t v = (uint64_t)(int64_t)robot_id;
        while (v >= 0x80u) {
            buf[p++] = (uint8_t)(v | 0x80u);
            v >>= 7;
        }
        buf[p++] = (uint8_t)v;
    } else {
        p = (uint16_t)(p + put_varint(buf + p, (uint32_t)robot_id));
    }
    p = (uint16_t)(p + put_varint(buf + p, (DIGEST_EXT << 3) | 2u));
    d->head = (uint8_t)p;
    d->body = (uint16_t)(p + LEN_ROOM);
    d->pos = d->body;
    d->end = budget > d->body + OMITTED_ROOM ? (uint16_t)(budget - OMITTED_ROOM) : d->body;
    d->omitted = 0;
}

/* Room for a length-delimited field's value at pos: as if its length took one byte (the value
 * is written one byte further on and moved back); the caller checks a longer one. The value
 * may end one byte past end: end stays OMITTED_ROOM below the budget, so within the buffer. */
static uint16_t value_room(const fw_digest *d)
{
    return d->end > d->pos + 2u ? (uint16_t)(d->end - d->pos - 2u) : 0u;
}

/* Keeps a value of n bytes written at pos + 1 + LEN_ROOM under tag if it fits whole. */
static bool keep(fw_digest *d, uint8_t tag, uint16_t n)
{
    uint16_t size = (uint16_t)(1u + (n < 128u ? 1u : 2u) + n);
    if (n == 0 || d->pos + size > d->end) return false;
    d->buf[d->pos] = tag;
    d->pos = close_len(d->buf, (uint16_t)(d->pos + 1u), n);
    return true;
}

bool fw_digest_status(fw_digest *d, const fumanoid_Status *status)
{
    pb_ostream_t os = pb_ostream_from_buffer(d->buf + d->pos + 1u + LEN_ROOM, value_room(d));
    return pb_encode(&os, fumanoid_Status_fields, status) && keep(d, 0x0Au, (uint16_t)os.bytes_written);
}

bool fw_digest_item(fw_digest *d, int32_t robot_id, const pb_extension_type_t *type, const void *msg)
{
    uint16_t room = value_room(d);
    uint16_t n = room == 0 ? 0u : fw_encode_payload(d->buf + d->pos + 1u + LEN_ROOM, room, robot_id, type, msg);
    if (!keep(d, 0x12u, n)) {
        if (d->omitted < 127u) d->omitted++;
        return false;
    }
    return true;
}

uint16_t fw_digest_end(fw_digest *d)
{
    uint16_t hdr = fw_header_size(d->framing);
    uint16_t end;
    if (d->omitted != 0) {
        d->buf[d->pos++] = 0x18u;
        d->buf[d->pos++] = d->omitted;
    }
    end = close_len(d->buf, d->head, (uint16_t)(d->pos - d->body));
    fw_write_header(d->framing, d->buf, (uint32_t)(end - hdr));
    return end;
}
