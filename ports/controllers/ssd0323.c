/* SPDX-License-Identifier: MIT */
/* Solomon SSD0323: 128x64 4-bit grey OLED controller on SPI (the
 * lm3s6965evb's panel).  The sequence below is one QEMU 7.2 accepts and that
 * follows the datasheet's order: display off, set up addressing, timing and
 * contrast, then the grey table, then display on. */
#include "stp_panel.h"

/* records: a count, then a command and its parameters (stp_panel.h) */
static const uint8_t init_sequence[] = {
    1, 0xAE,          /* display off while setting up */
    2, 0xA0, 0x52,    /* re-map: column address and COM scan as the EVB wires them */
    2, 0xA1, 0x00,    /* display start line 0 */
    2, 0xA2, 0x00,    /* display offset 0 */
    1, 0xA4,          /* normal display (not all on/off, not inverted) */
    2, 0xA8, 0x3F,    /* multiplex ratio: 64 rows */
    2, 0x81, 0x60,    /* contrast */
    1, 0x86,          /* full current range */
    2, 0xAD, 0x02,    /* DC-DC converter off: the EVB supplies the panel */
    2, 0xB1, 0x22,    /* phase lengths */
    2, 0xB2, 0x46,    /* row period */
    2, 0xB3, 0x41,    /* display clock divider */
    2, 0xBC, 0x0F,    /* precharge voltage */
    2, 0xBE, 0x0F,    /* VCOMH */
    2, 0xBF, 0x02,    /* VSL */
    9, 0xB8,          /* grey-scale table: 8 bytes of pulse widths */
    0x01, 0x11, 0x22, 0x32, 0x43, 0x54, 0x65, 0x76,
    1, 0xE3,          /* no operation: ends the table for controllers that count */
    1, 0xAF           /* display on */
};

const stp_panel_controller stp_panel_ssd0323 = {
    "SSD0323", 128, 64, 0,
    STP_PANEL_WINDOW, STP_PANEL_GREY4_LEFT_HIGH,
    init_sequence, (uint16_t)sizeof init_sequence,
    0x15, 0x75, 2, /* column window in byte units (2 pixels), row window */
    0, 0, 0,
    0, 0, 0, 0,    /* SPI facts: not used by the firmware port */
    0, 0, 0,       /* no counters */
    0, 0, 0, 0, 0, 0, 0, /* no line records */
    0, 0, 0, 0     /* no refresh or sleep sequence */
};
