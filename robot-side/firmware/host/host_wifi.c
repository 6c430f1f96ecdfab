#include "host_wifi.h"

int host_wifi_open(host_wifi *w, int udp_fd, const struct sockaddr_in *console, uint16_t local_port)
{
    (void)w; (void)udp_fd; (void)console; (void)local_port;
    return -1;
}
int host_wifi_poll_fd(const host_wifi *w) { return w->serial_fd; }
void host_wifi_close(host_wifi *w) { (void)w; }
