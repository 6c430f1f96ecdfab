/*
 * touchline-blast: the load generator of `touchline bench ingest`. Sends a set of datagrams
 * round-robin to one UDP address on this machine as fast as one core can (sendmmsg, 64 per
 * call), for a fixed time, and prints how many it sent. Written in C because a Java sender
 * on the same two cores is slower than the receivers it is meant to saturate.
 *
 *   touchline-blast --to 127.0.0.1:PORT --file DATAGRAMS --seconds N
 *
 * DATAGRAMS: each datagram as a 2-byte big-endian length and its bytes. Only loopback
 * addresses (127.0.0.0/8) are accepted: this is a benchmark, not a network tool.
 * Output (stdout, one line): "sent COUNT in SECONDS s".
 */
#define _GNU_SOURCE
#include <arpa/inet.h>
#include <errno.h>
#include <netinet/in.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <time.h>
#include <unistd.h>

#define MAX_DATAGRAMS 256
#define MAX_SIZE 1400
#define BATCH 64

static unsigned char data[MAX_DATAGRAMS][MAX_SIZE];
static size_t sizes[MAX_DATAGRAMS];

static double now_seconds(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

static int usage(const char *why) {
    fprintf(stderr, "touchline-blast: %s\nusage: touchline-blast --to 127.0.0.1:PORT --file DATAGRAMS --seconds N\n",
            why);
    return 2;
}

static int load(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) {
        return -1;
    }
    int n = 0;
    unsigned char len[2];
    while (n < MAX_DATAGRAMS && fread(len, 1, 2, f) == 2) {
        size_t size = ((size_t)len[0] << 8) | len[1];
        if (size == 0 || size > MAX_SIZE || fread(data[n], 1, size, f) != size) {
            fclose(f);
            return -2;
        }
        sizes[n++] = size;
    }
    fclose(f);
    return n;
}

int main(int argc, char **argv) {
    const char *to = NULL;
    const char *file = NULL;
    double seconds = 0;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "--to") == 0) {
            to = argv[i + 1];
        } else if (strcmp(argv[i], "--file") == 0) {
            file = argv[i + 1];
        } else if (strcmp(argv[i], "--seconds") == 0) {
            seconds = atof(argv[i + 1]);
        } else {
            return usage("unknown option");
        }
    }
    if (!to || !file || !(seconds > 0)) {
        return usage("--to, --file and --seconds are required");
    }
    char host[64];
    const char *colon = strrchr(to, ':');
    if (!colon || (size_t)(colon - to) >= sizeof host) {
        return usage("--to needs HOST:PORT");
    }
    memcpy(host, to, (size_t)(colon - to));
    host[colon - to] = '\0';
    struct sockaddr_in addr;
    memset(&addr, 0, sizeof addr);
    addr.sin_family = AF_INET;
    addr.sin_port = htons((unsigned short)atoi(colon + 1));
    if (inet_pton(AF_INET, host, &addr.sin_addr) != 1 || (ntohl(addr.sin_addr.s_addr) >> 24) != 127) {
        return usage("only loopback addresses (127.0.0.0/8)");
    }
    int n = load(file);
    if (n <= 0) {
        return usage(n == -1 ? "cannot open the datagram file" : "the datagram file is empty or malformed");
    }
    int fd = socket(AF_INET, SOCK_DGRAM, 0);
    if (fd < 0 || connect(fd, (struct sockaddr *)&addr, sizeof addr) != 0) {
        perror("touchline-blast: socket");
        return 1;
    }
    struct mmsghdr msgs[BATCH];
    struct iovec iov[BATCH];
    memset(msgs, 0, sizeof msgs);
    unsigned long long sent = 0;
    double start = now_seconds();
    double end = start + seconds;
    double last = start;
    while (last < end) {
        for (int k = 0; k < BATCH; k++) {
            int d = (int)((sent + (unsigned long long)k) % (unsigned long long)n);
            iov[k].iov_base = data[d];
            iov[k].iov_len = sizes[d];
            msgs[k].msg_hdr.msg_iov = &iov[k];
            msgs[k].msg_hdr.msg_iovlen = 1;
        }
        int r = sendmmsg(fd, msgs, BATCH, 0);
        if (r > 0) {
            sent += (unsigned long long)r;
        } else if (r < 0 && errno != EINTR && errno != ENOBUFS && errno != EAGAIN && errno != ECONNREFUSED) {
            perror("touchline-blast: sendmmsg");
            break;
        }
        last = now_seconds();
    }
    printf("sent %llu in %.6f s\n", sent, last - start);
    close(fd);
    return 0;
}
