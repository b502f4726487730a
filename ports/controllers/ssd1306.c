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

static const uint8_t init_sequence[] STP_PANEL_ROM = {
    STP_PANEL_RESET(1),        /* RES# low (datasheet: at least 3 us) */
    STP_PANEL_DELAY(1),        /* then released before the first command */
    STP_PANEL_CMD(0xAE),       /* display off while setting up */
    STP_PANEL_CMD(0xD5, 0x80), /* display clock divider / oscillator: the reset value */
    STP_PANEL_CMD(0xA8, 0x3F), /* multiplex ratio: 64 rows */
    STP_PANEL_CMD(0xD3, 0x00), /* display offset 0 */
    STP_PANEL_CMD(0x40),       /* display start line 0 */
    STP_PANEL_CMD(0x8D, 0x14), /* charge pump on (internal VCC) */
    STP_PANEL_CMD(0x20, 0x02), /* memory addressing mode: page */
    STP_PANEL_CMD(0xA1),       /* segment re-map: column 0 at the module's left edge */
    STP_PANEL_CMD(0xC8),       /* COM scan from COM63: page 0 at the top */
    STP_PANEL_CMD(0xDA, 0x12), /* COM pins: alternative configuration (128x64 modules) */
    STP_PANEL_CMD(0x81, 0xCF), /* contrast */
    STP_PANEL_CMD(0xD9, 0xF1), /* pre-charge periods for the charge pump */
    STP_PANEL_CMD(0xDB, 0x40), /* VCOMH deselect level */
    STP_PANEL_CMD(0xA4),       /* show RAM (not all on) */
    STP_PANEL_CMD(0xA6),       /* not inverted: a 1 bit lights the pixel */
    STP_PANEL_CMD(0xAF)        /* display on */
};

/* No refresh and no sleep sequence: the picture stays. */
const stp_panel_controller stp_panel_ssd1306 = {
    .name = "SSD1306",
    .width = 128,
    .height = 64,
    .addressing = STP_PANEL_PAGES,
    .packing = STP_PANEL_MONO_COLUMN_LSB_TOP,
    .init = init_sequence,
    .init_length = (uint16_t)sizeof init_sequence,
    .page_command = 0xB0,        /* page | p */
    .column_low_command = 0x00,  /* column low | (c & 15) */
    .column_high_command = 0x10, /* column high | (c >> 4) */
    .bus_flags = STP_PANEL_BUS_DC, /* D/C line; parameters with D/C low */
    .spi_mode = 0,
    .spi_hz = 8000000u
};
