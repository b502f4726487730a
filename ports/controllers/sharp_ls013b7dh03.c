/* SPDX-License-Identifier: MIT */
/* Sharp LS013B7DH03: 128x128 memory LCD (a controller-less panel whose
 * serial interface is the "controller"), on SPI without a D/C line.
 *
 * Datasheet facts used:
 *  - SCS (chip select) is active HIGH; SCLK idle low, data read on the rising
 *    edge (SPI mode 0); 1 MHz is a safe clock for this panel.
 *  - A write is one SCS frame: the mode bits M0 (1 = data update), M1 (VCOM
 *    level when EXTMODE = L; ignored when EXTMODE = H), M2 (1 = all clear)
 *    and 5 dummy bits; then per line the 8-bit gate line address (lines
 *    counted from 1, AG0 first), the 128 data bits D1..D128 (D1 = the
 *    leftmost pixel, 1 = white) and 8 dummy bits; after the last line 8
 *    more dummy bits (16 in all).  A VCOM-only command (M0 = M2 = 0) is the
 *    mode byte and 8 dummy bits.
 *  - Every field goes out least significant bit first (M0, AG0 and D1
 *    first).
 * Bit order choice: the bus is left MSB first (SPI_LSB_FIRST is refused by
 * many SPI controllers, the Raspberry Pi's among them) and the bytes are
 * built so that the first bit on the wire is the datasheet's first bit: the
 * mode byte is M0 << 7 | M1 << 6 | M2 << 5 (write 0x80, VCOM 0x40), the line
 * address is sent bit-reversed, and the data byte k holds D(8k+1) in bit 7,
 * which is exactly stipple's MONO1 row (pixel 0 in bit 7): with 1 = white =
 * ON, rows go out unchanged.
 * Orientation: row 0 is gate line 1, pixel 0 is D1; no rotation, no offset.
 * VCOM must alternate (the panel's DC bias): through M1 in software, or the
 * EXTCOMIN line; stp_spipanel does either (STP_PANEL_BUS_VCOM). */
#include "stp_panel.h"

/* records: a count, then the bytes of one SCS frame */
static const uint8_t init_sequence[] STP_PANEL_ROM = {
    STP_PANEL_CMD(0x20, 0x00) /* all clear (M2), VCOM low: the panel starts white */
};

/* No refresh sequence: the panel shows lines as they arrive. */
const stp_panel_controller stp_panel_sharp_ls013b7dh03 = {
    .name = "LS013B7DH03",
    .width = 128,
    .height = 128,
    .addressing = STP_PANEL_LINES,
    .packing = STP_PANEL_MONO_ROW_MSB_LEFT,
    .init = init_sequence,
    .init_length = (uint16_t)sizeof init_sequence,
    .bus_flags = STP_PANEL_BUS_CS_HIGH | STP_PANEL_BUS_VCOM, /* SCS active high */
    .spi_mode = 0,
    .spi_hz = 1000000u,
    .line_write_mode = 0x80,      /* M0 */
    .line_vcom_bit = 0x40,        /* M1 */
    .line_hold_mode = 0x00,       /* VCOM only */
    .line_address_reversed = 1,   /* the address goes out LSB first */
    .line_first_address = 1,      /* row 0 = gate line 1 */
    .line_trailer = 1,            /* 8 dummy bits after each line */
    .write_trailer = 1            /* and 8 more at the end */
};
