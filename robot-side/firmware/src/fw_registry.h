/* The extension registry: nanopb cannot decode extensions of Message by itself, so
 * processData() walks the top-level fields, reads each extension's tag, looks its number
 * up in a table and decodes the submessage into that entry's static buffer, then calls
 * the entry's handler. Unknown extensions are reported, never a crash.
 *
 * Adding a message type = a proto extension, nanopb regeneration, one table entry, one
 * handler (README.md, "How to add a message type"). */
#ifndef FW_REGISTRY_H
#define FW_REGISTRY_H

#include <stddef.h>
#include <stdint.h>
#include <pb.h>
#include "fw_framing.h"

typedef void (*fw_handler)(int32_t sender_id, const void *msg);

typedef struct {
    uint32_t ext;              /* extension field number in Message */
    const pb_msgdesc_t *type;  /* nanopb descriptor of the submessage */
    void *dest;                /* static storage the submessage is decoded into */
    fw_handler handler;
} fw_registry_entry;

typedef enum {
    FW_OK = 0,
    FW_ERR_DECODE,        /* not valid protobuf, or a field over its nanopb limit */
    FW_ERR_NO_ROBOT_ID,   /* required robotID missing */
    FW_ERR_NO_EXTENSION,  /* a Message without any extension */
    FW_ERR_UNKNOWN_EXT    /* an extension number without a registry entry */
} fw_result;

typedef struct {
    fw_result result;
    uint32_t ext;       /* the extension handled, or the unknown one */
    int32_t robot_id;
    const char *detail; /* nanopb's error string on decode errors */
} fw_process_report;

void fw_registry_use(const fw_registry_entry *table, size_t count);
const fw_registry_entry *fw_registry_find(uint32_t ext);

/* Decodes one Message (protobuf payload without framing header) and dispatches it. */
fw_result processData(const uint8_t *buf, uint16_t len);
const fw_process_report *fw_last_report(void);
const char *fw_result_name(fw_result r);

/* Encodes header + Message{robotID, one extension} into out (capacity cap, normally a
 * static 1400-byte buffer). Returns the datagram length, or 0 if it does not fit. */
uint16_t fw_encode_message(uint8_t *out, uint16_t cap, fw_framing framing, int32_t robot_id,
                           const pb_extension_type_t *ext_type, const void *msg);
/* The same Message without a frame header (a match digest's item); 0 if it does not fit. */
uint16_t fw_encode_payload(uint8_t *out, uint16_t cap, int32_t robot_id, const pb_extension_type_t *ext_type,
                           const void *msg);

#endif
