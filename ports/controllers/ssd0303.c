/* SPDX-License-Identifier: MIT */
/* Solomon SSD0303: 132x64 mono OLED controller on I2C (the lm3s811evb's
 * OSRAM 96x16 panel, wired to columns 36..131 of pages 0 and 1).
 *
 * Memory is 8 pages of 8 rows; a data byte is 8 rows of one column, bit 0
 * the top row; the column pointer steps right after each data byte.  The
 * init sequence is the one TI's Stellaris EVB example driver sends to this
 * panel (values from its OSRAM 96x16 table); QEMU 7.2 accepts every command
 * of it and ignores the timing, contrast and power values.  Each record is a
 * command and its parameters, which the I2C bus ends with a STOP. */
#include "stp_panel.h"

/* records: a count, then a command and its parameters (stp_panel.h) */
static const uint8_t init_sequence[] = {
    1, 0xAE,       /* display off while setting up */
    2, 0x81, 0x2B, /* contrast */
    1, 0xA1,       /* segment re-map, as the EVB wires the panel */
    1, 0x40,       /* display start line 0 */
    2, 0xD3, 0x00, /* display offset 0 */
    2, 0xA8, 0x0F, /* multiplex ratio: 16 rows */
    1, 0xA4,       /* show memory (not all on) */
    1, 0xA6,       /* not inverted: a 1 bit lights the pixel */
    1, 0xC8,       /* COM scan direction as the EVB wires the rows */
    2, 0xD5, 0x72, /* display clock divider / oscillator */
    2, 0xD8, 0x00, /* mono mode */
    2, 0xD9, 0x22, /* pre-charge period */
    2, 0xDA, 0x12, /* COM pin configuration */
    2, 0xDB, 0x0F, /* VCOM deselect level */
    2, 0xAD, 0x8B, /* DC-DC converter on */
    1, 0xAF        /* display on */
};

const stp_panel_controller stp_panel_ssd0303 = {
    "SSD0303", 96, 16, 36,
    STP_PANEL_PAGES, STP_PANEL_MONO_COLUMN_LSB_TOP,
    init_sequence, (uint16_t)sizeof init_sequence,
    0, 0, 0,         /* no column/row window */
    0xB0, 0x00, 0x10, /* page | p, column low | (c & 15), column high | (c >> 4) */
    0, 0, 0, 0,      /* SPI facts: not used by the I2C firmware port */
    0, 0, 0,         /* no counters */
    0, 0, 0, 0, 0, 0, 0, /* no line records */
    0, 0, 0, 0       /* no refresh or sleep sequence */
};
