/* SPDX-License-Identifier: MIT */
/* Solomon SSD1306: 128x64 mono OLED controller, here on 4-wire SPI (SCLK,
 * SDIN, CS# active low, D/C#: low = command, high = data; a command's
 * parameters also go with D/C# low).  SPI mode 0 (data sampled on the rising
 * edge); the datasheet's shortest serial clock cycle is 100 ns (10 MHz).
 *
 * Memory is 8 pages of 8 rows; a data byte is 8 rows of one column, bit 0 the
 * top row; in page addressing mode (set explicitly, 0x20 0x02) the column
 * pointer steps right after each byte.  A 1 bit lights the pixel (0xA6,
 * normal display): stipple's ON pixel is a lit pixel.
 *
 * Orientation: segment re-map 0xA1 (RAM column 0 on SEG127) and COM scan
 * 0xC8 (COM63 first) are what the common 128x64 modules need for RAM column
 * 0 to be the left edge and page 0 the top with the flex cable at the
 * bottom; no rotation, no column offset.  The rest of the sequence follows
 * the datasheet's example for the internal charge pump. */
#include "stp_panel.h"

/* records: a count, then a command and its parameters; count 0: a step */
static const uint8_t init_sequence[] = {
    0, STP_PANEL_STEP_RESET, 1, 0, /* RES# low (datasheet: at least 3 us) */
    0, STP_PANEL_STEP_DELAY, 1, 0, /* then released before the first command */
    1, 0xAE,       /* display off while setting up */
    2, 0xD5, 0x80, /* display clock divider / oscillator: the reset value */
    2, 0xA8, 0x3F, /* multiplex ratio: 64 rows */
    2, 0xD3, 0x00, /* display offset 0 */
    1, 0x40,       /* display start line 0 */
    2, 0x8D, 0x14, /* charge pump on (internal VCC) */
    2, 0x20, 0x02, /* memory addressing mode: page */
    1, 0xA1,       /* segment re-map: column 0 at the module's left edge */
    1, 0xC8,       /* COM scan from COM63: page 0 at the top */
    2, 0xDA, 0x12, /* COM pins: alternative configuration (128x64 modules) */
    2, 0x81, 0xCF, /* contrast */
    2, 0xD9, 0xF1, /* pre-charge periods for the charge pump */
    2, 0xDB, 0x40, /* VCOMH deselect level */
    1, 0xA4,       /* show RAM (not all on) */
    1, 0xA6,       /* not inverted: a 1 bit lights the pixel */
    1, 0xAF        /* display on */
};

const stp_panel_controller stp_panel_ssd1306 = {
    "SSD1306", 128, 64, 0,
    STP_PANEL_PAGES, STP_PANEL_MONO_COLUMN_LSB_TOP,
    init_sequence, (uint16_t)sizeof init_sequence,
    0, 0, 0,           /* no column/row window */
    0xB0, 0x00, 0x10,  /* page | p, column low | (c & 15), column high | (c >> 4) */
    STP_PANEL_BUS_DC, 0, 8000000u, 0, /* D/C line, SPI mode 0, 8 MHz, no inversion */
    0, 0, 0,           /* no counters */
    0, 0, 0, 0, 0, 0, 0, /* no line records */
    0, 0, 0, 0         /* the picture stays: no refresh, no sleep at close */
};
