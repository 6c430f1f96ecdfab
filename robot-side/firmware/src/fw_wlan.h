/* The network as the firmware sees it: the polling API of the 2014 reference firmware
 * (pollInitNetwork, recvWlanData, sendMsgToCon) over a driver chosen at start-up: the
 * GS1500M serial Wi-Fi module on the board (and in --wifi-sim), or plain host UDP. */
#ifndef FW_WLAN_H
#define FW_WLAN_H

#include <stdbool.h>
#include <stdint.h>

#define WLAN_CID_CONSOLE 0 /* cid argument meaning "the console's connection" */

typedef struct {
    char cid;        /* module connection id ('0'..'f'), 0 on host UDP */
    uint8_t ip[4];
    uint16_t port;
} wlan_peer;

typedef struct {
    bool (*poll_init)(void *ctx, uint32_t now);
    /* true when a whole datagram is in buf; from describes its sender */
    bool (*recv)(void *ctx, uint8_t *buf, uint16_t cap, uint16_t *len, wlan_peer *from);
    bool (*send_con)(void *ctx, const uint8_t *msg, uint16_t len, char cid);
    bool (*send_peer)(void *ctx, const wlan_peer *to, const uint8_t *msg, uint16_t len);
    void *ctx;
} wlan_driver;

void wlan_use(const wlan_driver *d);
bool pollInitNetwork(uint32_t now);
bool recvWlanData(uint8_t *buf, uint16_t *len); /* *len: capacity in, datagram length out */
const wlan_peer *wlanLastSender(void);
bool sendMsgToCon(const uint8_t *msg, uint16_t len, char cid);
bool sendMsgToPeer(const wlan_peer *to, const uint8_t *msg, uint16_t len);

#endif
