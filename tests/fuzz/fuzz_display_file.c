/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer target: the display file and its interpreter, through the public
 * API of include/stipple/render.h (it offers no way to load raw
 * instructions, so the instructions are whatever the API enters).
 *
 * The input is a program: a header picks the device size and the display
 * file's capacity, then each following byte picks a call (view, lights,
 * material, levels, colour, transparency, shadow maps, segments, move/line,
 * flat and smooth polygons, render) whose arguments come from the next
 * bytes.  stp_fix values are drawn from
 * small integers, fractions, any 32-bit pattern and a table of extremes
 * (STP_FIX_MAX, STP_FIX_MIN, INT32_MIN, 32767, 2^-16, ...).  Every buffer
 * lent to the core (renderer, display file, band, Z buffer, sort array,
 * gamma and style tables, polygon vertices, normals and shades, shadow
 * maps) is its own heap block of exactly the size the API asks for, so ASan
 * sees any access beyond it; a shadow map's block is freed as soon as the
 * API says it is no longer used (replaced, removed, or a new view).
 *
 * Checked beyond the sanitizers:
 *  - a setting call that fails (view, lighting, levels, transparency, shadow
 *    maps, segments) leaves the renderer object unchanged, byte for byte;
 *  - segments follow a model of the API's rules: the status of create,
 *    close, delete and visibility; the display file's use (each segment's
 *    share is removed on delete, used <= capacity, failed calls enter
 *    nothing); stp_renderer_polygon_count equals the polygons entered in visible
 *    segments; stp_renderer_last_shade is -1 or in [0, 1];
 *  - stp_renderer_render returns the status the arguments call for (one fault at a
 *    time: a bad format, band height or hidden method, a short buffer, a
 *    port that refuses a band), and the port sees bands top to bottom,
 *    whole rows, the packed stride, nothing after a refusal;
 *  - the picture does not depend on the band height: each render is done
 *    again in one band as tall as the frame and must match pixel for pixel
 *    (render.h: "the result is the same pixel for pixel whatever the band
 *    height");
 *  - the formats agree (without transparency): MONO1 is the GREY8 picture
 *    through the halftone cell, RGB888 without colour is grey (R = G = B =
 *    GREY8), STYLE8 without a style table holds indices 1..levels whose
 *    levels GREY8 shows (port.h; 0 only for a background of 0);
 *  - every MONO1 render is drawn again in the panel page layout
 *    (STP_PIXEL_MONO1_PAGES), in bands of whole pages and in one band, and
 *    each, unpacked to rows here, is the MONO1 picture pixel for pixel; a
 *    page band's bits below its last row are 0 (port.h); a band height that
 *    is neither whole pages nor the frame's is refused (STP_ERR_ARG).
 */
#include <string.h>

#include "fuzz_common.h"
#include "stipple/stipple.h"

#define ONE STP_FIX_ONE

/* Limits that keep one input fast: calls per input, renders per input, and
 * the bands of one render. */
#define FZ_MAX_CALLS 200
#define FZ_MAX_RENDERS 6
#define FZ_MAX_BANDS 256u

/* ------------------------------------------------------------ values */

static const stp_fix extremes[] = {
    0,
    1,
    -1,
    ONE,
    -ONE,
    ONE / 2,
    ONE >> 8,
    STP_FIX_MAX,
    STP_FIX_MIN,
    INT32_MIN,
    STP_FIX_MAX - 1,
    STP_FIX_MIN + 1,
    32767 * ONE,
    -32767 * ONE,
    180 * ONE,
    90 * ONE,
    179 * ONE + ONE / 2,
    (stp_fix)1 << 24,
    -((stp_fix)1 << 24),
    (stp_fix)1 << 30,
    -((stp_fix)1 << 30),
    10 * ONE,
    100 * ONE,
    3,
};

static stp_fix fz_fix(fz_reader *in)
{
    const size_t count = sizeof extremes / sizeof extremes[0];
    uint8_t mode = fz_u8(in);

    switch (mode % 8) {
    case 0: return (stp_fix)(int8_t)fz_u8(in) * ONE;
    case 1: return (stp_fix)(int8_t)fz_u8(in) * (ONE / 64);
    case 2: return (stp_fix)(int16_t)fz_u16(in) * (ONE / 256);
    case 3: return (stp_fix)(int32_t)fz_u32(in);
    case 4: return extremes[fz_u8(in) % count];
    case 5: return (stp_fix)(int16_t)fz_u16(in);
    case 6: {
        /* next to an extreme, wrapping as int32 would */
        stp_fix e = extremes[fz_u8(in) % count];
        int32_t d = (int8_t)fz_u8(in);
        return (stp_fix)(int32_t)((uint32_t)e + (uint32_t)d);
    }
    default: return (stp_fix)(int16_t)fz_u16(in) * (ONE / 4);
    }
}

static stp_vec3 fz_vec(fz_reader *in)
{
    stp_vec3 v;
    v.x = fz_fix(in);
    v.y = fz_fix(in);
    v.z = fz_fix(in);
    return v;
}

/* A point near a given one: offsets of up to +-2 in steps of 1/64. */
static stp_vec3 fz_near(fz_reader *in, stp_vec3 c)
{
    stp_vec3 v;
    v.x = stp_fix_add(c.x, (stp_fix)(int8_t)fz_u8(in) * (ONE / 64));
    v.y = stp_fix_add(c.y, (stp_fix)(int8_t)fz_u8(in) * (ONE / 64));
    v.z = stp_fix_add(c.z, (stp_fix)(int8_t)fz_u8(in) * (ONE / 64));
    return v;
}

/* ------------------------------------------------------------ model */

/* What the API's rules say about segments (render.h), mirrored: slots are
 * taken lowest first, as the renderer does, only so FULL is predictable. */
typedef struct seg_model {
    int used, open, visible, id;
    uint32_t instrs;   /* display-file entries the segment holds */
    uint32_t polygons; /* polygons entered in it */
} seg_model;

typedef struct state {
    stp_renderer *r;
    stp_instr *df;
    uint32_t capacity, width, height;
    int levels;
    int open; /* slot of the open segment, -1 none */
    seg_model seg[STP_MAX_SEGMENTS];
    stp_vec3 target; /* the view's "at": polygons built near it are seen */
    int renders;
    int colour_seen; /* colour shading was on at some time: colour polygons */
    int transparency_seen; /* polygons may be transparent */
    int light_count; /* lights of the current lighting */
    uint16_t *maps[STP_MAX_LIGHTS]; /* shadow maps lent to the renderer */
    uint8_t *snapshot; /* the renderer object before a setting call */
    size_t mem_size;
} state;

/* A refused setting must leave the renderer as it was: the renderer object
 * is compared byte for byte with its copy from before the call. */
static void snap(state *st)
{
    memcpy(st->snapshot, (const void *)st->r, st->mem_size);
}

static void same_if_failed(const state *st, int status, const char *call)
{
    size_t i;
    if (status == STP_OK)
        return;
    for (i = 0; i < st->mem_size; i++)
        FZ_CHECK(st->snapshot[i] == ((const uint8_t *)st->r)[i],
                 "%s failed (%d) but changed the renderer (byte %zu of %zu)", call, status, i,
                 st->mem_size);
}

static void drop_map(state *st, int light)
{
    free(st->maps[light]);
    st->maps[light] = NULL;
}

static int find_seg(const state *st, int id)
{
    int i;
    for (i = 0; i < STP_MAX_SEGMENTS; i++)
        if (st->seg[i].used && st->seg[i].id == id)
            return i;
    return -1;
}

static void check_counts(const state *st)
{
    uint32_t used = 0, polygons = 0;
    int i;
    for (i = 0; i < STP_MAX_SEGMENTS; i++) {
        if (!st->seg[i].used)
            continue;
        used += st->seg[i].instrs;
        if (st->seg[i].visible)
            polygons += st->seg[i].polygons;
    }
    FZ_CHECK(stp_renderer_display_file_used(st->r) == used, "display file holds %u, segments %u",
             (unsigned)stp_renderer_display_file_used(st->r), (unsigned)used);
    FZ_CHECK(used <= st->capacity, "used %u over capacity %u", (unsigned)used,
             (unsigned)st->capacity);
    FZ_CHECK(stp_renderer_polygon_count(st->r) == polygons, "stp_renderer_polygon_count %u, model %u",
             (unsigned)stp_renderer_polygon_count(st->r), (unsigned)polygons);
}

/* Implicit segments (render.h): a drawing call with no open segment opens
 * one with the first free id of -1, -2, ...; creating a segment, closing it
 * or changing the view or lighting ends it. */
static int free_slot(const state *st)
{
    int slot;
    for (slot = 0; slot < STP_MAX_SEGMENTS && st->seg[slot].used; slot++)
        ;
    return slot < STP_MAX_SEGMENTS ? slot : -1;
}

static void end_implicit(state *st)
{
    if (st->open >= 0 && st->seg[st->open].id < 0) {
        st->seg[st->open].open = 0;
        st->open = -1;
    }
}

/* Before a drawing call that passed its argument checks: STP_OK (a segment
 * is open, or the implicit one was opened in the model) or STP_ERR_FULL. */
static int open_implicit(state *st)
{
    int slot, id = -1;
    if (st->open >= 0)
        return STP_OK;
    if ((slot = free_slot(st)) < 0)
        return STP_ERR_FULL;
    while (find_seg(st, id) >= 0)
        id--;
    memset(&st->seg[slot], 0, sizeof st->seg[slot]);
    st->seg[slot].used = st->seg[slot].open = st->seg[slot].visible = 1;
    st->seg[slot].id = id;
    st->open = slot;
    return STP_OK;
}

/* Book what a drawing call entered into the open segment. */
static void account(state *st, uint32_t before, int status, int polygon)
{
    uint32_t after = stp_renderer_display_file_used(st->r);
    if (status != STP_OK) {
        FZ_CHECK(after == before, "a failed call (%d) entered %u entries", status,
                 (unsigned)(after - before));
        return;
    }
    FZ_CHECK(after >= before, "display file shrank while drawing");
    if (st->open >= 0) {
        st->seg[st->open].instrs += after - before;
        if (polygon && after > before)
            st->seg[st->open].polygons++;
    } else {
        FZ_CHECK(after == before, "drawing with no open segment entered something");
    }
}

/* ------------------------------------------------------------ the port */

/* Bytes of rows rows of format fmt, width pixels wide: rows of stride
 * bytes, or for STP_PIXEL_MONO1_PAGES (rows + 7) / 8 pages of width bytes
 * (port.h); 0 for an unknown format. */
static size_t layout_bytes(stp_pixel_format fmt, uint32_t width, uint32_t rows)
{
    size_t stride = stp_row_bytes(fmt, width);
    if (fmt == STP_PIXEL_MONO1_PAGES)
        return stride * (((size_t)rows + 7u) / 8u);
    return stride * rows;
}

typedef struct capture {
    stp_port port;
    uint8_t *frame; /* height rows of stride bytes (MONO1_PAGES: pages) */
    size_t stride;
    uint32_t band_rows, next_y, flushes, fail_at;
    int failed;
} capture;

static int capture_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                         size_t stride)
{
    capture *c = (capture *)port->user;
    uint32_t expect_rows = port->height - c->next_y < c->band_rows ? port->height - c->next_y
                                                                    : c->band_rows;
    FZ_CHECK(!c->failed, "flush called after the port refused a band");
    FZ_CHECK(y0 == c->next_y, "band at row %u, expected %u", (unsigned)y0, (unsigned)c->next_y);
    FZ_CHECK(rows == expect_rows, "band of %u rows, expected %u", (unsigned)rows,
             (unsigned)expect_rows);
    FZ_CHECK(stride == c->stride, "stride %zu, expected %zu", stride, c->stride);
    FZ_CHECK(pixels != NULL, "no pixels");
    if (c->flushes++ == c->fail_at) {
        c->failed = 1;
        return -1;
    }
    if (port->format == STP_PIXEL_MONO1_PAGES) {
        size_t bytes = layout_bytes(port->format, port->width, rows), x;
        FZ_CHECK(y0 % 8u == 0, "a page band starts at row %u, within a page", (unsigned)y0);
        /* port.h: the bits of rows past the band's last row are 0 */
        for (x = 0; rows % 8u != 0 && x < stride; x++)
            FZ_CHECK((pixels[bytes - stride + x] >> (rows % 8u)) == 0,
                     "page band at row %u (%u rows): column %zu has bits below its last row",
                     (unsigned)y0, (unsigned)rows, x);
        memcpy(c->frame + (size_t)(y0 / 8u) * stride, pixels, bytes);
    } else {
        memcpy(c->frame + (size_t)y0 * stride, pixels, (size_t)rows * stride);
    }
    c->next_y += rows;
    return 0;
}

