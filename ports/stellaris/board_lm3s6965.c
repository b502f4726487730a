/* SPDX-License-Identifier: MIT */
/* The lm3s6965evb for main.c: the SSD0323 128x64 grey OLED on SSI0, one
 * write window for the whole frame, released by the "up" key. */
#include "board.h"
#include "lm3s6965_oled.h"
#include "stellaris.h"
#include "stp_panel.h"

#if defined(STP_FW_PAGES) && STP_FW_PAGES
#error "the lm3s6965evb's panel takes MONO1 rows: STP_FW_PAGES=0 (firmware/CMakeLists.txt sets it from STP_FW_BOARD)"
#endif

#define PANEL_W 128u
#define CHUNK_PIXELS 16u /* packed and sent a piece of a row at a time */

static uint8_t packed[CHUNK_PIXELS / 2u];

static int panel_start(void)
{
    stp_lm3s6965_oled_setup();
    return stp_panel_init(&stp_panel_ssd0323, &stp_lm3s6965_oled_bus) == 0 &&
                   stp_panel_window_all(&stp_panel_ssd0323, &stp_lm3s6965_oled_bus) == 0
               ? 0
               : -1;
}

/* Rows go out CHUNK_PIXELS at a time (4-bit grey, two pixels a byte): the
 * window fills row by row whatever the data calls, and the buffer stays
 * small. */
static int flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    (void)port;
    (void)y0; /* bands come top to bottom and the window was set for the frame */
    for (; rows > 0; rows--, pixels += stride) {
        const uint8_t *chunk;
        for (chunk = pixels; chunk < pixels + PANEL_W / 8u; chunk += CHUNK_PIXELS / 8u) {
            stp_panel_pack_mono_row(&stp_panel_ssd0323, chunk, CHUNK_PIXELS, packed);
            if (stp_lm3s6965_oled_bus.data(stp_lm3s6965_oled_bus.ctx, packed, sizeof packed) != 0)
                return -1;
        }
    }
    return 0;
}

/* Hold the picture until the board's "up" key (PE0) changes level: a test
 * harness takes its screendump first and then presses the key (QMP send-key
 * up), so the firmware's own exit status still ends QEMU.  A change rather
 * than a level: QEMU's gamepad drives PE0 through an inverter and the pin
 * reads 0 until the first key event. */
static void hold(void)
{
    uint32_t first;
    STP_SYSCTL_RCGC2 |= 1u << 4;
    STP_GPIO_DIR(STP_GPIO_E) &= ~1u;
    STP_GPIO_DEN(STP_GPIO_E) |= 1u;
    first = STP_GPIO_DATA(STP_GPIO_E, 1u);
    stp_semihost_write("stipple: frame done; press up to finish\n");
    while (STP_GPIO_DATA(STP_GPIO_E, 1u) == first)
        ;
}

const stp_board stp_board_this = {"lm3s6965evb", PANEL_W, 64u, STP_PIXEL_MONO1, "-s 128x64", panel_start, flush, hold};
