/* SPDX-License-Identifier: MIT */
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

#ifdef __cplusplus
extern "C" {
#endif

/* Where the sequences (init, refresh, sleep) live: program memory on an
 * AVR (avr-gcc would copy plain const data into RAM at start-up), plain
 * const data elsewhere.  stp_panel_run reads them accordingly. */
#if defined(__AVR__)
#include <avr/pgmspace.h>
#define STP_PANEL_ROM PROGMEM
#else
#define STP_PANEL_ROM
#endif

typedef enum stp_panel_addressing {
    /* A column window and a row window, each set by a command with start
     * and end; data then fills the window row by row (SSD0323). */
    STP_PANEL_WINDOW = 0,
    /* 8-row pages: a page command and a start column (low and high nibble
     * commands); data fills one page left to right (SSD0303, SSD1306). */
    STP_PANEL_PAGES = 1,
    /* A RAM window and address counters, then a RAM-write command and the
     * whole window's data row by row (SSD1680 and the SSD16xx e-paper
     * family): column_command (start, end: one byte each, in column_unit
     * pixels), row_command (start, end: 16 bits each, low byte first),
     * x_counter_command (one byte, column units), y_counter_command (16
     * bits, low byte first), write_command.  The panel shows RAM only when
     * the refresh sequence runs, so a frame is gathered first. */
    STP_PANEL_WINDOW_COUNTERS = 2,
    /* No addressing commands: a write is a chip-select frame holding a mode
     * byte (line_write_mode), then per row a line record [gate line address]
     * [row bytes][line_trailer zero bytes], then write_trailer zero bytes
     * (Sharp memory LCDs).  Rows may be written in any order. */
    STP_PANEL_LINES = 3
} stp_panel_addressing;

typedef enum stp_panel_packing {
    /* 4-bit grey, two pixels per byte, the left one in the high nibble. */
    STP_PANEL_GREY4_LEFT_HIGH = 0,
    /* 1 bit per pixel, a byte is 8 rows of one column, bit 0 the top row. */
    STP_PANEL_MONO_COLUMN_LSB_TOP = 1,
    /* 1 bit per pixel, a byte is 8 pixels of one row, the leftmost in bit 7
     * (the first bit out on an MSB-first bus); an ON pixel is 1 (0 with
     * invert).  Without invert this is stipple's MONO1 row itself.  Pad bits
     * past the width are sent as 1. */
    STP_PANEL_MONO_ROW_MSB_LEFT = 2
} stp_panel_packing;

/* bus_flags: how the controller meets a bus (0 for SSD0303 and SSD0323,
 * whose buses live in their board ports). */
#define STP_PANEL_BUS_DC 0x01u           /* a D/C line: low = command bytes, high = data */
#define STP_PANEL_BUS_PARAMS_AS_DATA 0x02u /* with BUS_DC: a command's parameters go
                                            with D/C high (SSD1680); without, low
                                            like the command (SSD1306) */
#define STP_PANEL_BUS_CS_HIGH 0x04u      /* chip select is active high (Sharp SCS) */
#define STP_PANEL_BUS_BUSY 0x08u         /* a BUSY output the sequences wait on */
#define STP_PANEL_BUS_VCOM 0x10u         /* the panel wants VCOM alternated: the
                                            mode byte's line_vcom_bit, or EXTCOMIN */

/* Steps inside a sequence (init, refresh, sleep): a record whose count is 0
 * is a step, four bytes: 0, op, arg low byte, arg high byte. */
#define STP_PANEL_STEP_RESET 1u      /* pulse RESET: asserted arg ms, then released */
#define STP_PANEL_STEP_WAIT_READY 2u /* wait until BUSY is released, at most arg ms */
#define STP_PANEL_STEP_DELAY 3u      /* wait arg ms */

/* Records for a sequence, counted by the preprocessor:
 * STP_PANEL_CMD(0xD5, 0x80) is the record 2, 0xD5, 0x80 (a command and up
 * to 15 parameters); STP_PANEL_RESET(ms), STP_PANEL_DELAY(ms) and
 * STP_PANEL_WAIT_READY(ms) are the steps (ms 0..65535). */
#define STP_PANEL_CMD(...) STP_PANEL_NARGS_(__VA_ARGS__), __VA_ARGS__
#define STP_PANEL_NARGS_(...)                                                               \
    STP_PANEL_16TH_(__VA_ARGS__, 16, 15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0)
#define STP_PANEL_16TH_(a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, a15,     \
                        a16, n, ...)                                                          \
    n
