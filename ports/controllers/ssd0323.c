/* SPDX-License-Identifier: MIT */
/* Solomon SSD0323: 128x64 4-bit grey OLED controller on SPI (the
 * lm3s6965evb's panel).  The sequence below is one QEMU 7.2 accepts and that
 * follows the datasheet's order: display off, set up addressing, timing and
 * contrast, then the grey table, then display on. */
#include "stp_panel.h"

/* records: a count, then a command and its parameters (stp_panel.h) */
static const uint8_t init_sequence[] STP_PANEL_ROM = {
    STP_PANEL_CMD(0xAE),       /* display off while setting up */
    STP_PANEL_CMD(0xA0, 0x52), /* re-map: column address and COM scan as the EVB wires them */
    STP_PANEL_CMD(0xA1, 0x00), /* display start line 0 */
    STP_PANEL_CMD(0xA2, 0x00), /* display offset 0 */
    STP_PANEL_CMD(0xA4),       /* normal display (not all on/off, not inverted) */
    STP_PANEL_CMD(0xA8, 0x3F), /* multiplex ratio: 64 rows */
    STP_PANEL_CMD(0x81, 0x60), /* contrast */
    STP_PANEL_CMD(0x86),       /* full current range */
    STP_PANEL_CMD(0xAD, 0x02), /* DC-DC converter off: the EVB supplies the panel */
    STP_PANEL_CMD(0xB1, 0x22), /* phase lengths */
    STP_PANEL_CMD(0xB2, 0x46), /* row period */
    STP_PANEL_CMD(0xB3, 0x41), /* display clock divider */
    STP_PANEL_CMD(0xBC, 0x0F), /* precharge voltage */
    STP_PANEL_CMD(0xBE, 0x0F), /* VCOMH */
    STP_PANEL_CMD(0xBF, 0x02), /* VSL */
    /* grey-scale table: 8 bytes of pulse widths */
    STP_PANEL_CMD(0xB8, 0x01, 0x11, 0x22, 0x32, 0x43, 0x54, 0x65, 0x76),
    STP_PANEL_CMD(0xE3),       /* no operation: ends the table for controllers that count */
    STP_PANEL_CMD(0xAF)        /* display on */
};

/* The firmware port reads no SPI facts, counters or line records. */
const stp_panel_controller stp_panel_ssd0323 = {
    .name = "SSD0323",
    .width = 128,
    .height = 64,
    .addressing = STP_PANEL_WINDOW,
    .packing = STP_PANEL_GREY4_LEFT_HIGH,
    .init = init_sequence,
    .init_length = (uint16_t)sizeof init_sequence,
    .column_command = 0x15, /* column window, in bytes */
    .row_command = 0x75,    /* row window */
    .column_unit = 2        /* pixels per byte */
};
