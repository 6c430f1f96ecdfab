#include "fw_wlan.h"

static const wlan_driver *g_driver;
static wlan_peer g_last;

void wlan_use(const wlan_driver *d) { g_driver = d; }

bool pollInitNetwork(uint32_t now) { return g_driver != 0 && g_driver->poll_init(g_driver->ctx, now); }

bool recvWlanData(uint8_t *buf, uint16_t *len)
{
    uint16_t cap = *len;
    if (g_driver == 0) return false;
    return g_driver->recv(g_driver->ctx, buf, cap, len, &g_last);
}

const wlan_peer *wlanLastSender(void) { return &g_last; }

bool sendMsgToCon(const uint8_t *msg, uint16_t len, char cid)
{
    return g_driver != 0 && g_driver->send_con(g_driver->ctx, msg, len, cid);
}

bool sendMsgToPeer(const wlan_peer *to, const uint8_t *msg, uint16_t len)
{
    return g_driver != 0 && g_driver->send_peer(g_driver->ctx, to, msg, len);
}
