/* What the firmware fuzz targets share: a silent log and a network driver that is always up
 * and never receives (each target feeds robot_dispatch itself and checks what is sent). */
#ifndef FUZZ_DRIVER_H
#define FUZZ_DRIVER_H
#include <stdbool.h>
#include <stdint.h>
#include "fw_wlan.h"

void fw_log(const char *what, const char *detail, int32_t value) { (void)what; (void)detail; (void)value; }

static bool drv_init(void *ctx, uint32_t now) { (void)ctx; (void)now; return true; }
static bool drv_recv(void *ctx, uint8_t *b, uint16_t cap, uint16_t *len, wlan_peer *from)
{
    (void)ctx; (void)b; (void)cap; (void)len; (void)from;
    return false;
}
#endif
