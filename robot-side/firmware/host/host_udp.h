/* Host platform port: the firmware's network driver on a plain UDP socket. */
#ifndef HOST_UDP_H
#define HOST_UDP_H

#include <netinet/in.h>
#include <stdint.h>
#include "fw_wlan.h"

typedef struct {
    int fd;
    struct sockaddr_in console;
    uint32_t oversize_dropped;
    uint32_t send_errors;
    wlan_driver driver;
} host_udp;

/* Binds 0.0.0.0:port (0 = OS-chosen); returns the bound port, or -1. */
int host_udp_bind(uint16_t port);
int host_udp_open(host_udp *u, int bound_fd, const struct sockaddr_in *console);
/* "host:port" -> IPv4 address; 0 on success. */
int host_parse_address(const char *text, struct sockaddr_in *out);

#endif
