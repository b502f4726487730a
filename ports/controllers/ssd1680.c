/* SPDX-License-Identifier: MIT */
/* Solomon SSD1680: black/white(/red) e-paper controller (176 sources x 296
 * gates of RAM), on 4-wire SPI: CS# active low, D/C# low for a command byte
 * and high for its parameters and RAM data; SPI mode 0; the datasheet allows
 * far more than the 4 MHz used here (long wires to e-paper HATs).
 *
 * Sequence (datasheet's typical operating flow): hardware reset, wait for
 * BUSY low, SWRESET (0x12), wait, driver output control (0x01: gates - 1,
 * scan G0 first), data entry mode (0x11 0x03: X and Y increment, X first),
 * border waveform (0x3C), display update control 1 (0x21: normal RAM, source
 * S8..S167 for the 122-pixel glass), internal temperature sensor (0x18);
 * per frame (stp_panel_window_counters_all): RAM X window (0x44, in bytes),
 * Y window (0x45), counters (0x4E, 0x4F), write B/W RAM (0x24, 1 bit per
 * pixel, MSB = leftmost, 1 = white); then display update control 2 (0x22
 * 0xF7: clock and analog on, load temperature and waveform, display, off
 * again) and master activation (0x20), and wait for BUSY (a full refresh
 * takes seconds).  At close: deep sleep mode 1 (0x10 0x01), which only a
 * hardware reset ends.
 *
 * Polarity: stipple's ON (light) pixel is a white pixel (RAM bit 1).
 * Orientation: the panel's own, portrait: x along the sources (RAM X from
 * 0), y along the gates (RAM Y from 0 = gate 0); no rotation, no offset.
 * A 122-pixel row fills 16 RAM bytes; the 6 pad bits are sent white. */
#include "stp_panel.h"

static const uint8_t init_122x250[] STP_PANEL_ROM = {
    STP_PANEL_RESET(10),                 /* RES# low 10 ms */
    STP_PANEL_DELAY(10),
    STP_PANEL_WAIT_READY(2000),
    STP_PANEL_CMD(0x12),                 /* SWRESET */
    STP_PANEL_WAIT_READY(2000),
    STP_PANEL_CMD(0x01, 0xF9, 0x00, 0x00), /* driver output control: 250 gates, G0 first */
    STP_PANEL_CMD(0x11, 0x03),           /* data entry: X+, Y+, X first */
    STP_PANEL_CMD(0x3C, 0x05),           /* border waveform */
    STP_PANEL_CMD(0x21, 0x00, 0x80),     /* display update control 1 */
    STP_PANEL_CMD(0x18, 0x80),           /* internal temperature sensor */
    STP_PANEL_WAIT_READY(2000)
};

static const uint8_t init_128x296[] STP_PANEL_ROM = {
    STP_PANEL_RESET(10),
    STP_PANEL_DELAY(10),
    STP_PANEL_WAIT_READY(2000),
    STP_PANEL_CMD(0x12),
    STP_PANEL_WAIT_READY(2000),
    STP_PANEL_CMD(0x01, 0x27, 0x01, 0x00), /* driver output control: 296 gates, G0 first */
    STP_PANEL_CMD(0x11, 0x03),
    STP_PANEL_CMD(0x3C, 0x05),
    STP_PANEL_CMD(0x21, 0x00, 0x80),
    STP_PANEL_CMD(0x18, 0x80),
    STP_PANEL_WAIT_READY(2000)
};

static const uint8_t refresh_sequence[] STP_PANEL_ROM = {
    STP_PANEL_CMD(0x22, 0xF7),           /* display update control 2: full update */
    STP_PANEL_CMD(0x20),                 /* master activation */
    STP_PANEL_WAIT_READY(15000)          /* BUSY high while the waveform runs */
};

static const uint8_t sleep_sequence[] STP_PANEL_ROM = {
    STP_PANEL_WAIT_READY(2000),          /* never a command while BUSY (after a failed refresh) */
    STP_PANEL_CMD(0x10, 0x01)            /* deep sleep mode 1 (RAM kept) */
};

/* What the two glass sizes share: the bus, the RAM window and counter
 * commands (X in bytes of 8 pixels), the refresh and the sleep. */
#define SSD1680_COMMON                                                                          \
    .name = "SSD1680", .addressing = STP_PANEL_WINDOW_COUNTERS,                                 \
    .packing = STP_PANEL_MONO_ROW_MSB_LEFT,                                                     \
    .column_command = 0x44, .row_command = 0x45, .column_unit = 8,                              \
    .bus_flags = STP_PANEL_BUS_DC | STP_PANEL_BUS_PARAMS_AS_DATA | STP_PANEL_BUS_BUSY,          \
    .spi_mode = 0, .spi_hz = 4000000u,                                                          \
    .x_counter_command = 0x4E, .y_counter_command = 0x4F, .write_command = 0x24 /* B/W RAM */, \
    .refresh = refresh_sequence, .refresh_length = (uint16_t)sizeof refresh_sequence,           \
    .sleep = sleep_sequence, .sleep_length = (uint16_t)sizeof sleep_sequence

const stp_panel_controller stp_panel_ssd1680 = {
    SSD1680_COMMON,
    .width = 122,
    .height = 250,
    .init = init_122x250,
    .init_length = (uint16_t)sizeof init_122x250
};

const stp_panel_controller stp_panel_ssd1680_128x296 = {
    SSD1680_COMMON,
    .width = 128,
    .height = 296,
    .init = init_128x296,
    .init_length = (uint16_t)sizeof init_128x296
};
