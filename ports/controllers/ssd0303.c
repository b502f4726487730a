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
static const uint8_t init_sequence[] STP_PANEL_ROM = {
    STP_PANEL_CMD(0xAE),       /* display off while setting up */
    STP_PANEL_CMD(0x81, 0x2B), /* contrast */
    STP_PANEL_CMD(0xA1),       /* segment re-map, as the EVB wires the panel */
    STP_PANEL_CMD(0x40),       /* display start line 0 */
    STP_PANEL_CMD(0xD3, 0x00), /* display offset 0 */
    STP_PANEL_CMD(0xA8, 0x0F), /* multiplex ratio: 16 rows */
    STP_PANEL_CMD(0xA4),       /* show memory (not all on) */
    STP_PANEL_CMD(0xA6),       /* not inverted: a 1 bit lights the pixel */
    STP_PANEL_CMD(0xC8),       /* COM scan direction as the EVB wires the rows */
    STP_PANEL_CMD(0xD5, 0x72), /* display clock divider / oscillator */
    STP_PANEL_CMD(0xD8, 0x00), /* mono mode */
    STP_PANEL_CMD(0xD9, 0x22), /* pre-charge period */
    STP_PANEL_CMD(0xDA, 0x12), /* COM pin configuration */
    STP_PANEL_CMD(0xDB, 0x0F), /* VCOM deselect level */
    STP_PANEL_CMD(0xAD, 0x8B), /* DC-DC converter on */
    STP_PANEL_CMD(0xAF)        /* display on */
};

/* The I2C firmware port reads no SPI facts, counters or line records. */
const stp_panel_controller stp_panel_ssd0303 = {
    .name = "SSD0303",
    .width = 96,
    .height = 16,
    .column_offset = 36,
    .addressing = STP_PANEL_PAGES,
    .packing = STP_PANEL_MONO_COLUMN_LSB_TOP,
    .init = init_sequence,
    .init_length = (uint16_t)sizeof init_sequence,
    .page_command = 0xB0,       /* page | p */
    .column_low_command = 0x00, /* column low | (c & 15) */
    .column_high_command = 0x10 /* column high | (c >> 4) */
};
