/* A simulated GS1500M serial Wi-Fi module (host only): a thread that speaks the module's
 * serial protocol (AT commands, bulk data ESC Z / ESC Y / ESC y, ESC O / ESC F notices)
 * on one end of a byte stream and does real UDP on the robot's port. Everything going to
 * the microcontroller passes through a buffer of 1400 data bytes (+ one header) drained at
 * the serial baud rate; when it is full the oldest waiting bytes are lost -- never the rest
 * of the frame already on the line -- so under load datagrams reach the firmware with their
 * header cut off, as on the real module. The line from the firmware is limited
 * to the baud rate too: the module reads no faster, so the firmware's UART writes block
 * (the firmware end of the socketpair has a small send buffer). */
#ifndef GS1500_SIM_H
#define GS1500_SIM_H

#include <stdint.h>

typedef struct {
    uint32_t udp_in;           /* datagrams received from the network */
    uint32_t udp_dropped;      /* no open connection for them */
    uint32_t udp_out;          /* datagrams sent for the firmware */
    uint32_t send_failed;      /* answered with ESC F */
    uint32_t frames_from_mcu;
    uint32_t bad_from_mcu;     /* malformed bulk-data headers from the firmware */
    uint32_t commands;
    uint32_t overflow_bytes;   /* lost in the 1400-byte buffer */
    uint32_t overflow_events;
} gs_sim_stats;

typedef struct gs_sim gs_sim;

/* Takes over udp_fd (bound to local_port) and serial_fd; starts the module thread.
 * baud 0 = 460800 (the thesis' setting). */
gs_sim *gs_sim_start(int serial_fd, int udp_fd, uint16_t local_port, uint32_t baud);
/* Drops the connection with this cid as a real module does ("DISCONNECT <cid>"). */
void gs_sim_disconnect(gs_sim *s, char cid);
void gs_sim_stop(gs_sim *s, gs_sim_stats *stats);

#endif
