/*
 * Display controllers described as data, and the few routines that turn the
 * core's bands into their command and data bytes.
 *
 * A controller description says what the silicon wants (init sequence,
 * how a write window is set, how pixels pack into bytes); a bus says how
 * bytes reach it (SPI with a data/command pin, I2C with control bytes).
 * The same description serves the bare-metal ports and the Linux SPI path.
 * Portable C99: no libc, no heap.
 */
#ifndef STIPPLE_PORTS_PANEL_H
#define STIPPLE_PORTS_PANEL_H

#include <stddef.h>
#include <stdint.h>

typedef enum stp_panel_addressing {
    /* A column window and a row window, each set by a command with start
     * and end; data then fills the window row by row (SSD0323). */
    STP_PANEL_WINDOW = 0,
    /* 8-row pages: a page command and a start column (low and high nibble
     * commands); data fills one page left to right (SSD0303, SSD1306). */
    STP_PANEL_PAGES = 1
} stp_panel_addressing;

typedef enum stp_panel_packing {
    /* 4-bit grey, two pixels per byte, the left one in the high nibble. */
    STP_PANEL_GREY4_LEFT_HIGH = 0,
    /* 1 bit per pixel, a byte is 8 rows of one column, bit 0 the top row. */
    STP_PANEL_MONO_COLUMN_LSB_TOP = 1
} stp_panel_packing;

typedef struct stp_panel_controller {
    const char *name;
    uint16_t width, height;       /* visible pixels */
    uint16_t column_offset;       /* controller column of visible column 0 */
    stp_panel_addressing addressing;
    stp_panel_packing packing;
    /* The init sequence, sent once, in order, as records: a count n (1..255)
     * and n bytes, one command and its parameters.  Each record is one
     * bus->command call: an I2C controller wants a STOP after a command's
     * parameters (SSD0303), an SPI one does not care where calls end. */
    const uint8_t *init;
    uint16_t init_length;         /* bytes of init, the counts included */
    /* STP_PANEL_WINDOW: opcodes taking (start, end); columns are counted in
     * bytes of packed pixels (column_unit pixels each) */
    uint8_t column_command, row_command, column_unit;
    /* STP_PANEL_PAGES: page_command | page, column_low | (c & 15),
     * column_high | (c >> 4) */
    uint8_t page_command, column_low_command, column_high_command;
} stp_panel_controller;

/* How bytes reach the controller.  command: bytes the controller reads as
 * commands (each call may hold a command and its parameters); data: pixel
 * bytes.  Return 0, or < 0 on a bus error. */
typedef struct stp_panel_bus {
    int (*command)(void *ctx, const uint8_t *bytes, size_t count);
    int (*data)(void *ctx, const uint8_t *bytes, size_t count);
    void *ctx;
} stp_panel_bus;

extern const stp_panel_controller stp_panel_ssd0323; /* 128x64, 4-bit grey, SPI */
extern const stp_panel_controller stp_panel_ssd0303; /* 96x16 of 132x64, mono, I2C */

/* Send the init sequence, a bus->command call per record.  Returns 0, the
 * bus error, or -1 for a record running past init_length or of count 0. */
int stp_panel_init(const stp_panel_controller *c, const stp_panel_bus *bus);

/* Grey level a MONO1 ON pixel gets on a grey panel (OFF gets 0). */
#define STP_PANEL_GREY4_ON 15u

/* Bytes one row of width pixels packs to (WINDOW controllers). */
size_t stp_panel_row_bytes(const stp_panel_controller *c, uint32_t width);

/* Pack one MONO1 row (stipple's format: pixel 0 in bit 7 of byte 0, 1 = ON)
 * of width pixels into the controller's format (WINDOW controllers):
 * out gets stp_panel_row_bytes(c, width) bytes. */
void stp_panel_pack_mono_row(const stp_panel_controller *c, const uint8_t *mono,
                             uint32_t width, uint8_t *out);

/* Set the write window to the whole visible area (WINDOW controllers);
 * the rows that follow fill it top to bottom. */
int stp_panel_window_all(const stp_panel_controller *c, const stp_panel_bus *bus);

/* Send rows [y0, y0 + rows) of a MONO1 picture, row stride bytes apart,
 * width pixels wide, packing through scratch (stp_panel_row_bytes bytes).
 * WINDOW controllers: the rows follow on from the previous call within the
 * window stp_panel_window_all set. */
int stp_panel_send_mono_rows(const stp_panel_controller *c, const stp_panel_bus *bus,
                             const uint8_t *pixels, size_t stride, uint32_t width,
                             uint32_t rows, uint8_t *scratch);

/* PAGES controllers: send one 8-row page of a MONO1 picture (rows
 * 8*page .. 8*page+7 at pixels, stride apart), through scratch (width
 * bytes). */
int stp_panel_send_mono_page(const stp_panel_controller *c, const stp_panel_bus *bus,
                             uint32_t page, const uint8_t *pixels, size_t stride,
                             uint32_t width, uint8_t *scratch);

#endif
