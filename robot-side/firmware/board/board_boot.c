/* The board's boot number, kept in flash (docs/security.md, "Boots"): the high word of the
 * robot's own tag counter and what the console's requests are bound to. It only ever goes up, so
 * the console can tell the robot's restart (a higher boot) from a capture of an earlier boot (a
 * lower one), and requests captured in an earlier boot never verify again. A reset, a power cycle
 * and a flat battery keep it; erasing the whole flash starts it at 1 again.
 *
 * Two 1 KB pages at the end of the STM32F103's 128 KB flash hold 32-bit slots, filled in order
 * (erased = 0xFFFFFFFF); the boot number is the greatest slot of both. A boot programs the next
 * free slot of the page holding the greatest; a full page moves on to the other one, erased
 * first, so the old greatest stays readable until the new one is written: a reset at any moment
 * leaves the boot number where it was or higher, never lower. 256 boots per page erase. */
#include <stdint.h>
#include "board_boot.h"

#define FLASH_KEYR (*(volatile uint32_t *)0x40022004u)
#define FLASH_SR (*(volatile uint32_t *)0x4002200Cu)
#define FLASH_CR (*(volatile uint32_t *)0x40022010u)
#define FLASH_AR (*(volatile uint32_t *)0x40022014u)
#define CR_PG (1u << 0)
#define CR_PER (1u << 1)
#define CR_STRT (1u << 6)
#define CR_LOCK (1u << 7)
#define SR_BSY (1u << 0)
#define ERASED 0xFFFFFFFFu
#define SLOTS 256u /* a 1 KB page of 32-bit slots */

static volatile uint32_t *const k_pages[2] = {(volatile uint32_t *)0x0801F800u, (volatile uint32_t *)0x0801FC00u};

static void flash_wait(void)
{
    while (FLASH_SR & SR_BSY) {
    }
}

static void program_half(volatile uint16_t *at, uint16_t v)
{
    FLASH_CR |= CR_PG;
    *at = v;
    flash_wait();
    FLASH_CR &= ~CR_PG;
}

static void program_slot(volatile uint32_t *at, uint32_t v)
{
    volatile uint16_t *half = (volatile uint16_t *)at;
    /* the high half first: a reset in between leaves a greater number, never a smaller one */
    program_half(half + 1, (uint16_t)(v >> 16));
    program_half(half, (uint16_t)v);
}

static void erase_page(volatile uint32_t *page)
{
    FLASH_CR |= CR_PER;
    FLASH_AR = (uint32_t)page;
    FLASH_CR |= CR_STRT;
    flash_wait();
    FLASH_CR &= ~CR_PER;
}

uint32_t board_next_boot(void)
{
    uint32_t boot = 0, i;
    unsigned p, at = 0;
    for (p = 0; p < 2u; p++) {
        for (i = 0; i < SLOTS && k_pages[p][i] != ERASED; i++) {
            if (k_pages[p][i] >= boot) {
                boot = k_pages[p][i];
                at = p;
            }
        }
    }
    for (i = 0; i < SLOTS && k_pages[at][i] != ERASED; i++) {
    }
    boot++;
    FLASH_KEYR = 0x45670123u; /* unlock: the two keys of the reference manual (RM0008) */
    FLASH_KEYR = 0xCDEF89ABu;
    if (i < SLOTS) {
        program_slot(&k_pages[at][i], boot);
    } else {
        erase_page(k_pages[1u - at]);
        program_slot(&k_pages[1u - at][0], boot);
    }
    FLASH_CR |= CR_LOCK;
    return boot;
}