#define STP_PANEL_STEP_(op, ms) 0, (op), (uint8_t)((ms) & 0xFFu), (uint8_t)(((ms) >> 8) & 0xFFu)
#define STP_PANEL_RESET(ms) STP_PANEL_STEP_(STP_PANEL_STEP_RESET, ms)
#define STP_PANEL_DELAY(ms) STP_PANEL_STEP_(STP_PANEL_STEP_DELAY, ms)
#define STP_PANEL_WAIT_READY(ms) STP_PANEL_STEP_(STP_PANEL_STEP_WAIT_READY, ms)

/* Written with designated initialisers: a field a controller does not use
 * is left out, and is 0. */
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

    /* ---- added with the Linux SPI path (stp_spipanel); all 0 for SSD0303
     * and SSD0323, whose firmware ports do not read them ---- */
    uint8_t bus_flags;            /* STP_PANEL_BUS_* */
    uint8_t spi_mode;             /* clock polarity << 1 | phase: 0..3 */
    uint32_t spi_hz;              /* default SCLK, hertz (within the datasheet's) */
    uint8_t invert;               /* MONO_ROW_MSB_LEFT: 1 sends ON as 0 */
    /* STP_PANEL_WINDOW_COUNTERS (with column_command, row_command,
     * column_unit above) */
    uint8_t x_counter_command, y_counter_command, write_command;
    /* STP_PANEL_LINES: mode bytes as they go out MSB first */
    uint8_t line_write_mode;      /* opens a write */
    uint8_t line_vcom_bit;        /* OR'ed into a mode byte while VCOM is high */
    uint8_t line_hold_mode;       /* a VCOM-only command (then write_trailer bytes) */
    uint8_t line_address_reversed;/* 1: the address goes out least significant bit
                                     first, so it is sent bit-reversed */
    uint16_t line_first_address;  /* gate line address of row 0 */
    uint8_t line_trailer, write_trailer; /* zero bytes: after each line record,
                                            and once more after the last */
    /* Sequences in init's format (steps allowed, see stp_panel_run):
     * refresh runs after a frame's pixels are in RAM (e-paper display
     * update), sleep when the panel is let go.  NULL / 0: none. */
    const uint8_t *refresh;
    uint16_t refresh_length;
    const uint8_t *sleep;
    uint16_t sleep_length;
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
/* The SPI panels of stp_spipanel (each file's comment gives the datasheet
 * facts used, polarity and orientation). */
extern const stp_panel_controller stp_panel_ssd1306;          /* 128x64 mono OLED */
extern const stp_panel_controller stp_panel_sharp_ls013b7dh03; /* 128x128 memory LCD */
extern const stp_panel_controller stp_panel_ssd1680;          /* 122x250 e-paper (2.13") */
extern const stp_panel_controller stp_panel_ssd1680_128x296;  /* 128x296 e-paper (2.9") */

/* Send the init sequence, a bus->command call per record.  Returns 0, the
 * bus error, or -1 for a record running past init_length or of count 0
 * (a step: sequences with steps go through stp_panel_run). */
int stp_panel_init(const stp_panel_controller *c, const stp_panel_bus *bus);

/* Runs a step of a sequence: op is STP_PANEL_STEP_*, arg its argument (ms).
 * Returns 0, or < 0 to stop the sequence (a timeout, a line error, an op
 * it does not know). */
typedef int (*stp_panel_step_fn)(void *ctx, unsigned op, unsigned arg);

/* Runs a sequence of length bytes (STP_PANEL_ROM): records go to
 * bus->command as in stp_panel_init, steps (count 0) to step(step_ctx, op,
 * arg).  Returns 0, the bus or step error, or -1 for a record or step
 * running past the end (on an AVR also for a record of more than 16
 * bytes: each is copied out of program memory into 16 bytes of stack). */
int stp_panel_run(const uint8_t *seq, uint16_t length, const stp_panel_bus *bus,
                  stp_panel_step_fn step, void *step_ctx);

/* Grey level a MONO1 ON pixel gets on a grey panel (OFF gets 0). */
#define STP_PANEL_GREY4_ON 15u

/* Bytes one row of width pixels packs to (row packings: GREY4_LEFT_HIGH,
 * MONO_ROW_MSB_LEFT). */
size_t stp_panel_row_bytes(const stp_panel_controller *c, uint32_t width);

