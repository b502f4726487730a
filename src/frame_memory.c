/* SPDX-License-Identifier: MIT */
/* Defaults for stp_renderer_render: the output and the frame memory carved from one
 * caller buffer (render.h, stp_output_default and stp_frame_memory_*), and
 * the bytes of a pixel row (port.h, stp_row_bytes).  This module owns the
 * layout of the caller's memory; the rasteriser (raster.c) and the ray
 * tracer use it, and it uses neither (no import circle). */
#include "align_private.h"
#include "frame_memory_private.h"
#include "stipple/render.h"

/* The bytes of one row of width pixels of format fmt (port.h). */
size_t stp_row_bytes(stp_pixel_format fmt, uint32_t width)
{
    switch (fmt) {
    case STP_PIXEL_MONO1: return ((size_t)width + 7u) / 8u;
    case STP_PIXEL_GREY8:
    case STP_PIXEL_STYLE8: return (size_t)width;
    case STP_PIXEL_RGB888: return (size_t)width * 3u;
    case STP_PIXEL_MONO1_PAGES: return (size_t)width; /* one page of 8 rows */
    default: return 0;
    }
}

size_t stp_band_bytes(stp_pixel_format fmt, uint32_t width, uint32_t rows)
{
    size_t stride = stp_row_bytes(fmt, width), count = (size_t)rows;
    if (fmt == STP_PIXEL_MONO1_PAGES)
        count = ((size_t)rows + 7u) / 8u;
    if (count != 0 && stride > SIZE_MAX / count)
        return 0;
    return stride * count;
}

/* C99 has no alignof: a type's alignment is its offset after a char. */
struct sort_alignment {
    char c;
    stp_sort_entry e;
};
#define SORT_ALIGN offsetof(struct sort_alignment, e)

int stp_output_default(stp_output *output)
{
    if (output == 0)
        return STP_ERR_ARG;
#if STP_WITH_ZBUFFER
    output->hidden = STP_HIDDEN_ZBUFFER;
#elif STP_WITH_PAINTER
    output->hidden = STP_HIDDEN_PAINTER;
#else
    output->hidden = STP_HIDDEN_NONE;
#endif
    output->cell = 0;
    output->gamma = 0;
    output->styles = 0;
    output->background = 0;
    output->background_colour = 0;
    output->diffusion = 0;
    output->edge_aa = 0;
    return STP_OK;
}

/* Bytes of one band row's Z-buffer entries (0 without the Z buffer). */
static size_t depth_row_bytes(const stp_port *port, stp_hidden hidden)
{
    return hidden == STP_HIDDEN_ZBUFFER ? (size_t)port->width * sizeof(uint16_t) : 0u;
}

/* Bytes of a band of rows rows: the pixels (stp_band_bytes) and, for the Z
 * buffer, its entries; 0 for an unknown format or a size that does not
 * fit size_t. */
static size_t band_bytes(const stp_port *port, stp_pixel_format drawn, stp_hidden hidden, uint32_t rows)
{
    size_t pixels = stp_band_bytes(drawn, port->width, rows), depth = depth_row_bytes(port, hidden);
    if ((pixels == 0 && rows > 0) || stp_row_bytes(drawn, port->width) == 0)
        return 0;
    if (rows > 0 && depth > SIZE_MAX / rows)
        return 0;
    depth *= (size_t)rows;
    if (depth > SIZE_MAX - pixels)
        return 0;
    return pixels + depth;
}

/* The most rows of a band of drawn format whose pixels and Z entries fit
 * in size bytes, at most the port's height; for a STP_PIXEL_MONO1_PAGES
 * port whole pages, or the whole frame (stp_renderer_render's band_rows).
 * 0: none. */
static size_t band_rows_fitting(const stp_port *port, stp_pixel_format drawn, stp_hidden hidden, size_t size)
{
    size_t depth = depth_row_bytes(port, hidden), rows;
    if (drawn == STP_PIXEL_MONO1_PAGES) {
        size_t page = (size_t)port->width + 8u * depth; /* no overflow: width < 2^15 */
        rows = 8u * (size / page);
        if (rows < port->height && band_bytes(port, drawn, hidden, port->height) <= size)
            rows = (size_t)port->height; /* a frame below one page */
    } else {
        rows = size / (stp_row_bytes(drawn, port->width) + depth);
    }
    if (rows > port->height)
        rows = (size_t)port->height;
    if (port->format == STP_PIXEL_MONO1_PAGES && rows < port->height)
        rows -= rows % 8u; /* a page port's band drawn grey: whole pages too */
    return rows;
}

