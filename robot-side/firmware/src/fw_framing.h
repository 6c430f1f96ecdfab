/* Datagram framing of the FUmanoids protocol and the demultiplexing of the robot port.
 *
 * One robot port receives three kinds of datagram, told apart by their first bytes:
 * FUmanoids frames (legacy 12-byte header or 4-byte length header), GameController
 * packets ('R' 'G') and reliable-stream segments (first two bytes both < 42). */
#ifndef FW_FRAMING_H
#define FW_FRAMING_H

#include <stddef.h>
#include <stdint.h>

#define FW_MAX_DATAGRAM 1400u
#define FW_LEGACY_HEADER 12u
#define FW_LENGTH_HEADER 4u
#define FW_LEGACY_TYPE 42u

typedef enum { FW_FRAMING_LEGACY = 0, FW_FRAMING_LENGTH = 1 } fw_framing;

typedef enum {
    FW_DGRAM_FUMANOID,       /* payload_off/payload_len/framing are set */
    FW_DGRAM_GAMECONTROLLER, /* starts with 'R' 'G' */
    FW_DGRAM_RELIABLE,       /* first two bytes both < 42, not a FUmanoids frame */
    FW_DGRAM_TOO_SHORT,
    FW_DGRAM_TOO_LONG,
    FW_DGRAM_BAD_LENGTH,     /* legacy header whose length disagrees with the datagram */
    FW_DGRAM_UNKNOWN
} fw_datagram_kind;

typedef struct {
    fw_datagram_kind kind;
    fw_framing framing;
    uint16_t payload_off;
    uint16_t payload_len;
    uint32_t declared_len; /* length field of a legacy header (for error reports) */
} fw_datagram_info;

void fw_classify(const uint8_t *d, size_t len, fw_datagram_info *out);
uint16_t fw_header_size(fw_framing f);
/* Writes the header for a payload of payload_len bytes; out must hold fw_header_size(f). */
void fw_write_header(fw_framing f, uint8_t *out, uint32_t payload_len);
const char *fw_datagram_kind_name(fw_datagram_kind k);

#endif