typedef enum fault {
    FAULT_NONE,
    FAULT_FORMAT,
    FAULT_BAND_ROWS,
    FAULT_HIDDEN,
    FAULT_BAND_SIZE,
    FAULT_ZBUF,
    FAULT_SORT,
    FAULT_PORT,
    FAULT_COUNT,
    /* not drawn from the input: a MONO1_PAGES render whose band_rows (as
     * given) is neither a multiple of 8 nor the height */
    FAULT_PAGE_BAND
} fault;

typedef struct render_args {
    stp_pixel_format format;
    stp_hidden hidden;
    uint32_t band_rows;
    stp_output out;
    stp_cell cell;
    uint8_t *gamma;
    stp_style_table styles;
    uint8_t *style_codes;
    stp_fix *background_colour;
} render_args;

static void *xmalloc(size_t n)
{
    void *p = malloc(n == 0 ? 1 : n);
    FZ_CHECK(p != NULL, "out of memory (%zu bytes)", n);
    return p;
}

/* One stp_renderer_render into a fresh frame; returns the status, *frame_out gets the
 * frame (caller frees) when the status is STP_OK. */
static int render_once(state *st, const render_args *a, fault f, uint32_t fail_at,
                       uint8_t **frame_out)
{
    stp_frame_memory mem;
    capture cap;
    size_t stride = stp_row_bytes(a->format, st->width);
    size_t frame_bytes = layout_bytes(a->format, st->width, st->height);
    uint32_t band_rows = a->band_rows;
    size_t band_bytes = layout_bytes(a->format, st->width, band_rows);
    uint32_t polygons = stp_renderer_polygon_count(st->r);
    int expect = STP_OK, status;

    memset(&cap, 0, sizeof cap);
    memset(&mem, 0, sizeof mem);
    cap.port.width = st->width;
    cap.port.height = st->height;
    /* an unknown format: the first value past the last one */
    cap.port.format = f == FAULT_FORMAT ? (stp_pixel_format)(STP_PIXEL_MONO1_PAGES + 1) : a->format;
    cap.port.flush = capture_flush;
    cap.port.user = &cap;
    cap.stride = stride;
    cap.band_rows = band_rows;
    cap.fail_at = f == FAULT_PORT ? fail_at : UINT32_MAX;
    cap.frame = (uint8_t *)xmalloc(frame_bytes);
    memset(cap.frame, 0xEE, frame_bytes);

    if (f == FAULT_BAND_ROWS)
        mem.band_rows = (fail_at & 1) ? 0 : st->height + 1;
    else
        mem.band_rows = band_rows;
    mem.band_size = band_bytes - (f == FAULT_BAND_SIZE ? 1 : 0);
    mem.band = (uint8_t *)xmalloc(mem.band_size);
    mem.zbuf_count = (size_t)st->width * band_rows - (f == FAULT_ZBUF ? 1 : 0);
    mem.zbuf = (uint16_t *)xmalloc(mem.zbuf_count * sizeof *mem.zbuf);
    mem.sort_count = f == FAULT_SORT ? polygons - 1 : polygons;
    mem.sort = (stp_sort_entry *)xmalloc(mem.sort_count * sizeof *mem.sort);

    {
        stp_output out = a->out;
        out.hidden = f == FAULT_HIDDEN ? (stp_hidden)(3 + (fail_at & 7)) : a->hidden;
        switch (f) {
        case FAULT_FORMAT:
        case FAULT_BAND_ROWS:
        case FAULT_PAGE_BAND:
        case FAULT_HIDDEN: expect = STP_ERR_ARG; break;
        case FAULT_BAND_SIZE: expect = STP_ERR_MEMORY; break;
        /* a short Z buffer or sort array matters only to its own method */
        case FAULT_ZBUF: expect = a->hidden == STP_HIDDEN_ZBUFFER ? STP_ERR_MEMORY : STP_OK; break;
        case FAULT_SORT: expect = a->hidden == STP_HIDDEN_PAINTER ? STP_ERR_MEMORY : STP_OK; break;
        case FAULT_PORT: {
            uint32_t bands = (st->height + band_rows - 1) / band_rows;
            expect = fail_at < bands ? STP_ERR_PORT : STP_OK;
            break;
        }
        default: break;
        }
        /* port.h: STYLE8 without a table holds indices 1..255 only; the
         * check comes after the argument and buffer-size checks */
        if ((expect == STP_OK || expect == STP_ERR_MEMORY || expect == STP_ERR_PORT) &&
            f != FAULT_BAND_SIZE &&
            cap.port.format == STP_PIXEL_STYLE8 && out.styles == NULL && st->levels > 255)
            expect = STP_ERR_ARG;
        status = stp_renderer_render(st->r, &cap.port, &out, &mem);
    }
    FZ_CHECK(status == expect, "stp_renderer_render returned %d (%s), expected %d (fault %d)", status,
             stp_status_text(status), expect, (int)f);
    if (status == STP_OK)
        FZ_CHECK(cap.next_y == st->height, "frame ended at row %u of %u", (unsigned)cap.next_y,
                 (unsigned)st->height);
    else if (f != FAULT_PORT)
        FZ_CHECK(cap.flushes == 0, "a refused render flushed %u bands", (unsigned)cap.flushes);
    free(mem.band);
    free(mem.zbuf);
    free(mem.sort);
    if (status == STP_OK && frame_out != NULL) {
        *frame_out = cap.frame;
    } else {
        free(cap.frame);
    }
    return status;
}

