/* SPDX-License-Identifier: MIT */
/* Sequences, packing and addressing for the controllers of stp_panel.h:
 * init/refresh/sleep sequences, row and page packing, SSD16xx RAM windows
 * and memory-LCD line records.  Portable C99: no libc, no heap. */
#include "stp_panel.h"

/* The one walker over records and steps: init sequences, refresh and sleep
 * sequences alike. */
/* A sequence's byte: program memory on an AVR (STP_PANEL_ROM) */
#if defined(__AVR__)
#define SEQ_BYTE(p) pgm_read_byte(p)
#define SEQ_RECORD_MAX 16u
#else
#define SEQ_BYTE(p) (*(p))
#endif

int stp_panel_run(const uint8_t *seq, uint16_t length, const stp_panel_bus *bus,
                  stp_panel_step_fn step, void *step_ctx)
{
    const uint8_t *end = seq + length;
    while (seq != end) {
        uint8_t n = SEQ_BYTE(seq++);
        size_t left = (size_t)(end - seq);
        int status;
        if (n == 0) {
            /* a step: 0, op, arg low, arg high */
            if (left < 3u || !step)
                return -1;
            status = step(step_ctx, SEQ_BYTE(seq), (unsigned)SEQ_BYTE(seq + 1) | (unsigned)SEQ_BYTE(seq + 2) << 8);
            seq += 3;
        } else {
            if (n > left)
                return -1;
#if defined(__AVR__)
            {
                uint8_t record[SEQ_RECORD_MAX];
                if (n > SEQ_RECORD_MAX)
                    return -1;
                memcpy_P(record, seq, n);
                status = bus->command(bus->ctx, record, n);
            }
#else
            status = bus->command(bus->ctx, seq, n);
#endif
            seq += n;
        }
        if (status != 0)
            return status;
    }
    return 0;
}

int stp_panel_init(const stp_panel_controller *c, const stp_panel_bus *bus)
{
    return stp_panel_run(c->init, c->init_length, bus, 0, 0);
}

size_t stp_panel_row_bytes(const stp_panel_controller *c, uint32_t width)
{
    if (c->packing == STP_PANEL_MONO_ROW_MSB_LEFT)
        return ((size_t)width + 7u) / 8u;
    return c->packing == STP_PANEL_GREY4_LEFT_HIGH ? ((size_t)width + 1u) / 2u : width;
}

void stp_panel_pack_mono_row(const stp_panel_controller *c, const uint8_t *mono,
                             uint32_t width, uint8_t *out)
{
    uint32_t x;
    if (c->packing == STP_PANEL_MONO_ROW_MSB_LEFT) {
        /* stipple's own layout: copy, invert if asked, pad bits set */
        size_t i, n = ((size_t)width + 7u) / 8u;
        unsigned pad = (8u - (width & 7u)) & 7u;
        for (i = 0; i < n; i++)
            out[i] = (uint8_t)(c->invert ? ~mono[i] : mono[i]);
        if (n > 0 && pad)
            out[n - 1] = (uint8_t)(out[n - 1] | ((1u << pad) - 1u));
        return;
    }
    /* x even: pixels x and x + 1 are bits 7 and 6 of their byte shifted
     * left by x & 7; they become bits 4 and 0, times the ON level */
    for (x = 0; x < width; x += 2) {
        unsigned pair = ((unsigned)mono[x >> 3] << (x & 7u)) & (x + 1u < width ? 0xC0u : 0x80u);
        out[x >> 1] = (uint8_t)(((pair >> 3 | pair >> 6) & 0x11u) * STP_PANEL_GREY4_ON);
    }
}

int stp_panel_window_all(const stp_panel_controller *c, const stp_panel_bus *bus)
{
    uint8_t cmd[3];
    int status;
    uint32_t unit = c->column_unit ? c->column_unit : 1u;
    uint32_t first = c->column_offset / unit;
    uint32_t last = first + (c->width + unit - 1u) / unit - 1u;
    cmd[0] = c->column_command;
    cmd[1] = (uint8_t)first;
    cmd[2] = (uint8_t)last;
    if ((status = bus->command(bus->ctx, cmd, 3)) != 0)
        return status;
    cmd[0] = c->row_command;
    cmd[1] = 0;
    cmd[2] = (uint8_t)(c->height - 1u);
    return bus->command(bus->ctx, cmd, 3);
}

int stp_panel_send_mono_rows(const stp_panel_controller *c, const stp_panel_bus *bus,
                             const uint8_t *pixels, size_t stride, uint32_t width,
                             uint32_t rows, uint8_t *scratch)
{
    uint32_t y;
    size_t n = stp_panel_row_bytes(c, width);
    for (y = 0; y < rows; y++) {
        int status;
        stp_panel_pack_mono_row(c, pixels + (size_t)y * stride, width, scratch);
        if ((status = bus->data(bus->ctx, scratch, n)) != 0)
            return status;
    }
    return 0;
}

/* Column k's byte gathers bit 7 - k of each row byte, row r into bit r:
 * each row byte shifted left once per column, its top bit shifted into
 * the column bytes from the top (after 8 rows, row 0 is in bit 0).  Eight
 * byte variables, no indexing: on an 8-bit CPU they stay in registers. */
#define STP_PACK_COLUMN(c, b) c = (uint8_t)((c >> 1) | (b & 0x80u)), b = (uint8_t)(b << 1)

