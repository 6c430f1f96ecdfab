/* The board's boot number, kept in flash (board_boot.c). */
#ifndef BOARD_BOOT_H
#define BOARD_BOOT_H

#include <stdint.h>

/* One above the last boot number kept in flash, kept there before it is returned. */
uint32_t board_next_boot(void);

#endif