static int pixel_differs(const state *st, stp_pixel_format fmt, int grey, const uint8_t *a,
                         const uint8_t *b, uint32_t *x_out, uint32_t *y_out)
{
    size_t stride = stp_row_bytes(fmt, st->width);
    uint32_t x, y;
    for (y = 0; y < st->height; y++) {
        const uint8_t *ra = a + (size_t)y * stride, *rb = b + (size_t)y * stride;
        for (x = 0; x < st->width; x++) {
            int differ;
            switch (fmt) {
            case STP_PIXEL_MONO1:
                differ = ((ra[x >> 3] ^ rb[x >> 3]) >> (7u - (x & 7u))) & 1u;
                break;
            case STP_PIXEL_RGB888:
                differ = memcmp(ra + 3 * x, rb + 3 * x, 3) != 0;
                FZ_CHECK(!grey || (ra[3 * x] == ra[3 * x + 1] && ra[3 * x] == ra[3 * x + 2]),
                         "RGB888 pixel (%u, %u) not grey without colour", (unsigned)x,
                         (unsigned)y);
                break;
            default: differ = ra[x] != rb[x]; break;
            }
            if (differ) {
                *x_out = x;
                *y_out = y;
                return 1;
            }
        }
    }
    return 0;
}

static void pick_cell(fz_reader *in, render_args *a)
{
    switch (fz_u8(in) % 7) {
    case 0: a->out.cell = NULL; return;
    case 1:
        FZ_CHECK(stp_cell_bayer_spaced(&a->cell, 2 << fz_range(in, 0, 2),
                                       (stp_spacing)fz_range(in, 0, 2)) == 0,
                 "Bayer cell refused");
        break;
    case 2: stp_cell_seed2x2(&a->cell); break;
    case 3: stp_cell_pattern2x2(&a->cell); break;
    case 4: {
        uint8_t t[STP_CELL_MAX * STP_CELL_MAX];
        int w = fz_range(in, 1, STP_CELL_MAX), h = fz_range(in, 1, STP_CELL_MAX), i;
        for (i = 0; i < w * h; i++)
            t[i] = fz_u8(in);
        FZ_CHECK(stp_cell_user(&a->cell, w, h, t) == 0, "user cell refused");
        break;
    }
    default: FZ_CHECK(stp_cell_bayer(&a->cell, 4) == 0, "Bayer 4x4 refused"); break;
    }
    a->out.cell = &a->cell;
}

