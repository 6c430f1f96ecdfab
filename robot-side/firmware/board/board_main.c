/* The communication core on the CM-530 (STM32F103, Cortex-M3, 72 MHz) for the footprint
 * build: USART1 talks to the GS1500M, SysTick counts milliseconds. Only the registers
 * the core needs; no HAL. The simulated camera is not linked: the only debug option here
 * is a text line, which exercises the same encode-and-send path as every other option. */
#include <stdbool.h>
#include <stdint.h>
#include "board_boot.h"
#include "fw_gs1500.h"
#include "fw_robot.h"
/* The team key (docs/security.md): `touchline keys show --c-header team_key.h`, built with
 * -DTOUCHLINE_TEAM_KEY_HEADER='"team_key.h"'. Without it the board runs in lab mode. */
#ifdef TOUCHLINE_TEAM_KEY_HEADER
#include TOUCHLINE_TEAM_KEY_HEADER
#define BOARD_TEAM_KEY (&touchline_team_key)
#else
#define BOARD_TEAM_KEY 0
#endif

#define USART1_SR (*(volatile uint32_t *)0x40013800u)
#define USART1_DR (*(volatile uint32_t *)0x40013804u)
#define SR_RXNE (1u << 5)
#define SR_TXE (1u << 7)

static volatile uint32_t g_ms;
void SysTick_Handler(void);
void SysTick_Handler(void) { g_ms++; }

/* No console on the board: fw_log is the empty inline one of fw_robot.h (FW_LOG_NONE, footprint.sh). */
#ifndef FW_LOG_NONE
#error "the board has no console: build it with -DFW_LOG_NONE (footprint.sh does)"
#endif

static int uart_read(void *ctx, uint8_t *buf, uint16_t cap)
{
    uint16_t n = 0;
    (void)ctx;
    while (n < cap && (USART1_SR & SR_RXNE)) buf[n++] = (uint8_t)USART1_DR;
    return n;
}

static bool uart_write(void *ctx, const uint8_t *buf, uint16_t n)
{
    uint16_t i;
    (void)ctx;
    for (i = 0; i < n; i++) {
        while (!(USART1_SR & SR_TXE)) {
        }
        USART1_DR = buf[i];
    }
    return true;
}

static bool produce_text(uint32_t now, fw_outgoing *out)
{
    static const char line[] = "behaviour: searching ball";
    uint32_t i;
    out->type = &fumanoid_debugText;
    for (i = 0; i < sizeof "demo.text"; i++) out->m.text.option[i] = "demo.text"[i];
    out->m.text.has_text = true;
    for (i = 0; i < sizeof line; i++) out->m.text.text[i] = line[i];
    out->m.text.has_timestamp = true;
    out->m.text.timestamp = now;
    return true;
}

static const fw_option_def k_options[] = {
    {"demo.text", "behaviour log lines", fumanoid_DebugKind_TEXT, produce_text},
};

static gs_module g_module;
static const gs_serial k_serial = {uart_read, uart_write, 0};
static const gs_config k_gs = {"fumanoids", {192, 168, 1, 100}, 11011, 3838};
static robot_config g_robot = {
    1, 13, "cm530", FW_FRAMING_LEGACY, 10, k_options, 1, 0, true, RS_DEFAULT_MODULUS, 100, 0, 0,
    FW_GC_RETURN_PERIOD_MS, /* return packets to the GameController's own address (2026 field) */
};

int main(void)
{
    gs_module_init(&g_module, &k_serial, &k_gs);
    wlan_use(&g_module.driver);
    g_robot.team_key = BOARD_TEAM_KEY;
    g_robot.boot_id = board_next_boot(); /* before the robot talks: requests are bound to it */
    robot_init(&g_robot, g_ms);
    for (;;) robot_poll(g_ms);
}
