/* --wifi-sim: the firmware core's GS1500M driver (src/fw_gs1500.c) talking over a
 * socketpair -- the "UART" -- to a simulated GS1500M (host/gs1500_sim.c) that does real
 * UDP on the robot's port. */
#ifndef HOST_WIFI_H
#define HOST_WIFI_H

#include <netinet/in.h>
#include <stdint.h>
#include "fw_gs1500.h"
#include "gs1500_sim.h"

typedef struct {
    int serial_fd;          /* firmware end of the serial line */
    int module_fd;          /* module end */
    gs_sim *module;
    gs_module gs;           /* the firmware's driver; gs.driver plugs into wlan_use() */
    wlan_driver driver;
} host_wifi;

/* baud 0 = 460800. */
int host_wifi_open(host_wifi *w, int udp_fd, const struct sockaddr_in *console, uint16_t local_port, uint32_t baud);
int host_wifi_poll_fd(const host_wifi *w);
void host_wifi_close(host_wifi *w, gs_sim_stats *stats);

#endif