/* The 8-bit level GREY8 shows for a style index (render.h, stp_output). */
static int level_of(const state *st, const render_args *a, int index)
{
    if (index < 1)
        index = 1;
    if (index > st->levels)
        index = st->levels;
    if (a->out.gamma)
        return a->out.gamma[index - 1];
    return ((index - 1) * 255 + (st->levels - 1) / 2) / (st->levels - 1);
}

/* The same picture in GREY8 decides the other formats: MONO1 is GREY8
 * through the halftone cell (stp_cell_on), RGB888 without colour is GREY8
 * in each channel, STYLE8 without a table holds the index 1..levels whose
 * level GREY8 shows (0: the background, when it is 0).  Not with
 * transparency: its blend reads back the device's own pixels, which differ
 * (1-bit on MONO1) by design. */
static void cross_check(state *st, const render_args *a, const uint8_t *frame)
{
    render_args g = *a;
    uint8_t *grey = NULL;
    stp_cell bayer;
    const stp_cell *cell = a->out.cell;
    size_t stride = stp_row_bytes(a->format, st->width);
    uint32_t x, y;

    if (a->format == STP_PIXEL_GREY8 || st->transparency_seen ||
        (a->format == STP_PIXEL_RGB888 && (st->colour_seen || a->background_colour)) ||
        (a->format == STP_PIXEL_STYLE8 && a->out.styles))
        return;
    g.format = STP_PIXEL_GREY8;
    g.band_rows = st->height;
    if (g.out.cell == &a->cell)
        g.out.cell = &g.cell;
    FZ_CHECK(render_once(st, &g, FAULT_NONE, 0, &grey) == STP_OK, "GREY8 render failed");
    if (cell == NULL) {
        FZ_CHECK(stp_cell_bayer(&bayer, 4) == 0, "Bayer 4x4 refused");
        cell = &bayer;
    }
    for (y = 0; y < st->height; y++) {
        for (x = 0; x < st->width; x++) {
            const uint8_t *p = frame + (size_t)y * stride;
            uint8_t v = grey[(size_t)y * st->width + x];
            switch (a->format) {
            case STP_PIXEL_MONO1: {
                int bit = (p[x >> 3] >> (7u - (x & 7u))) & 1;
                FZ_CHECK(bit == (stp_cell_on(cell, x, y, v) != 0),
                         "MONO1 pixel (%u, %u) is %d, GREY8 level %u gives %d", (unsigned)x,
                         (unsigned)y, bit, v, !bit);
                break;
            }
            case STP_PIXEL_RGB888:
                FZ_CHECK(p[3 * x] == v, "RGB888 pixel (%u, %u) is %u, GREY8 %u", (unsigned)x,
                         (unsigned)y, p[3 * x], v);
                break;
            default:
                FZ_CHECK(p[x] <= st->levels, "STYLE8 pixel (%u, %u) holds index %u of %d levels",
                         (unsigned)x, (unsigned)y, p[x], st->levels);
                FZ_CHECK(v == level_of(st, a, p[x]),
                         "STYLE8 pixel (%u, %u) holds index %u (level %d) where GREY8 shows %u "
                         "(%d levels)",
                         (unsigned)x, (unsigned)y, p[x], level_of(st, a, p[x]), v, st->levels);
                break;
            }
        }
    }
    free(grey);
}

/* A MONO1_PAGES frame (pages of width bytes, bit y mod 8 of byte
 * (y / 8) width + x) unpacked to MONO1 rows (pixel 0 in bit 7), the padding
 * bits 0: a fresh block the caller frees. */
static uint8_t *pages_to_rows(const state *st, const uint8_t *pages)
{
    size_t stride = stp_row_bytes(STP_PIXEL_MONO1, st->width);
    uint8_t *rows = (uint8_t *)xmalloc(stride * st->height);
    uint32_t x, y;
    memset(rows, 0, stride * st->height);
    for (y = 0; y < st->height; y++)
        for (x = 0; x < st->width; x++)
            if ((pages[(size_t)(y / 8u) * st->width + x] >> (y % 8u)) & 1u)
                rows[(size_t)y * stride + x / 8u] |= (uint8_t)(0x80u >> (x % 8u));
    return rows;
}

/* The MONO1 render of a (its frame: mono) drawn again in the page layout:
 * refused in bands that are not whole pages, then in bands of whole pages
 * (a's band height rounded up to one) and in one band; each unpacked must
 * be mono pixel for pixel. */
static void pages_check(state *st, const render_args *a, const uint8_t *mono)
{
    render_args p = *a;
    uint8_t *frames[2] = {NULL, NULL};
    uint32_t heights[2], x = 0, y = 0;
    int k;
    if (p.out.cell == &a->cell)
        p.out.cell = &p.cell;
    if (p.out.styles == &a->styles)
        p.out.styles = &p.styles;
    p.format = STP_PIXEL_MONO1_PAGES;
    if (a->band_rows % 8u != 0 && a->band_rows < st->height)
        (void)render_once(st, &p, FAULT_PAGE_BAND, 0, NULL); /* checks the STP_ERR_ARG */
    heights[0] = (a->band_rows + 7u) / 8u * 8u;
    heights[0] = heights[0] < st->height ? heights[0] : st->height;
    heights[1] = st->height;
    for (k = 0; k < 2; k++) {
        uint8_t *rows;
        p.band_rows = heights[k];
        FZ_CHECK(render_once(st, &p, FAULT_NONE, 0, &frames[k]) == STP_OK,
                 "MONO1_PAGES render in bands of %u rows failed", (unsigned)heights[k]);
        rows = pages_to_rows(st, frames[k]);
        FZ_CHECK(!pixel_differs(st, STP_PIXEL_MONO1, 0, rows, mono, &x, &y),
                 "MONO1_PAGES pixel (%u, %u) (bands of %u rows) differs from MONO1 (bands of %u "
                 "rows; hidden %d, %ux%u)",
                 (unsigned)x, (unsigned)y, (unsigned)heights[k], (unsigned)a->band_rows,
                 (int)a->hidden, (unsigned)st->width, (unsigned)st->height);
        free(rows);
        free(frames[k]);
    }
}