void stp_panel_pack_block(const uint8_t *rows, size_t stride, uint8_t out[8])
{
    uint8_t c0 = 0, c1 = 0, c2 = 0, c3 = 0, c4 = 0, c5 = 0, c6 = 0, c7 = 0, any = 0;
    unsigned r;
    for (r = 0; r < 8u; r++)
        any = (uint8_t)(any | rows[(size_t)r * stride]);
    if (any) {
        for (r = 0; r < 8u; r++) {
            uint8_t b = rows[(size_t)r * stride];
            STP_PACK_COLUMN(c0, b);
            STP_PACK_COLUMN(c1, b);
            STP_PACK_COLUMN(c2, b);
            STP_PACK_COLUMN(c3, b);
            STP_PACK_COLUMN(c4, b);
            STP_PACK_COLUMN(c5, b);
            STP_PACK_COLUMN(c6, b);
            STP_PACK_COLUMN(c7, b);
        }
    }
    out[0] = c0;
    out[1] = c1;
    out[2] = c2;
    out[3] = c3;
    out[4] = c4;
    out[5] = c5;
    out[6] = c6;
    out[7] = c7;
}

void stp_panel_pack_page(const uint8_t *pixels, size_t stride, uint32_t width, uint8_t *out)
{
    uint32_t x0;
    for (x0 = 0; x0 < width; x0 += 8u) {
        uint8_t col[8];
        unsigned c, n = width - x0 < 8u ? (unsigned)(width - x0) : 8u;
        stp_panel_pack_block(pixels + (x0 >> 3), stride, col);
        for (c = 0; c < n; c++)
            out[x0 + c] = col[c];
    }
}

int stp_panel_send_page(const stp_panel_controller *c, const stp_panel_bus *bus, uint32_t page,
                        const uint8_t *columns, uint32_t width)
{
    int status;
    uint32_t col = c->column_offset;
    uint8_t cmd;
    /* one command per call: I2C controllers take "one command byte follows"
     * control bytes, and a command per call keeps that the bus's business */
    cmd = (uint8_t)(c->page_command | page);
    if ((status = bus->command(bus->ctx, &cmd, 1)) != 0)
        return status;
    cmd = (uint8_t)(c->column_low_command | (col & 15u));
    if ((status = bus->command(bus->ctx, &cmd, 1)) != 0)
        return status;
    cmd = (uint8_t)(c->column_high_command | (col >> 4));
    if ((status = bus->command(bus->ctx, &cmd, 1)) != 0)
        return status;
    return bus->data(bus->ctx, columns, width);
}

int stp_panel_send_mono_page(const stp_panel_controller *c, const stp_panel_bus *bus,
                             uint32_t page, const uint8_t *pixels, size_t stride,
                             uint32_t width, uint8_t *scratch)
{
    stp_panel_pack_page(pixels, stride, width, scratch);
    return stp_panel_send_page(c, bus, page, scratch, width);
}

int stp_panel_window_counters_all(const stp_panel_controller *c, const stp_panel_bus *bus)
{
    uint8_t cmd[5];
    int status;
    uint32_t unit = c->column_unit ? c->column_unit : 1u;
    uint32_t first = c->column_offset / unit;
    uint32_t last = first + (c->width + unit - 1u) / unit - 1u;
    uint32_t bottom = c->height - 1u;
    cmd[0] = c->column_command;
    cmd[1] = (uint8_t)first;
    cmd[2] = (uint8_t)last;
    if ((status = bus->command(bus->ctx, cmd, 3)) != 0)
        return status;
    cmd[0] = c->row_command;
    cmd[1] = 0;
    cmd[2] = 0;
    cmd[3] = (uint8_t)(bottom & 0xFFu);
    cmd[4] = (uint8_t)(bottom >> 8);
    if ((status = bus->command(bus->ctx, cmd, 5)) != 0)
        return status;
    cmd[0] = c->x_counter_command;
    cmd[1] = (uint8_t)first;
    if ((status = bus->command(bus->ctx, cmd, 2)) != 0)
        return status;
    cmd[0] = c->y_counter_command;
    cmd[1] = 0;
    cmd[2] = 0;
    if ((status = bus->command(bus->ctx, cmd, 3)) != 0)
        return status;
    cmd[0] = c->write_command;
    return bus->command(bus->ctx, cmd, 1);
}

size_t stp_panel_line_record_bytes(const stp_panel_controller *c)
{
    return 1u + stp_panel_row_bytes(c, c->width) + c->line_trailer;
}

uint8_t stp_panel_line_mode(const stp_panel_controller *c, int hold, int vcom)
{
    uint8_t mode = hold ? c->line_hold_mode : c->line_write_mode;
    return (uint8_t)(vcom ? mode | c->line_vcom_bit : mode);
}

static uint8_t reverse_bits(uint8_t v)
{
    uint8_t r = 0;
    unsigned i;
    for (i = 0; i < 8; i++)
        r = (uint8_t)(r | (((v >> i) & 1u) << (7u - i)));
    return r;
}

size_t stp_panel_line_record(const stp_panel_controller *c, uint32_t y, const uint8_t *mono,
                             uint8_t *out)
{
    size_t n = stp_panel_row_bytes(c, c->width), i;
    uint8_t address = (uint8_t)(c->line_first_address + y);
    out[0] = c->line_address_reversed ? reverse_bits(address) : address;
    stp_panel_pack_mono_row(c, mono, c->width, out + 1);
    for (i = 0; i < c->line_trailer; i++)
        out[1 + n + i] = 0;
    return 1u + n + c->line_trailer;
}