/* Pack one MONO1 row (stipple's format: pixel 0 in bit 7 of byte 0, 1 = ON)
 * of width pixels into the controller's format (row packings): out gets
 * stp_panel_row_bytes(c, width) bytes. */
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

/* Pack 8 MONO1 rows (pixels, rows stride bytes apart, width pixels) into
 * width bytes of the SSD1306 page layout (STP_PANEL_MONO_COLUMN_LSB_TOP:
 * out[x] holds column x, bit r row r), as u8g2's page buffers hold a tile
 * row too. */
void stp_panel_pack_page(const uint8_t *pixels, size_t stride, uint32_t width, uint8_t *out);

/* The same for one 8x8 block: rows[r * stride] (r = 0..7) are the 8 row
 * bytes of 8 columns; out[k] gets column k (bit r: row r).  A sender that
 * streams a page packs it a block at a time, with no page buffer. */
void stp_panel_pack_block(const uint8_t *rows, size_t stride, uint8_t out[8]);

/* PAGES controllers: send page `page` (rows 8 page .. 8 page + 7) as it
 * is: columns holds width bytes in the panel's layout (column x in byte x,
 * least significant bit on top: STP_PIXEL_MONO1_PAGES, port.h). */
int stp_panel_send_page(const stp_panel_controller *c, const stp_panel_bus *bus, uint32_t page,
                        const uint8_t *columns, uint32_t width);

/* PAGES controllers: send one 8-row page of a MONO1 picture (rows
 * 8*page .. 8*page+7 at pixels, stride apart), through scratch (width
 * bytes). */
int stp_panel_send_mono_page(const stp_panel_controller *c, const stp_panel_bus *bus,
                             uint32_t page, const uint8_t *pixels, size_t stride,
                             uint32_t width, uint8_t *scratch);

/* PAGES controllers fed by bands of any height: a band row goes to the
 * page it belongs to; a page the band holds whole is sent straight from the
 * band, other rows are gathered in page_rows until the page's last row (or
 * the panel's) has come.  width <= 8 * row_bytes; page_rows holds 8 rows of
 * row_bytes, columns width bytes (the packed page). */
typedef struct stp_panel_pages {
    const stp_panel_controller *controller;
    const stp_panel_bus *bus;
    uint32_t width, height;
    size_t row_bytes;
    uint8_t *page_rows;
    uint8_t *columns;
} stp_panel_pages;

/* Take rows [y0, y0 + rows) of a MONO1 picture (stride bytes apart), as a
 * stp_port flush does.  Returns 0, or the bus error. */
int stp_panel_pages_put(const stp_panel_pages *p, uint32_t y0, uint32_t rows,
                        const uint8_t *pixels, size_t stride);

/* PAGES controllers fed a STP_PIXEL_MONO1_PAGES band, as a stp_port flush
 * is: rows [y0, y0 + rows) in (rows + 7) / 8 pages of width bytes, stride
 * bytes apart, each sent as it is (no packing, no buffer).  y0 must be a
 * multiple of 8 (stp_renderer_render's page bands are).  Returns 0, -1 for
 * a y0 within a page, or the bus error. */
int stp_panel_pages_send(const stp_panel_controller *c, const stp_panel_bus *bus, uint32_t y0,
                         uint32_t rows, const uint8_t *pages, size_t stride, uint32_t width);

/* WINDOW_COUNTERS controllers: set the RAM window to the visible area
 * (columns from column_offset), the counters to its first pixel, and send
 * write_command; the frame's packed rows follow as data, top row first. */
int stp_panel_window_counters_all(const stp_panel_controller *c, const stp_panel_bus *bus);

/* LINES controllers: bytes of one line record (address, packed row,
 * line_trailer). */
size_t stp_panel_line_record_bytes(const stp_panel_controller *c);

/* LINES controllers: the mode byte opening a write (hold = 0) or a
 * VCOM-only command (hold = 1), with VCOM at vcom (0/1). */
uint8_t stp_panel_line_mode(const stp_panel_controller *c, int hold, int vcom);

/* LINES controllers: write the line record of row y (0..height-1) of a MONO1
 * row into out (stp_panel_line_record_bytes bytes); returns that count. */
size_t stp_panel_line_record(const stp_panel_controller *c, uint32_t y, const uint8_t *mono,
                             uint8_t *out);

#ifdef __cplusplus
}
#endif

#endif