/* Render with arguments from the input, check it, and unless a fault was
 * injected, render again in one band and compare, against GREY8, and a
 * MONO1 render against the page layout's. */
static void op_render(state *st, fz_reader *in, int final_hidden)
{
    render_args a;
    fault f = FAULT_NONE;
    uint32_t fail_at = 0, bands;
    uint8_t *banded = NULL, *whole = NULL;
    int status;

    memset(&a, 0, sizeof a);
    a.format = (stp_pixel_format)fz_range(in, 0, 3);
    a.hidden = final_hidden >= 0 ? (stp_hidden)final_hidden : (stp_hidden)fz_range(in, 0, 2);
    a.band_rows = (uint32_t)fz_range(in, 1, 256);
    if (a.band_rows > st->height)
        a.band_rows = st->height;
    bands = (st->height + a.band_rows - 1) / a.band_rows;
    if (bands > FZ_MAX_BANDS)
        a.band_rows = (st->height + FZ_MAX_BANDS - 1) / FZ_MAX_BANDS;
    pick_cell(in, &a);
    a.out.hidden = a.hidden;
    if (fz_u8(in) & 1) {
        int i;
        a.gamma = (uint8_t *)xmalloc((size_t)st->levels);
        if (fz_u8(in) & 1) {
            stp_fix gamma = fz_fix(in), k = fz_fix(in);
            FZ_CHECK(stp_gamma_table(a.gamma, st->levels, gamma, k) == 0,
                     "gamma table refused %d levels", st->levels);
        } else {
            for (i = 0; i < st->levels; i++)
                a.gamma[i] = fz_u8(in);
        }
        a.out.gamma = a.gamma;
    }
    if (fz_u8(in) & 1) {
        int i;
        a.styles.levels = fz_range(in, 1, 256);
        a.style_codes = (uint8_t *)xmalloc((size_t)a.styles.levels);
        for (i = 0; i < a.styles.levels; i++)
            a.style_codes[i] = fz_u8(in);
        a.styles.codes = a.style_codes;
        a.out.styles = &a.styles;
    }
    a.out.background = fz_fix(in);
    if (fz_u8(in) % 4 == 0) {
        int c;
        a.background_colour = (stp_fix *)xmalloc(3 * sizeof *a.background_colour);
        for (c = 0; c < 3; c++)
            a.background_colour[c] = fz_fix(in);
        a.out.background_colour = a.background_colour;
    }
    if (final_hidden < 0 && fz_u8(in) % 4 == 0) {
        f = (fault)fz_range(in, 1, FAULT_COUNT - 1);
        fail_at = fz_u8(in);
        if (f == FAULT_SORT && stp_renderer_polygon_count(st->r) == 0)
            f = FAULT_NONE; /* no array can be short of zero entries */
    }

    status = render_once(st, &a, f, fail_at, &banded);
    if (status == STP_OK) {
        render_args whole_args = a;
        uint32_t x = 0, y = 0;
        whole_args.band_rows = st->height;
        if (whole_args.out.cell == &a.cell)
            whole_args.out.cell = &whole_args.cell;
        if (whole_args.out.styles == &a.styles)
            whole_args.out.styles = &whole_args.styles;
        FZ_CHECK(render_once(st, &whole_args, FAULT_NONE, 0, &whole) == STP_OK,
                 "one-band render failed");
        FZ_CHECK(!pixel_differs(st, a.format, !st->colour_seen && a.background_colour == NULL,
                                banded, whole, &x, &y),
                 "pixel (%u, %u) differs between bands of %u rows and one band of %u "
                 "(format %d, hidden %d, %ux%u)",
                 (unsigned)x, (unsigned)y, (unsigned)a.band_rows, (unsigned)st->height,
                 (int)a.format, (int)a.hidden, (unsigned)st->width, (unsigned)st->height);
        cross_check(st, &a, banded);
        if (a.format == STP_PIXEL_MONO1)
            pages_check(st, &a, banded);
    }
    free(banded);
    free(whole);
    free(a.gamma);
    free(a.style_codes);
    free(a.background_colour);
    st->renders++;
}

/* ------------------------------------------------------------ calls */

static void op_view(state *st, fz_reader *in)
{
    stp_view v;
    int status, bad_projection;
    v.from = fz_vec(in);
    v.at = fz_u8(in) & 1 ? fz_vec(in) : fz_near(in, v.from);
    v.up = fz_vec(in);
    v.fov_degrees = fz_u8(in) & 1 ? fz_fix(in) : fz_range(in, 1, 179) * ONE;
    v.window_half = fz_fix(in);
    v.hither = fz_fix(in);
    v.projection = (stp_projection)fz_range(in, 0, 2);
    bad_projection = v.projection != STP_PERSPECTIVE && v.projection != STP_PARALLEL;
    snap(st);
    status = stp_renderer_set_view(st->r, &v);
    same_if_failed(st, status, "stp_renderer_set_view");
    FZ_CHECK(status == STP_OK || status == STP_ERR_VIEW || (bad_projection && status == STP_ERR_ARG),
             "stp_renderer_set_view returned %d", status);
    FZ_CHECK(!(bad_projection && status == STP_OK), "an unknown projection was accepted");
    if (status == STP_OK) {
        int j;
        end_implicit(st);
        st->target = v.at;
        /* "stp_renderer_set_view removes every map" */
        for (j = 0; j < STP_MAX_LIGHTS; j++)
            drop_map(st, j);
    }
}

