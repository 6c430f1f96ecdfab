#include "host_udp.h"
#include "fw_robot.h"
#include <arpa/inet.h>
#include <errno.h>
#include <netdb.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

int host_parse_address(const char *text, struct sockaddr_in *out)
{
    char host[256];
    const char *colon = strrchr(text, ':');
    struct addrinfo hints, *res = NULL;
    long port;
    char *end;
    if (colon == NULL || (size_t)(colon - text) >= sizeof host) return -1;
    memcpy(host, text, (size_t)(colon - text));
    host[colon - text] = '\0';
    port = strtol(colon + 1, &end, 10);
    if (*end != '\0' || port <= 0 || port > 65535) return -1;
    memset(&hints, 0, sizeof hints);
    hints.ai_family = AF_INET;
    hints.ai_socktype = SOCK_DGRAM;
    if (getaddrinfo(host[0] ? host : "127.0.0.1", NULL, &hints, &res) != 0 || res == NULL) return -1;
    memcpy(out, res->ai_addr, sizeof *out);
    out->sin_port = htons((uint16_t)port);
    freeaddrinfo(res);
    return 0;
}

int host_udp_bind(uint16_t port)
{
    struct sockaddr_in a;
    socklen_t alen = sizeof a;
    int one = 1;
    int fd = socket(AF_INET, SOCK_DGRAM, 0);
    if (fd < 0) return -1;
    setsockopt(fd, SOL_SOCKET, SO_BROADCAST, &one, sizeof one);
    memset(&a, 0, sizeof a);
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_ANY);
    a.sin_port = htons(port);
    if (bind(fd, (struct sockaddr *)&a, sizeof a) != 0 || getsockname(fd, (struct sockaddr *)&a, &alen) != 0) {
        close(fd);
        return -1;
    }
    return fd;
}

static bool udp_poll_init(void *ctx, uint32_t now)
{
    (void)ctx;
    (void)now;
    return true; /* a host socket is "associated" at once */
}

static bool udp_recv(void *ctx, uint8_t *buf, uint16_t cap, uint16_t *len, wlan_peer *from)
{
    host_udp *u = ctx;
    for (;;) {
        struct sockaddr_in src;
        socklen_t slen = sizeof src;
        ssize_t n = recvfrom(u->fd, buf, cap, MSG_DONTWAIT | MSG_TRUNC, (struct sockaddr *)&src, &slen);
        if (n < 0) return false;
        if ((size_t)n > cap) {
            u->oversize_dropped++;
            fw_log("datagram longer than 1400 bytes dropped", 0, (int32_t)n);
            continue;
        }
        *len = (uint16_t)n;
        from->cid = 0;
        memcpy(from->ip, &src.sin_addr.s_addr, 4);
        from->port = ntohs(src.sin_port);
        return true;
    }
}

static bool udp_send_to(host_udp *u, const struct sockaddr_in *to, const uint8_t *msg, uint16_t len)
{
    if (sendto(u->fd, msg, len, 0, (const struct sockaddr *)to, sizeof *to) != (ssize_t)len) {
        /* ECONNREFUSED from an earlier ICMP, or a full buffer: UDP may lose, count it */
        u->send_errors++;
        return false;
    }
    return true;
}

static bool udp_send_con(void *ctx, const uint8_t *msg, uint16_t len, char cid)
{
    host_udp *u = ctx;
    (void)cid;
    return udp_send_to(u, &u->console, msg, len);
}

static bool udp_send_peer(void *ctx, const wlan_peer *to, const uint8_t *msg, uint16_t len)
{
    host_udp *u = ctx;
    struct sockaddr_in a;
    memset(&a, 0, sizeof a);
    a.sin_family = AF_INET;
    memcpy(&a.sin_addr.s_addr, to->ip, 4);
    a.sin_port = htons(to->port);
    return udp_send_to(u, &a, msg, len);
}

int host_udp_open(host_udp *u, int bound_fd, const struct sockaddr_in *console)
{
    memset(u, 0, sizeof *u);
    u->fd = bound_fd;
    u->console = *console;
    u->driver.poll_init = udp_poll_init;
    u->driver.recv = udp_recv;
    u->driver.send_con = udp_send_con;
    u->driver.send_peer = udp_send_peer;
    u->driver.ctx = u;
    return 0;
}
