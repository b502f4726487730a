/* SPDX-License-Identifier: MIT */
/* The lm3s811evb for main.c: the SSD0303 96x16 mono OLED on I2C0, fed
 * bands in its own page layout (STP_PIXEL_MONO1_PAGES: 8 rows a byte, one
 * byte a column), each page sent as it is: no repacking, no page buffer;
 * released by a byte on UART0. */
#include "board.h"
#include "lm3s811_oled.h"
#include "stellaris.h"
#include "stp_panel.h"

#if defined(STP_FW_PAGES) && !STP_FW_PAGES
#error "the lm3s811evb's panel takes its own pages: STP_FW_PAGES=1 (firmware/CMakeLists.txt sets it from STP_FW_BOARD)"
#endif

#define PANEL_W 96u
#define PANEL_H 16u

static int panel_start(void)
{
    stp_lm3s811_oled_setup();
    return stp_panel_init(&stp_panel_ssd0303, &stp_lm3s811_oled_bus) == 0 ? 0 : -1;
}

/* A band of (rows + 7) / 8 pages, stride bytes apart, starting on page
 * y0 / 8 (stp_renderer_render's page bands do). */
static int flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    (void)port;
    return stp_panel_pages_send(&stp_panel_ssd0303, &stp_lm3s811_oled_bus, y0, rows, pixels,
                                stride, PANEL_W) == 0
               ? 0
               : -1;
}

/* UART0 (PA0/PA1; a PL011 at 0x4000C000), receive only. */
#define UART0 0x4000C000u
#define UART_DR STP_REG(UART0 + 0x000u)
#define UART_FR STP_REG(UART0 + 0x018u)
#define UART_IBRD STP_REG(UART0 + 0x024u)
#define UART_FBRD STP_REG(UART0 + 0x028u)
#define UART_LCRH STP_REG(UART0 + 0x02Cu)
#define UART_CTL STP_REG(UART0 + 0x030u)
#define UART_FR_RXFE 0x10u

/* Hold the picture until a byte arrives on UART0: a test harness takes its
 * screendump first and then sends the byte, so the firmware's own exit
 * status still ends QEMU (QEMU gives this board no keys). */
static void hold(void)
{
    STP_SYSCTL_RCGC1 |= 1u << 0; /* UART0 */
    STP_SYSCTL_RCGC2 |= 1u << 0; /* GPIO A */
    STP_GPIO_AFSEL(STP_GPIO_A) |= 0x03u;
    STP_GPIO_DEN(STP_GPIO_A) |= 0x03u;
    UART_CTL = 0;
    /* 115200 8N1 from the 6 MHz system clock: 6e6 / (16 x 115200) = 3 + 16/64 */
    UART_IBRD = 3;
    UART_FBRD = 16;
    UART_LCRH = 0x60u;  /* 8 bits, no FIFO */
    UART_CTL = 0x301u;  /* enable, transmit, receive */
    stp_semihost_write("stipple: frame done; send a byte on UART0 to finish\n");
    while (UART_FR & UART_FR_RXFE)
        ;
    (void)UART_DR;
}

const stp_board stp_board_this = {"lm3s811evb", PANEL_W, PANEL_H, STP_PIXEL_MONO1_PAGES, "-s 96x16", panel_start, flush, hold};
