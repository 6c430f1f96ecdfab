#include "host_wifi.h"
#include <arpa/inet.h>
#include <errno.h>
#include <poll.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

/* The UART as the firmware sees it: non-blocking reads, writes that block until sent. */
static int serial_read(void *ctx, uint8_t *buf, uint16_t cap)
{
    host_wifi *w = ctx;
    ssize_t n = recv(w->serial_fd, buf, cap, MSG_DONTWAIT);
    return n > 0 ? (int)n : 0;
}

static bool serial_write(void *ctx, const uint8_t *buf, uint16_t n)
{
    host_wifi *w = ctx;
    uint16_t off = 0;
    while (off < n) {
        ssize_t k = send(w->serial_fd, buf + off, (size_t)(n - off), MSG_NOSIGNAL);
        if (k < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        off = (uint16_t)(off + k);
    }
    return true;
}

int host_wifi_open(host_wifi *w, int udp_fd, const struct sockaddr_in *console, uint16_t local_port, uint32_t baud)
{
    int sv[2];
    gs_serial serial;
    gs_config cfg;
    memset(w, 0, sizeof *w);
    if (socketpair(AF_UNIX, SOCK_STREAM, 0, sv) != 0) return -1;
    w->serial_fd = sv[0];
    w->module_fd = sv[1];
    {
        /* a UART holds a few bytes, not the kernel's default of ~200 kB */
        int small = 2048;
        setsockopt(sv[0], SOL_SOCKET, SO_SNDBUF, &small, sizeof small);
    }
    w->module = gs_sim_start(sv[1], udp_fd, local_port, baud);
    if (w->module == NULL) {
        close(sv[0]);
        close(sv[1]);
        return -1;
    }
    serial.read = serial_read;
    serial.write = serial_write;
    serial.ctx = w;
    memset(&cfg, 0, sizeof cfg);
    cfg.ssid = "touchline";
    memcpy(cfg.console_ip, &console->sin_addr.s_addr, 4);
    cfg.console_port = ntohs(console->sin_port);
    cfg.local_port = local_port;
    gs_module_init(&w->gs, &serial, &cfg);
    w->driver = w->gs.driver;
    return 0;
}

int host_wifi_poll_fd(const host_wifi *w) { return w->serial_fd; }

void host_wifi_close(host_wifi *w, gs_sim_stats *stats)
{
    shutdown(w->serial_fd, SHUT_RDWR);
    gs_sim_stop(w->module, stats);
    close(w->serial_fd);
    close(w->module_fd);
}