/* The format a band for port is drawn in: a 1-bit port's is grey when the
 * output diffuses errors or anti-aliases edges (render.h, stp_output). */
static stp_pixel_format drawn_format(const stp_port *port, const stp_output *output)
{
    int one_bit = port->format == STP_PIXEL_MONO1 || port->format == STP_PIXEL_MONO1_PAGES;
    return one_bit && (output->diffusion || output->edge_aa) ? STP_PIXEL_GREY8 : port->format;
}

size_t stp_frame_memory_bytes(const stp_port *port, stp_hidden hidden, uint32_t band_rows,
                              uint32_t polygons)
{
    size_t sort = 0, bytes;
    if (port == 0 || (bytes = band_bytes(port, port->format, hidden, band_rows)) == 0)
        return 0;
    if (hidden == STP_HIDDEN_PAINTER) {
        size_t count = (size_t)polygons; /* a 16-bit size_t may not hold it */
        if (count != polygons || count > SIZE_MAX / sizeof(stp_sort_entry))
            return 0;
        sort = count * sizeof(stp_sort_entry);
    }
    if (sort > SIZE_MAX - bytes - (SORT_ALIGN - 1u))
        return 0;
    return bytes + sort + (SORT_ALIGN - 1u);
}

int stp_frame_memory_split(stp_frame_memory *memory, const stp_renderer *r, const stp_port *port,
                           const stp_output *output, void *buffer, size_t size)
{
    stp_output defaults;
    uint8_t *p = (uint8_t *)buffer;
    size_t sort_count = 0, sort_bytes, rows;
    stp_pixel_format drawn;
    if (memory == 0 || port == 0 || buffer == 0)
        return STP_ERR_ARG;
    if (output == 0) {
        (void)stp_output_default(&defaults);
        output = &defaults;
    }
    drawn = drawn_format(port, output);
    if (band_bytes(port, drawn, output->hidden, 1) == 0 || stp_row_bytes(port->format, port->width) == 0)
        return STP_ERR_ARG;
    if (output->hidden == STP_HIDDEN_PAINTER) {
        if (r == 0)
            return STP_ERR_ARG;
        uint32_t polygons = stp_renderer_polygon_count(r);
        sort_count = (size_t)polygons;
        if (sort_count != polygons) /* a 16-bit size_t */
            return STP_ERR_MEMORY;
    }
    memory->band = 0;
    memory->band_size = 0;
    memory->band_rows = 0;
    memory->zbuf = 0;
    memory->zbuf_count = 0;
    memory->sort = 0;
    memory->sort_count = 0;
    memory->setup = 0;
    memory->setup_count = 0;
    /* the sort entries want 32-bit alignment, the Z buffer 16 */
    while (!stp_is_aligned(p, SORT_ALIGN) && size > 0) {
        p++;
        size--;
    }
    sort_bytes = sort_count * sizeof(stp_sort_entry);
    if (sort_count > SIZE_MAX / sizeof(stp_sort_entry) || sort_bytes > size)
        return STP_ERR_MEMORY;
    rows = band_rows_fitting(port, drawn, output->hidden, size - sort_bytes);
    if (rows < 1)
        return STP_ERR_MEMORY;
    if (sort_count > 0) {
        memory->sort = (stp_sort_entry *)(void *)p;
        memory->sort_count = sort_count;
        p += sort_bytes;
    }
    if (output->hidden == STP_HIDDEN_ZBUFFER) {
        memory->zbuf = (uint16_t *)(void *)p;
        memory->zbuf_count = (size_t)port->width * rows;
        p += memory->zbuf_count * sizeof(uint16_t);
    }
    memory->band = p;
    memory->band_rows = (uint32_t)rows;
    memory->band_size = stp_band_bytes(drawn, port->width, (uint32_t)rows);
    return STP_OK;
}
