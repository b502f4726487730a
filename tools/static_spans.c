/* SPDX-License-Identifier: MIT */
/* Host side: a static scene's picture as visible spans.  See static_spans.h. */
#include "static_spans.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct capture {
    uint8_t *picture;
    size_t row_bytes;
} capture;

static int capture_rows(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                        size_t stride)
{
    capture *c = port->user;
    uint32_t r;
    for (r = 0; r < rows; r++)
        memcpy(c->picture + (size_t)(y0 + r) * c->row_bytes, pixels + r * stride, c->row_bytes);
    return 0;
}

/* The display file played back through the host core in one whole-frame
 * band, format GREY8 or MONO1, into picture (height * row bytes). */
static int play(const stp_instr *df, uint32_t used, uint32_t width, uint32_t height, int levels,
                int fill_style, const stp_output *output, stp_pixel_format format,
                uint8_t *picture, char *err, size_t errlen)
{
    void *mem = malloc(stp_renderer_size());
    size_t row_bytes = format == STP_PIXEL_MONO1 ? (width + 7u) / 8u : width;
    uint8_t *band = malloc(row_bytes * height);
    uint16_t *zbuf = malloc((size_t)width * height * sizeof *zbuf);
    stp_sort_entry *sort = malloc((used + 1u) * sizeof *sort);
    stp_frame_memory fm;
    stp_port port;
    capture c;
    stp_renderer *r;
    int status = STP_ERR_MEMORY;
    if (mem && band && zbuf && sort &&
        (r = stp_playback_create(mem, stp_renderer_size(), df, used, width, height, levels,
                                 fill_style)) != 0) {
        memset(&fm, 0, sizeof fm);
        fm.band = band;
        fm.band_size = row_bytes * height;
        fm.band_rows = height;
        fm.zbuf = zbuf;
        fm.zbuf_count = (size_t)width * height;
        fm.sort = sort;
        fm.sort_count = used + 1u;
        memset(&port, 0, sizeof port);
        port.width = width;
        port.height = height;
        port.format = format;
        port.flush = capture_rows;
        c.picture = picture;
        c.row_bytes = row_bytes;
        port.user = &c;
        status = stp_renderer_render(r, &port, output, &fm);
    }
    free(mem);
    free(band);
    free(zbuf);
    free(sort);
    if (status != STP_OK)
        snprintf(err, errlen, "playing the display file back: %s", stp_status_text(status));
    return status == STP_OK ? 0 : -1;
}

/* Shade index of level v, added to the table when new. */
static int shade_of(stp_tool_spans *s, const stp_cell *cell, uint8_t v)
{
    int k, cy;
    uint32_t x;
    for (k = 0; k < s->shade_count; k++)
        if (s->levels[k] == v)
            return k;
    s->levels[k] = v;
    for (cy = 0; cy < s->cell_rows; cy++) {
        uint8_t byte = 0;
        for (x = 0; x < 8; x++)
            if (stp_cell_on(cell, x, (uint32_t)cy, v))
                byte = (uint8_t)(byte | (0x80u >> x));
        s->patterns[k * s->cell_rows + cy] = byte;
    }
    s->shade_count++;
    return k;
}

static int side_ok(int n)
{
    return n == 1 || n == 2 || n == 4 || n == 8;
}

int stp_tool_static_spans(const stp_instr *df, uint32_t used, uint32_t width, uint32_t height,
                          int levels, int fill_style, const stp_output *output,
                          stp_tool_spans *s, char *err, size_t errlen)
{
    const stp_cell *cell = output->cell;
    size_t mono_bytes = (width + 7u) / 8u, n = 0;
    uint8_t *grey = malloc((size_t)width * height), *mono = malloc(mono_bytes * height);
    uint8_t *again = malloc(mono_bytes * height);
    uint32_t x, y;
    int result = -1;
    memset(s, 0, sizeof *s);
    if (width < 1 || width > 256 || height < 1 || height > 32767) {
        snprintf(err, errlen, "--spans needs a picture 1..256 pixels wide and 1..32767 high (%lux%lu)",
                 (unsigned long)width, (unsigned long)height);
        goto done;
    }
    if (!cell || cell->mask || !side_ok(cell->width) || !side_ok(cell->height) ||
        output->diffusion) {
        snprintf(err, errlen, "--spans needs a halftone cell 1, 2, 4 or 8 pixels each way "
                              "(not error diffusion or blue noise)");
        goto done;
    }
    s->cell_rows = cell->height;
    /* every row can be a run per pixel: two bytes each at most */
    s->runs = malloc((size_t)width * height * 2u);
    if (!grey || !mono || !again || !s->runs) {
        snprintf(err, errlen, "out of memory");
        goto done;
    }
    if (play(df, used, width, height, levels, fill_style, output, STP_PIXEL_GREY8, grey, err,
             errlen) != 0 ||
        play(df, used, width, height, levels, fill_style, output, STP_PIXEL_MONO1, mono, err,
             errlen) != 0)
        goto done;
    for (y = 0; y < height; y++) {
        const uint8_t *row = grey + (size_t)y * width;
        for (x = 0; x < width; x++) {
            if (x + 1u < width && row[x + 1u] == row[x])
                continue;
            s->runs[n++] = (uint8_t)x;
            s->runs[n++] = (uint8_t)shade_of(s, cell, row[x]);
        }
    }
    s->run_bytes = n;
    {
        stp_spans sp;
        stp_spans_cursor cur;
        sp.width = (uint16_t)width;
        sp.height = (uint16_t)height;
        sp.cell_rows = (uint8_t)s->cell_rows;
        sp.shade_count = (uint8_t)s->shade_count;
        sp.patterns = s->patterns;
        sp.runs = s->runs;
        sp.run_bytes = (uint32_t)s->run_bytes;
        stp_spans_start(&sp, &cur);
        if (s->shade_count > 255 ||
            stp_spans_draw(&sp, &cur, again, mono_bytes, height) != STP_OK ||
            memcmp(again, mono, mono_bytes * height) != 0) {
            snprintf(err, errlen, "the spans do not give the core's picture (a shade's pixels "
                                  "are not its level through the cell)");
            goto done;
        }
    }
    result = 0;
done:
    free(grey);
    free(mono);
    free(again);
    if (result != 0) {
        free(s->runs);
        s->runs = 0;
    }
    return result;
}
