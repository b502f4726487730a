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

#define WAIT(ms) 0, STP_PANEL_STEP_WAIT_READY, (uint8_t)((ms) & 0xFF), (uint8_t)((ms) >> 8)

/* records: a count, then a command and its parameters; count 0: a step */
static const uint8_t init_122x250[] = {
    0, STP_PANEL_STEP_RESET, 10, 0, /* RES# low 10 ms */
    0, STP_PANEL_STEP_DELAY, 10, 0,
    WAIT(2000),
    1, 0x12,                  /* SWRESET */
    WAIT(2000),
    4, 0x01, 0xF9, 0x00, 0x00, /* driver output control: 250 gates, G0 first */
    2, 0x11, 0x03,            /* data entry: X+, Y+, X first */
    2, 0x3C, 0x05,            /* border waveform */
    3, 0x21, 0x00, 0x80,      /* display update control 1 */
    2, 0x18, 0x80,            /* internal temperature sensor */
    WAIT(2000)
};

static const uint8_t init_128x296[] = {
    0, STP_PANEL_STEP_RESET, 10, 0,
    0, STP_PANEL_STEP_DELAY, 10, 0,
    WAIT(2000),
    1, 0x12,
    WAIT(2000),
    4, 0x01, 0x27, 0x01, 0x00, /* driver output control: 296 gates, G0 first */
    2, 0x11, 0x03,
    2, 0x3C, 0x05,
    3, 0x21, 0x00, 0x80,
    2, 0x18, 0x80,
    WAIT(2000)
};

static const uint8_t refresh_sequence[] = {
    2, 0x22, 0xF7,            /* display update control 2: full update */
    1, 0x20,                  /* master activation */
    WAIT(15000)               /* BUSY high while the waveform runs */
};

static const uint8_t sleep_sequence[] = {
    WAIT(2000),               /* never a command while BUSY (after a failed refresh) */
    2, 0x10, 0x01             /* deep sleep mode 1 (RAM kept) */
};

const stp_panel_controller stp_panel_ssd1680 = {
    "SSD1680", 122, 250, 0,
    STP_PANEL_WINDOW_COUNTERS, STP_PANEL_MONO_ROW_MSB_LEFT,
    init_122x250, (uint16_t)sizeof init_122x250,
    0x44, 0x45, 8,            /* RAM X window in bytes, RAM Y window */
    0, 0, 0,                  /* no pages */
    STP_PANEL_BUS_DC | STP_PANEL_BUS_PARAMS_AS_DATA | STP_PANEL_BUS_BUSY, 0, 4000000u, 0,
    0x4E, 0x4F, 0x24,         /* X and Y counters, write B/W RAM */
    0, 0, 0, 0, 0, 0, 0,      /* no line records */
    refresh_sequence, (uint16_t)sizeof refresh_sequence,
    sleep_sequence, (uint16_t)sizeof sleep_sequence
};

const stp_panel_controller stp_panel_ssd1680_128x296 = {
    "SSD1680", 128, 296, 0,
    STP_PANEL_WINDOW_COUNTERS, STP_PANEL_MONO_ROW_MSB_LEFT,
    init_128x296, (uint16_t)sizeof init_128x296,
    0x44, 0x45, 8,
    0, 0, 0,
    STP_PANEL_BUS_DC | STP_PANEL_BUS_PARAMS_AS_DATA | STP_PANEL_BUS_BUSY, 0, 4000000u, 0,
    0x4E, 0x4F, 0x24,
    0, 0, 0, 0, 0, 0, 0,
    refresh_sequence, (uint16_t)sizeof refresh_sequence,
    sleep_sequence, (uint16_t)sizeof sleep_sequence
};