static void op_lighting(state *st, fz_reader *in)
{
    stp_lighting l;
    int i, status;
    memset(&l, 0, sizeof l);
    l.brightness = fz_fix(in);
    l.background = fz_fix(in);
    l.attenuation_c = fz_fix(in);
    l.count = fz_range(in, -1, STP_MAX_LIGHTS + 1);
    for (i = 0; i < STP_MAX_LIGHTS; i++) {
        int c;
        l.lights[i].position = fz_vec(in);
        l.lights[i].power = fz_fix(in);
        for (c = 0; c < 3; c++)
            l.lights[i].colour[c] = fz_u8(in) & 1 ? fz_fix(in) : ONE;
    }
    snap(st);
    status = stp_renderer_set_lighting(st->r, &l);
    same_if_failed(st, status, "stp_renderer_set_lighting");
    if (l.count < 0 || l.count > STP_MAX_LIGHTS)
        FZ_CHECK(status == STP_ERR_ARG, "light count %d gave %d", l.count, status);
    else
        FZ_CHECK(status == STP_OK, "light count %d gave %d", l.count, status);
    if (status == STP_OK) {
        st->light_count = l.count;
        end_implicit(st);
    }
}

/* stp_renderer_set_shadow_map: one fault at most (light, size, short buffer); the
 * view's own values may be refused (STP_ERR_VIEW).  The old buffer of a
 * light is freed once a new map replaces it, so ASan sees a stale use. */
static void op_shadow_map(state *st, fz_reader *in)
{
    stp_shadow_view view;
    uint32_t w = (uint32_t)fz_range(in, 1, 48), h = (uint32_t)fz_range(in, 1, 48);
    int light = fz_range(in, 0, STP_MAX_LIGHTS - 1), expect = STP_OK, status;
    size_t count;
    uint16_t *depth;
    uint8_t how = fz_u8(in);

    switch (fz_u8(in) % 16) {
    case 0: light = fz_u8(in) & 1 ? -1 : STP_MAX_LIGHTS; expect = STP_ERR_ARG; break;
    case 1: w = fz_u8(in) & 1 ? 0 : 32768; expect = STP_ERR_ARG; break;
    case 2: h = 0; expect = STP_ERR_ARG; break;
    default: break;
    }
    if (light >= 0 && light < STP_MAX_LIGHTS && light >= st->light_count)
        expect = STP_ERR_ARG;
    count = (size_t)w * h;
    if (expect == STP_OK && (how & 8)) {
        count--;
        expect = STP_ERR_MEMORY;
    }
    depth = (uint16_t *)xmalloc((count > 0 ? count : 1) * sizeof *depth);
    view.target = how & 2 ? fz_vec(in) : fz_near(in, st->target);
    view.fov_degrees = how & 4 ? fz_fix(in) : fz_range(in, 1, 179) * ONE;
    view.near = how & 16 ? fz_fix(in) : (stp_fix)fz_u8(in) * (ONE / 16);
    snap(st);
    status = stp_renderer_set_shadow_map(st->r, light, depth, count, w, h, how & 1 ? &view : NULL);
    same_if_failed(st, status, "stp_renderer_set_shadow_map");
    if (expect == STP_OK)
        FZ_CHECK(status == STP_OK || status == STP_ERR_VIEW,
                 "stp_renderer_set_shadow_map(light %d, %ux%u) returned %d", light, (unsigned)w,
                 (unsigned)h, status);
    else
        FZ_CHECK(status == expect, "stp_renderer_set_shadow_map(light %d, %ux%u, count %zu) returned %d, "
                 "expected %d", light, (unsigned)w, (unsigned)h, count, status, expect);
    if (status == STP_OK) {
        size_t i;
        for (i = 0; i < count; i++)
            FZ_CHECK(depth[i] == 0, "a new shadow map is not cleared");
        drop_map(st, light);
        st->maps[light] = depth;
    } else {
        free(depth);
    }
}

static void op_remove_shadow_map(state *st, fz_reader *in)
{
    int light = fz_range(in, -1, STP_MAX_LIGHTS);
    int status;
    snap(st);
    status = stp_renderer_remove_shadow_map(st->r, light);
    same_if_failed(st, status, "stp_renderer_remove_shadow_map");
    int valid = light >= 0 && light < STP_MAX_LIGHTS;
    FZ_CHECK(status == (valid ? STP_OK : STP_ERR_ARG), "stp_renderer_remove_shadow_map(%d) returned %d",
             light, status);
    if (valid)
        drop_map(st, light);
}

static int fz_seg_id(fz_reader *in)
{
    uint8_t b = fz_u8(in);
    if (b < 240)
        return b % 24;
    switch (b % 4) {
    case 0: return -1;
    case 1: return 32767;
    case 2: return 32768;
    default: return INT32_MIN + (int)fz_u8(in);
    }
}

static void op_segment_create(state *st, fz_reader *in)
{
    int id = fz_seg_id(in), expect, status, slot = free_slot(st);
    if (id < 0 || id > 32767)
        expect = STP_ERR_ARG;
    else if ((st->open >= 0 && st->seg[st->open].id >= 0) || find_seg(st, id) >= 0)
        expect = STP_ERR_SEGMENT;
    else if (slot < 0)
        expect = STP_ERR_FULL;
    else
        expect = STP_OK;
    snap(st);
    status = stp_segment_create(st->r, id);
    same_if_failed(st, status, "stp_segment_create");
    FZ_CHECK(status == expect, "stp_segment_create(%d) returned %d, expected %d", id, status,
             expect);
    if (status == STP_OK) {
        end_implicit(st);
        memset(&st->seg[slot], 0, sizeof st->seg[slot]);
        st->seg[slot].used = st->seg[slot].open = st->seg[slot].visible = 1;
        st->seg[slot].id = id;
        st->open = slot;
    }
}

static void op_segment_close(state *st)
{
    int status;
    snap(st);
    status = stp_segment_close(st->r);
    same_if_failed(st, status, "stp_segment_close");
    FZ_CHECK(status == (st->open >= 0 ? STP_OK : STP_ERR_SEGMENT), "stp_segment_close gave %d",
             status);
    if (st->open >= 0) {
        st->seg[st->open].open = 0;
        st->open = -1;
    }
}

static void op_segment_delete(state *st, fz_reader *in)
{
    int id = fz_seg_id(in), s = find_seg(st, id);
    int expect = s < 0 || st->seg[s].open ? STP_ERR_SEGMENT : STP_OK;
    int status;
    snap(st);
    status = stp_segment_delete(st->r, id);
    same_if_failed(st, status, "stp_segment_delete");
    FZ_CHECK(status == expect, "stp_segment_delete(%d) returned %d, expected %d", id, status,
             expect);
    if (status == STP_OK)
        memset(&st->seg[s], 0, sizeof st->seg[s]);
}

