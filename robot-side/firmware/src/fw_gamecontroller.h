/* GameController receiver: the robot accepts the RoboCupGameControlData ("RGme") layouts a
 * small robot meets, each by magic + version + exact length (robots drop any other size):
 * HL v12 (688 bytes), 2014 v8 (158 bytes), SPL v18 (118 bytes) and 2013 v7 (116 bytes). */
#ifndef FW_GAMECONTROLLER_H
#define FW_GAMECONTROLLER_H

#include <stddef.h>
#include <stdint.h>

typedef enum {
    FW_GC_OK = 0,
    FW_GC_BAD_MAGIC,
    FW_GC_BAD_VERSION,   /* known magic, unknown version */
    FW_GC_BAD_LENGTH     /* known version, wrong datagram size */
} fw_gc_result;

typedef struct {
    uint8_t version;
    uint8_t state;        /* 0 INITIAL 1 READY 2 SET 3 PLAYING 4 FINISHED (5 STANDBY, SPL) */
    uint8_t packet_number;
    uint8_t team_numbers[2];
} fw_gc_info;

fw_gc_result fw_gc_parse(const uint8_t *d, size_t len, fw_gc_info *out);
const char *fw_gc_state_name(uint8_t state);

#endif
