/* GS1500M serial Wi-Fi module, "bulk data" mode: the receive parser (a byte-wise, polled
 * state machine) and the driver that brings the module up with AT commands and sends
 * datagrams. Serial format (see README.md, "Serial protocol"):
 *
 *   module -> MCU   ESC 'Z' <cid> <4 ASCII digits len> <len bytes>            (to our cid)
 *                   ESC 'y' <cid> <ip> ' ' <port> TAB <4 digits len> <bytes>  (UDP server)
 *                   ESC 'O' | ESC 'F'                    (send succeeded / failed)
 *                   text lines: OK, ERROR, CONNECT <cid>, DISCONNECT <cid>, ...
 *   MCU -> module   AT commands terminated by CR LF
 *                   ESC 'Z' <cid> <4 digits len> <bytes>                      (client cid)
 *                   ESC 'Y' <cid> <ip> ':' <port> ':' <4 digits len> <bytes>  (server cid)
 *
 * There is no end marker after data. When the module's 1400-byte buffer overflows, a
 * datagram arrives with its header cut off: the parser treats those bytes as text, and
 * every malformed header makes it resynchronise on the next ESC. It never writes past
 * the buffer it was given. */
#ifndef FW_GS1500_H
#define FW_GS1500_H

#include <stdbool.h>
#include <stdint.h>
#include "fw_wlan.h"

#define GS_ESC 0x1B
#define GS_MAX_DATA 1400u
#define GS_LINE_RING 64u
/* A datagram's bytes arrive back to back at the baud rate; a silent line for this long in
 * the middle of a header or datagram means its rest was lost in the module. */
#define GS_IDLE_RESYNC_MS 20u

typedef enum {
    GS_EV_NONE = 0,
    GS_EV_DATAGRAM,     /* a whole datagram is in the buffer: see cid/ip/port/len */
    GS_EV_LINE,         /* a text line ended: gs_parser_line() */
    GS_EV_SENT_OK,      /* ESC O */
    GS_EV_SENT_FAIL     /* ESC F */
} gs_event;

typedef struct {
    uint32_t datagrams;
    uint32_t lines;
    uint32_t garbage_lines;  /* "lines" with non-printable bytes: cut-off data */
    uint32_t resyncs;        /* malformed or cut-off headers */
    uint32_t oversize;       /* announced length > 1400 or > the buffer */
    uint32_t notices_ok;
    uint32_t notices_fail;
} gs_parser_stats;

typedef struct {
    uint8_t state;
    uint8_t kind;        /* 'Z' or 'y' */
    char cid;
    uint8_t ip[4];
    uint8_t ip_octet;
    uint16_t ip_acc;
    uint8_t ip_digits;
    uint16_t port;
    uint8_t port_digits;
    uint16_t len;
    uint8_t len_digits;
    uint16_t got;
    uint8_t *buf;
    uint16_t cap;
    char ring[GS_LINE_RING]; /* the current text line; keeps its last 64 bytes */
    uint8_t ring_head;       /* index of the next write */
    uint8_t line_len;        /* bytes in the line, capped at GS_LINE_RING */
    bool line_binary;
    bool line_done;          /* the line ended; the next byte starts a new one */
    gs_parser_stats stats;
} gs_parser;

void gs_parser_init(gs_parser *p, uint8_t *buf, uint16_t cap);
/* Datagrams are written into buf; the caller must pass the same buffer until a
 * GS_EV_DATAGRAM (it may change buf between datagrams). */
void gs_parser_set_buffer(gs_parser *p, uint8_t *buf, uint16_t cap);
gs_event gs_parser_push(gs_parser *p, uint8_t byte);
/* Copies the last completed text line (NUL-terminated), returns its length. */
uint16_t gs_parser_line(const gs_parser *p, char *out, uint16_t cap);
/* Abandons a header or datagram in progress (its rest was lost); true if there was one. */
bool gs_parser_abort(gs_parser *p);

/* ---- the driver ---- */
typedef struct {
    int (*read)(void *ctx, uint8_t *buf, uint16_t cap);         /* non-blocking, bytes read */
    bool (*write)(void *ctx, const uint8_t *buf, uint16_t n);   /* blocks until sent (UART) */
    void *ctx;
} gs_serial;

typedef struct {
    const char *ssid;
    uint8_t console_ip[4];
    uint16_t console_port;
    uint16_t local_port;     /* the robot port (3838 on the field) */
} gs_config;

typedef struct {
    uint32_t sent;
    uint32_t send_rejected;  /* not ready, or too long */
    uint32_t command_retries;
    uint32_t disconnects;
    uint32_t idle_aborts;    /* partial datagrams abandoned after GS_IDLE_RESYNC_MS */
} gs_driver_stats;

typedef struct {
    gs_serial serial;
    gs_config cfg;
    gs_parser parser;
    uint8_t chunk[64];       /* serial bytes read but not yet parsed */
    uint8_t chunk_len, chunk_pos;
    uint8_t step;            /* init step; GS_READY when up */
    bool step_sent;
    bool ok_seen, error_seen;
    char connect_cid;
    uint32_t step_at;
    uint32_t now;            /* last time seen in poll_init (called on every robot poll) */
    uint32_t last_byte_at;
    char server_cid, console_cid;
    char line[GS_LINE_RING + 1];
    gs_driver_stats stats;
    wlan_driver driver;      /* plug into wlan_use() */
} gs_module;

void gs_module_init(gs_module *m, const gs_serial *serial, const gs_config *cfg);
bool gs_module_ready(const gs_module *m);

#endif
