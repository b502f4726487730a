/* SPDX-License-Identifier: MIT */
/*
 * Emulated SPI panels for umockdev: a character device /dev/spidev0.0 whose
 * ioctl handler (in-process, like tests/usb/printer_sim.c) behaves as the
 * kernel's spidev would, and a display controller behind it that decodes
 * the bytes as the datasheet says and keeps the picture its glass shows.
 * The real stp_spipanel code talks to it through umockdev's preload library
 * (run the test under umockdev-wrapper).
 *
 * spidev: SPI_IOC_WR/RD_MODE, _MODE32, _LSB_FIRST, _BITS_PER_WORD,
 * _MAX_SPEED_HZ; SPI_IOC_MESSAGE(n) reads the n struct spi_ioc_transfer
 * from the client, resolves each tx_buf in the client's memory, and fails
 * EMSGSIZE when the message's bytes exceed bufsiz (as spidev does), EIO
 * when the fault is armed.  A message is one chip-select frame (cs_change
 * on a transfer ends the frame early).  Bytes are turned into the bit
 * stream on the wire (MSB first unless SPI_LSB_FIRST is set).
 *
 * Pins (spi_sim_lines gives the stp_spipanel_lines that drive them): RESET,
 * D/C (read as each byte arrives), BUSY (SSD1680, a deadline in monotonic
 * time), EXTCOMIN (Sharp, edges counted).
 *
 * Controllers:
 *  - SSD1306 (128x64 module): the command set with its parameter counts
 *    (parameters with D/C low), page / horizontal / vertical addressing,
 *    0x21/0x22 windows, page and column commands; the glass shows RAM
 *    through segment re-map, COM scan direction, inverse, entire-on,
 *    display on and the charge pump (a module needs it on to light).
 *    Start line, display offset, multiplex below 64 and scrolling are not
 *    modelled and count as violations.  RAM starts as noise.
 *  - Sharp LS013B7DH03: mode bits M0 M1 M2, 8-bit gate line addresses
 *    (AG0 first, 1..128), 128 data bits (D1 first, 1 = white), 8 dummy bits
 *    a line and 8 more at the end; all clear; VCOM-only command; SCS must be
 *    active high; M1 changes (EXTMODE low) or EXTCOMIN edges (high) counted.
 *  - SSD1680 (122x250 or 128x296 glass on the 176x296 RAM): commands and
 *    parameters (D/C high), SWRESET and hardware reset to defaults, driver
 *    output control, data entry mode (all eight), RAM X/Y windows and
 *    counters with their wrap-around, B/W and red RAM writes, display
 *    update control 1/2, master activation (the glass takes the B/W RAM
 *    when 0x22 asked for a display with clock, analog and waveform), deep
 *    sleep.  BUSY stays high for a while after reset, SWRESET and
 *    activation; anything sent while BUSY is high, or in deep sleep, is a
 *    violation.
 * Violations are logged as text; a correct driver leaves the log empty.
 */
#ifndef SPI_SIM_H
#define SPI_SIM_H

#include <glib.h>
#include <umockdev.h>

#include "stp_spipanel.h"

typedef enum { SPI_SIM_SSD1306, SPI_SIM_SHARP, SPI_SIM_SSD1680 } spi_sim_panel;

#define SIM_EPD_RAM_X 22  /* bytes: 176 sources */
#define SIM_EPD_RAM_Y 296 /* gates */

typedef struct spi_sim {
    UMockdevTestbed *testbed;
    UMockdevIoctlBase *handler;
    GMutex lock;
    spi_sim_panel panel;
    guint width, height, stride; /* the glass */
    guint8 *glass;               /* MONO1 rows: 1 = lit (OLED) or white */

    /* spidev */
    guint32 mode;
    guint8 bits;
    guint32 max_speed_hz;
    gsize bufsiz;

    /* faults, set by the test */
    gsize fail_after;       /* >0: EIO for the message that would pass this many bytes */
    int stuck_busy_after;   /* SSD1680: BUSY never drops after this command (-1: none) */
    guint swreset_busy_ms, refresh_busy_ms, reset_busy_ms;
    int extmode;            /* Sharp: EXTMODE high (VCOM from EXTCOMIN) */

    /* pins */
    int dc, reset_low, extcomin;
    gint64 busy_until;      /* monotonic us */
    int busy_stuck;

    /* what the driver did */
    gsize bytes;            /* accepted message bytes */
    guint messages, transfers, max_message, oversize, unknown_ioctls, failed;
    guint32 speed_min, speed_max; /* effective SCLK of the transfers */
    guint busy_polls;       /* wait_ready polls that found BUSY high */
    guint resets;
    guint extcomin_edges, m1_changes, vcom_commands;
    int last_m1;
    guint lines_written, refreshes;
    GPtrArray *violations;

    /* SSD1306 */
    struct {
        guint8 ram[8][128];
        guint8 cmd[8];
        guint cmd_len, cmd_need;
        guint mode, col, page, col_start, col_end, page_start, page_end;
        int display_on, charge_pump, remap, com_reverse, inverse, all_on;
        guint start_line, offset, mux;
    } oled;
    /* Sharp */
    struct {
        guint8 mem[128][16];
        guint8 line[16];
        int state;
        guint acc, nbits, address, data_bits, tail_bits, lines_in_frame;
        int m0, m1, m2;
    } sharp;
    /* SSD1680 */
    struct {
        guint8 bw[SIM_EPD_RAM_Y][SIM_EPD_RAM_X], red[SIM_EPD_RAM_Y][SIM_EPD_RAM_X];
        int cmd; /* -1: none */
        guint8 param[8];
        guint nparam;
        guint entry, xs, xe, ys, ye, xc, yc, gates, gate_flags;
        guint8 ctrl1a, ctrl1b, ctrl2, border;
        int deep_sleep, swresets;
    } epd;
} spi_sim;

/* A testbed with /dev/spidev0.0 and the panel behind it (glass width x
 * height: 128x64, 128x128, 122x250 or 128x296).  bufsiz > 0 also creates
 * /sys/module/spidev/parameters/bufsiz holding it; 0: no such file, spidev's
 * default 4096 applies. */
spi_sim *spi_sim_new(spi_sim_panel panel, guint width, guint height, gsize bufsiz);
void spi_sim_free(spi_sim *sim);

/* The control lines wired to the emulated panel: RESET, D/C, BUSY, EXTCOMIN
 * as the panel has them (vcom only when with_vcom). */
void spi_sim_lines(spi_sim *sim, int with_vcom, stp_spipanel_lines *lines);

/* Fills the panel's memory and glass with noise (a fresh frame must write
 * every pixel). */
void spi_sim_scramble(spi_sim *sim, guint32 seed);

/* The violations as one string ("; "-joined; g_free it). */
char *spi_sim_violations(spi_sim *sim);

#endif
