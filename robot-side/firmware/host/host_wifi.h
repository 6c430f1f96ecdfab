/* --wifi-sim: the firmware core's GS1500M driver talking over a socketpair to a simulated
 * GS1500M module (a thread) that does real UDP on the robot's port. */
#ifndef HOST_WIFI_H
#define HOST_WIFI_H

#include <netinet/in.h>
#include <stdint.h>
#include "fw_wlan.h"

typedef struct {
    int serial_fd;          /* firmware end of the serial line */
    void *module;           /* the simulated module */
    wlan_driver driver;
} host_wifi;

int host_wifi_open(host_wifi *w, int udp_fd, const struct sockaddr_in *console, uint16_t local_port);
int host_wifi_poll_fd(const host_wifi *w);
void host_wifi_close(host_wifi *w);

#endif