static void op_segment_visibility(state *st, fz_reader *in)
{
    int id = fz_seg_id(in), s = find_seg(st, id);
    int visible = (int)(int8_t)fz_u8(in) % 3;
    int status;
    snap(st);
    status = stp_segment_visibility(st->r, id, visible);
    same_if_failed(st, status, "stp_segment_visibility");
    FZ_CHECK(status == (s < 0 ? STP_ERR_SEGMENT : STP_OK),
             "stp_segment_visibility(%d) returned %d", id, status);
    if (s >= 0)
        st->seg[s].visible = visible != 0;
}

/* stp_renderer_polygon (flat), stp_renderer_polygon_smooth (vertex normals) or
 * stp_renderer_polygon_vertex_shades (shades given), by `smooth` 0, 1, 2. */
static void op_polygon(state *st, fz_reader *in, int smooth)
{
    uint8_t kind = fz_u8(in);
    int n, i, status, expect = STP_OK;
    stp_vec3 *v, *normals = NULL;
    stp_fix *shades = NULL;
    uint32_t before = stp_renderer_display_file_used(st->r);
    stp_fix shade;

    if (kind < 200)
        n = 3 + kind % 6;
    else if (kind < 250)
        n = fz_range(in, 3, STP_MAX_POLYGON_VERTICES);
    else
        n = fz_range(in, -2, STP_MAX_POLYGON_VERTICES + 2);
    v = (stp_vec3 *)xmalloc(sizeof *v * (size_t)(n > 0 ? n : 1));
    {
        /* vertices near the view's target, or anywhere, or a mix, with
         * repeats now and then */
        uint8_t how = fz_u8(in);
        stp_vec3 centre = how & 4 ? fz_near(in, st->target) : st->target;
        for (i = 0; i < n; i++) {
            uint8_t b = how & 3;
            if (b == 2)
                b = fz_u8(in) & 1;
            if (b == 3 && i > 0 && (fz_u8(in) & 7) == 0)
                v[i] = v[fz_range(in, 0, i - 1)];
            else if (b == 1)
                v[i] = fz_vec(in);
            else
                v[i] = fz_near(in, centre);
        }
    }
    if (smooth == 1) {
        /* any normal, none (zero: the polygon's), or one along an axis */
        normals = (stp_vec3 *)xmalloc(sizeof *normals * (size_t)(n > 0 ? n : 1));
        for (i = 0; i < n; i++) {
            uint8_t b = fz_u8(in);
            if (b < 128) {
                normals[i] = fz_vec(in);
            } else {
                normals[i].x = normals[i].y = normals[i].z = 0;
                if (b < 224)
                    *(&normals[i].x + b % 3) = (b & 8) ? -ONE : ONE;
            }
        }
    } else if (smooth == 2) {
        shades = (stp_fix *)xmalloc(sizeof *shades * (size_t)(n > 0 ? n : 1));
        for (i = 0; i < n; i++)
            shades[i] = fz_u8(in) & 1 ? fz_fix(in) : (stp_fix)fz_u8(in) * (ONE / 255);
    }
    if (n < 0)
        expect = STP_ERR_ARG;
    else if (n < 3)
        expect = STP_ERR_DEGENERATE;
    else if (n > STP_MAX_POLYGON_VERTICES)
        expect = STP_ERR_TOO_MANY_VERTICES;
    else
        expect = open_implicit(st);
    if (smooth == 1)
        status = stp_renderer_polygon_smooth(st->r, v, normals, n);
    else if (smooth == 2)
        status = stp_renderer_polygon_vertex_shades(st->r, v, shades, n);
    else
        status = stp_renderer_polygon(st->r, v, n);
    free(v);
    free(normals);
    free(shades);
    if (expect != STP_OK)
        FZ_CHECK(status == expect, "stp_renderer_polygon(n = %d) returned %d, expected %d", n, status,
                 expect);
    else
        /* STP_ERR_RANGE: a vertex beyond the view range (fz_fix reaches
         * +-32768 and the eye moves); account() checks nothing was entered */
        FZ_CHECK(status == STP_OK || status == STP_ERR_DEGENERATE || status == STP_ERR_FULL ||
                     status == STP_ERR_RANGE,
                 "stp_renderer_polygon(n = %d) returned %d", n, status);
    account(st, before, status, 1);
    if (status == STP_OK && stp_renderer_display_file_used(st->r) > before) {
        shade = stp_renderer_last_shade(st->r);
        FZ_CHECK(shade >= 0 && shade <= ONE, "stp_renderer_last_shade %d outside [0, 1]", (int)shade);
    }
}

static void op_pen(state *st, fz_reader *in, int line)
{
    uint32_t before = stp_renderer_display_file_used(st->r);
    stp_vec3 p = fz_u8(in) & 1 ? fz_vec(in) : fz_near(in, st->target);
    int expect = open_implicit(st);
    int status = line ? stp_renderer_line(st->r, p) : stp_renderer_move(st->r, p);
    if (expect != STP_OK)
        FZ_CHECK(status == expect, "pen call with no free segment slot gave %d", status);
    else
        FZ_CHECK(status == STP_OK || (line && status == STP_ERR_FULL) || status == STP_ERR_RANGE,
                 "pen call gave %d", status);
    account(st, before, status, 0);
}

static void op_transparency(state *st, fz_reader *in)
{
    stp_fix t_min, t_max, absorption, thickness;
    int power, status, in_range;
    if (fz_u8(in) & 1) {
        t_min = fz_fix(in);
        t_max = fz_fix(in);
        power = fz_range(in, -1, 6);
        absorption = fz_fix(in);
        thickness = fz_fix(in);
    } else {
        t_min = (stp_fix)fz_u8(in) * (ONE / 255);
        t_max = (stp_fix)fz_u8(in) * (ONE / 255);
        power = fz_range(in, 1, 4);
        absorption = (stp_fix)fz_u8(in) * (ONE / 16);
        thickness = (stp_fix)fz_u8(in) * (ONE / 64);
    }
    in_range = t_min >= 0 && t_min <= ONE && t_max >= 0 && t_max <= ONE && power >= 1 &&
               power <= 4 && absorption >= 0 && thickness >= 0;
    snap(st);
    status = stp_renderer_set_transparency(st->r, t_min, t_max, power, absorption, thickness);
    same_if_failed(st, status, "stp_renderer_set_transparency");
    if (status == STP_OK && (t_min != 0 || t_max != 0))
        st->transparency_seen = 1;
    FZ_CHECK(status == (in_range ? STP_OK : STP_ERR_ARG),
             "stp_renderer_set_transparency(%d, %d, %d, %d, %d) returned %d", (int)t_min, (int)t_max,
             power, (int)absorption, (int)thickness, status);
}

