/* The match digest (proto/fumanoid.proto, MatchDigest, extension 51): in READY/SET/PLAYING a
 * robot sends one datagram per period with its Status and the newest value of each match
 * item, in the team's order, up to a size budget. The digest is written field by field
 * straight into the datagram buffer (no second buffer, no heap): an item is encoded in
 * place and kept only when it fits whole; one that does not is left out and counted.
 *
 * Use: fw_digest_begin, fw_digest_status, fw_digest_item for each item, fw_digest_end. */
#ifndef FW_DIGEST_H
#define FW_DIGEST_H

#include <stdbool.h>
#include <stdint.h>
#include <pb.h>
#include "fumanoid.pb.h"
#include "fw_framing.h"

/* One Ethernet/Wi-Fi MTU (1500) less the IPv4 (20) and UDP (8) headers: the largest datagram
 * that travels as one IP fragment. */
#define FW_DIGEST_MTU_PAYLOAD 1472u

typedef struct {
    uint8_t *buf;
    uint16_t end;      /* the budget: the datagram may not grow beyond buf[end] */
    uint16_t body;     /* where the digest's fields start */
    uint16_t pos;      /* where the next field goes */
    uint8_t head;      /* frame header + robotID + the digest's tag */
    fw_framing framing;
    uint8_t omitted;
} fw_digest;

/* budget: the whole datagram (frame header included, a trailer's room excluded), at most
 * FW_MAX_DATAGRAM; buf must hold budget bytes. */
void fw_digest_begin(fw_digest *d, uint8_t *buf, uint16_t budget, fw_framing framing, int32_t robot_id);
/* The Status (field 1); false if it does not fit (the digest is then not worth sending). */
bool fw_digest_status(fw_digest *d, const fumanoid_Status *status);
/* One item (field 2): a Message{robotID, ext} as it would be streamed; false = left out, counted. */
bool fw_digest_item(fw_digest *d, int32_t robot_id, const pb_extension_type_t *type, const void *msg);
/* Writes the count of items left out and the frame around the digest; the datagram's length. */
uint16_t fw_digest_end(fw_digest *d);

#endif