static void op_call(state *st, fz_reader *in)
{
    switch (fz_u8(in) % 26) {
    case 0: op_view(st, in); break;
    case 1: {
        stp_vec3 p = fz_vec(in);
        stp_fix bright = fz_fix(in), background = fz_fix(in);
        int status, ok = bright >= 0 && background >= 0 && background <= ONE;
        snap(st);
        status = stp_renderer_set_light(st->r, p, bright, background);
        same_if_failed(st, status, "stp_renderer_set_light");
        FZ_CHECK(status == (ok ? STP_OK : STP_ERR_ARG), "stp_renderer_set_light returned %d", status);
        if (status == STP_OK) {
            st->light_count = 1;
            end_implicit(st);
        }
        break;
    }
    case 2: op_lighting(st, in); break;
    case 3: {
        stp_material m;
        stp_material_default(&m);
        m.reflectivity = fz_fix(in);
        m.refraction = fz_fix(in);
        m.gloss = fz_fix(in);
        m.specular = fz_fix(in);
        int c, ok, status;
        if (fz_u8(in) & 1) {
            for (c = 0; c < 3; c++)
                m.colour[c] = fz_fix(in);
        }
        ok = m.reflectivity >= 0 && m.reflectivity <= ONE && m.refraction >= 0 && m.gloss >= 0 &&
             m.specular >= 0;
        for (c = 0; c < 3; c++)
            ok = ok && m.colour[c] >= 0 && m.colour[c] <= ONE;
        snap(st);
        status = stp_renderer_set_object_shade(st->r, &m);
        same_if_failed(st, status, "stp_renderer_set_object_shade");
        FZ_CHECK(status == (ok ? STP_OK : STP_ERR_ARG), "stp_renderer_set_object_shade returned %d", status);
        break;
    }
    case 4:
        FZ_CHECK(stp_renderer_set_shading(st->r, (int8_t)fz_u8(in) % 3) == STP_OK, "stp_renderer_set_shading failed");
        break;
    case 5: {
        int index = fz_range(in, -2, 300), status;
        snap(st);
        status = stp_renderer_set_fill_style(st->r, index);
        same_if_failed(st, status, "stp_renderer_set_fill_style");
        FZ_CHECK(status == (index >= 1 && index <= st->levels ? STP_OK : STP_ERR_ARG),
                 "stp_renderer_set_fill_style(%d) returned %d", index, status);
        break;
    }
    case 6: {
        int levels = fz_u8(in) & 1 ? fz_range(in, 2, 256) : fz_range(in, -1, 300);
        int status;
        snap(st);
        status = stp_renderer_set_levels(st->r, levels);
        same_if_failed(st, status, "stp_renderer_set_levels");
        FZ_CHECK(status == (levels >= 2 && levels <= 256 ? STP_OK : STP_ERR_ARG),
                 "stp_renderer_set_levels(%d) returned %d", levels, status);
        if (status == STP_OK)
            st->levels = levels;
        break;
    }
    case 7:
        FZ_CHECK(stp_renderer_set_backface_removal(st->r, (int8_t)fz_u8(in) % 3) == STP_OK,
                 "stp_renderer_set_backface_removal failed");
        break;
    case 8:
    case 9: op_segment_create(st, in); break;
    case 10: op_segment_close(st); break;
    case 11: op_segment_delete(st, in); break;
    case 12: op_segment_visibility(st, in); break;
    case 13: op_pen(st, in, 0); break;
    case 14: op_pen(st, in, 1); break;
    case 15: op_polygon(st, in, 1); break;
    case 16: op_polygon(st, in, 2); break;
    case 17: {
        int on = (int8_t)fz_u8(in) % 3;
        FZ_CHECK(stp_renderer_set_colour(st->r, on) == STP_OK, "stp_renderer_set_colour(%d) failed", on);
        st->colour_seen |= on != 0;
        break;
    }
    case 18: op_transparency(st, in); break;
    case 20: op_shadow_map(st, in); break;
    case 21: op_remove_shadow_map(st, in); break;
    case 19:
        if (st->renders < FZ_MAX_RENDERS) {
            op_render(st, in, -1);
            break;
        }
        /* fall through */
    default: op_polygon(st, in, 0); break;
    }
    check_counts(st);
}

/* ------------------------------------------------------------ the target */

static uint32_t fz_side(fz_reader *in)
{
    uint8_t b = fz_u8(in);
    if (b < 250)
        return 1u + b % 96u;
    return b == 250 ? 32767u : 1u + fz_u16(in) % 32767u;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_reader in;
    state st;
    void *mem;
    size_t mem_size = stp_renderer_size();
    int calls, hidden;

    fz_init(&in, data, size);
    memset(&st, 0, sizeof st);
    st.width = fz_side(&in);
    st.height = fz_side(&in);
    /* keep a frame below 128 K pixels: the long side only with a short one */
    while ((uint64_t)st.width * st.height > 131072u) {
        if (st.width > st.height)
            st.width = st.width / 2u;
        else
            st.height = st.height / 2u;
    }
    st.capacity = 1u + fz_u16(&in) % 2048u;
    st.levels = 16;
    st.light_count = 1;
    st.open = -1;
    st.target.x = st.target.y = st.target.z = 0;

    mem = xmalloc(mem_size);
    st.mem_size = mem_size;
    st.snapshot = (uint8_t *)xmalloc(mem_size);
    st.df = (stp_instr *)xmalloc(st.capacity * sizeof *st.df);
    FZ_CHECK(stp_renderer_create(mem, mem_size - 1, st.df, st.capacity, st.width, st.height) ==
                 NULL,
             "renderer created in too little memory");
    FZ_CHECK(stp_renderer_create(mem, mem_size, st.df, st.capacity, 0, st.height) == NULL,
             "renderer created with width 0");
    FZ_CHECK(stp_renderer_create(mem, mem_size, st.df, st.capacity, st.width, 32768) == NULL,
             "renderer created with height 32768");
    st.r = stp_renderer_create(mem, mem_size, st.df, st.capacity, st.width, st.height);
    FZ_CHECK(st.r != NULL, "stp_renderer_create failed for %ux%u", (unsigned)st.width,
             (unsigned)st.height);

    for (calls = 0; calls < FZ_MAX_CALLS && !fz_done(&in); calls++)
        op_call(&st, &in);

    /* The whole display file under every hidden-surface method. */
    for (hidden = 0; hidden < 3; hidden++)
        op_render(&st, &in, hidden);

    for (calls = 0; calls < STP_MAX_LIGHTS; calls++)
        drop_map(&st, calls);
    free(st.df);
    free(st.snapshot);
    free(mem);
    return 0;
}
