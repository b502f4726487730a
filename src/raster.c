/* SPDX-License-Identifier: MIT */
/* The display-file interpreter: hidden surfaces, scan conversion and band
 * output.  See the fill rule in include/stipple/render.h. */
#include "renderer_state.h"
#include "shadow_private.h"
#include "output_private.h"
#include "frame_memory_private.h"
#include "dither_private.h"
#include "edge_aa_private.h"
#include "diffuse_private.h"
/* (64-bit hosts: the triangle walk without its shortcut for a triangle
 * off the band: replay skips those itself where there are several bands,
 * replay_banded_triangle, and with one there are none; peer bench 128x64
 * 460 instructions a frame fewer, 560 spinning) */
#define STP_TRI_BAND_SHORTCUT (!STP_LEAN_CODE && !STP_WIDE_ARITH)
/* with the guard band a triangle's crossings may lie left of the picture
 * (project_private.h): its spans clamped there too */
#define STP_TRI_CLAMP_LEFT STP_GUARD_BAND
#include "edge_walk_private.h"
#include "div64_private.h"
#include "sort_private.h" /* the painter's sort */
#include "depth_private.h" /* the depth stage: keys, planes, depth-tested spans */

#define SUB STP_SUBPIXEL_BITS
#define HALF_PIXEL (1 << (SUB - 1))


/* Where depth_q12 is three 32 x 32-bit products from 16-bit halves
 * (32-bit targets without wide arithmetic) it keeps its last results: 64
 * (512 bytes of the frame on the stack) hold a mesh's vertex until the
 * next ring of triangles comes back to it (16: 30 K more instructions a
 * Cortex-M0+ torus frame). */
#if !STP_WIDE_ARITH && UINTPTR_MAX > 0xFFFFu
#define KEY_CACHE 64
#else
#define KEY_CACHE 0
#endif

/* Everything one frame's interpretation needs, built once per stp_renderer_render. */
/* A style as the interpreter carries it: an index (0..levels) or, with
 * STP_COLOUR_FLAG, a colour; 32 bits wide because the flag is bit 24. */
typedef int32_t paint;

#if KEY_CACHE > 0
typedef struct key_mapping {
    int32_t key, q12;
} key_mapping;
#endif

/* The fields a triangle reads come first: ARMv6-M loads a word at an
 * offset below 128 bytes in one instruction, farther ones in three.
 * FRAME_WORD_LAYOUT (32- and 64-bit targets): the pattern bytes at offset
 * 0 (a span's byte one load at the frame plus its cell row, no offset to
 * add) and the width kept (FRAME_WIDTH: one load, not two); on a 16-bit
 * target (AVR: its loads reach 63 bytes past a pointer) the fields they
 * would move cost code (ATmega2560 tetra-s1 +630 bytes). */
#define FRAME_WORD_LAYOUT (UINTPTR_MAX > 0xFFFFu)
typedef struct frame {
#if FRAME_WORD_LAYOUT
    uint8_t patterns[STP_CELL_MAX];
#endif
    stp_renderer *r;
    uint8_t *band;
    uint16_t *zbuf;
    size_t stride;            /* bytes between band rows, or pages (MONO1_PAGES) */
#if FRAME_WORD_LAYOUT
    uint32_t width;           /* r->width (FRAME_WIDTH) */
#endif
    stp_band_rows rows; /* current band */
    /* the band's layout: rows (0, 0), or STP_PIXEL_MONO1_PAGES (3, 1):
     * row y's line starts (y - y0) >> line_shift strides in, and is
     * written at bit page_one << (y mod 8) (page_bit_of) */
    uint8_t line_shift, page_one;
    stp_polygon_setup *setup; /* the caller's per-polygon depth setups, or NULL */
    depth_keys keys; /* the visible polygons' depth keys (depth_private.h) */
    /* MONO1 spans from pattern bytes: a threshold cell whose width divides
     * 8 (mono_fill); cell_mask its height - 1 when a power of two, else 0;
     * patterns[] the byte of each cell row for style pattern_style (-1:
     * none yet) */
    int mono_fill;
    int pattern_port; /* mono_fill on a MONO1 port (not drawn grey): spans may come from patterns[];
                         PATTERN_PLAIN when no shadow records are gathered either */
    uint32_t cell_mask;
#if STP_WIDE_ARITH
    /* pattern_of_row's cell row y mod height as ((y cell_mod mod 2^32)
     * height) / 2^32, cell_mod = ceil(2^32 / height) mod 2^32 (0 for
     * height 1), exact for y and height below 2^16 (Lemire, Kaser and
     * Kurz's fastmod: a 32-bit factor for 16-bit operands); rows < 2^15 */
    uint32_t cell_mod, cell_rows;
#endif
    paint pattern_style;
    const stp_cell *cell;
    const stp_port *port;
    const stp_output *out;
#if STP_WITH_SHADOWS
    stp_shadow_poly *shadow; /* the polygon being drawn's shadow records;
                                NULL when no light has a map */
#endif
#if !FRAME_WORD_LAYOUT
    uint8_t patterns[STP_CELL_MAX];
#endif
    int second_pass;          /* the Z buffer's second pass draws something:
                                 a transparent polygon or a line (lines are
                                 drawn again over the opaque polygons) */
    /* pixels any visible polygon can cover (x_min > x_max: none) */
    uint32_t x_min, x_max, y_min, y_max;
#if STP_WIDE_ARITH
    int scan_y; /* 0: the Z buffer's scan leaves y out too (scan_y_wanted) */
#define FRAME_SCAN_Y(fr) ((fr)->scan_y)
#else
#define FRAME_SCAN_Y(fr) 1
#endif
#if STP_PATTERN_CACHE > 0
    /* the pattern rows of recent styles (cells up to 4 rows high), slot
     * style mod STP_PATTERN_CACHE: a depth-ordered frame alternates styles
     * polygon by polygon; -1: empty */
    paint cached_style[STP_PATTERN_CACHE];
    uint8_t cached_rows[STP_PATTERN_CACHE][4]; /* the byte of each cell row */
#endif
#if KEY_CACHE > 0
    /* depth_q12's recent results, slot by the key's low bits: a mesh's
     * vertex comes again in the next triangles; q12 0: empty */
    key_mapping cached[KEY_CACHE];
#endif
#if STP_WITH_EDGE_AA
    stp_edge_aa aa; /* edge anti-aliasing (edge_aa.c); aa.out NULL: off */
#endif
    stp_cell default_cell;
} frame;

#if FRAME_WORD_LAYOUT
#define FRAME_WIDTH(fr) ((fr)->width)
#else
#define FRAME_WIDTH(fr) ((fr)->r->width)
#endif


/* The line of band row y: the row itself, or (MONO1_PAGES) the first
 * byte of its page, written at page_bit_of(fr, y). */
static uint8_t *band_row(const frame *fr, uint32_t y)
{
    return fr->band + (size_t)((y - fr->rows.y0) >> (STP_WITH_PAGES ? fr->line_shift : 0u)) * fr->stride;
}

/* The page bit of row y (stp_halftone_fill_bits): 0 for rows; bands
 * start on page boundaries (y0 a multiple of 8). */
static uint8_t page_bit_of(const frame *fr, uint32_t y)
{
    return STP_WITH_PAGES ? (uint8_t)(fr->page_one << (y & 7u)) : 0u;
}

/* 8-bit drive value of a style index (gamma table or linear); index is a
 * plain style here (0..levels), so it fits an int. */
static uint8_t level_of(const frame *fr, paint index)
{
    return stp_output_level(fr->out, fr->r->levels, (int)index);
}

/* indices entered under more levels than are now set show as the top
 * style (0 stays 0: "nothing drawn") */
static uint8_t style_code(const frame *fr, paint index)
{
    return stp_output_style_code(fr->out, fr->r->levels, (int)index);
}

#if STP_PATTERN_CACHE > 0
/* Make style, kept in slot, the current pattern style: four byte copies
 * (compilers merge them). */
STP_HOT_INLINE void style_from_slot(frame *fr, paint style, uint32_t slot)
{
    fr->patterns[0] = fr->cached_rows[slot][0];
    fr->patterns[1] = fr->cached_rows[slot][1];
    fr->patterns[2] = fr->cached_rows[slot][2];
    fr->patterns[3] = fr->cached_rows[slot][3];
    fr->pattern_style = style;
}
#endif

#if STP_PATTERN_KEEP
/* Slot's pattern rows, made for the cell level `level`, kept in the
 * renderer (stp_pattern_keep) for the frames after. */
static void patterns_keep(frame *fr, uint32_t slot, uint8_t level)
{
    stp_pattern_keep *k = &fr->r->kept_patterns;
    uint32_t cy;
    k->style[slot] = fr->cached_style[slot];
    k->level[slot] = level;
    for (cy = 0; cy < 4; cy++)
        k->rows[slot][cy] = fr->cached_rows[slot][cy];
}

/* Whether the kept rows were made for cell (one of at most 4 rows, its
 * width dividing 8: at most STP_PATTERN_KEEP_TABLE thresholds), its
 * thresholds compared; if not, cell made the kept one, with no styles. */
static int patterns_kept_cell(stp_pattern_keep *k, const stp_cell *cell)
{
    const uint8_t *t = stp_cell_table(cell);
    uint32_t i, n = (uint32_t)cell->width * cell->height, same;
    same = k->width == cell->width && k->height == cell->height && k->kind == cell->kind;
    for (i = 0; same && i < n; i++)
        same = k->table[i] == t[i];
    if (same)
        return 1;
    k->kind = cell->kind;
    k->width = cell->width;
    k->height = cell->height;
    for (i = 0; i < n; i++)
        k->table[i] = t[i];
    for (i = 0; i < STP_PATTERN_CACHE; i++)
        k->style[i] = -1;
    return 0;
}
#endif

#if STP_PATTERN_CACHE > 0
/* The frame's pattern rows of recent styles (use_style): empty, or on
 * 64-bit hosts those the renderer kept from the frames before for this
 * frame's cell whose styles still map to the cell level they were made
 * for (a torus frame at 128x64 makes 13 styles: 4 000 instructions). */
static void patterns_start(frame *fr)
{
    uint32_t i;
#if STP_PATTERN_KEEP
    stp_pattern_keep *k = &fr->r->kept_patterns;
    if (fr->mono_fill && fr->cell->height <= 4 && patterns_kept_cell(k, fr->cell)) {
        for (i = 0; i < STP_PATTERN_CACHE; i++) {
            paint style = k->style[i];
            fr->cached_style[i] = style >= 0 && level_of(fr, style) == k->level[i] ? style : -1;
            fr->cached_rows[i][0] = k->rows[i][0];
            fr->cached_rows[i][1] = k->rows[i][1];
            fr->cached_rows[i][2] = k->rows[i][2];
            fr->cached_rows[i][3] = k->rows[i][3];
        }
        return;
    }
#endif
    for (i = 0; i < STP_PATTERN_CACHE; i++)
        fr->cached_style[i] = -1;
}
#endif

/* Make style the one put_span fills MONO1 spans of from pattern bytes:
 * one byte per cell row, built once for a run of polygons of that style
 * rather than per span. */
static void use_style(frame *fr, paint style)
{
    uint32_t cy;
    uint8_t level;
    if (!fr->mono_fill || style == fr->pattern_style)
        return;
#if STP_PATTERN_CACHE > 0
    if (fr->cell->height <= 4) {
        uint32_t slot = (uint32_t)style & (STP_PATTERN_CACHE - 1);
        if (fr->cached_style[slot] != style) {
            level = level_of(fr, style);
            for (cy = 0; cy < 4; cy++)
                fr->cached_rows[slot][cy] = cy < fr->cell->height ? stp_halftone_pattern_byte(fr->cell, cy, level) : 0;
            fr->cached_style[slot] = style;
#if STP_PATTERN_KEEP
            patterns_keep(fr, slot, level); /* for the frames after */
#endif
        }
        style_from_slot(fr, style, slot);
        return;
    }
#endif
    level = level_of(fr, style);
    for (cy = 0; cy < fr->cell->height; cy++)
        fr->patterns[cy] = stp_halftone_pattern_byte(fr->cell, cy, level);
    fr->pattern_style = style;
}

/* What a STP_OP_SHADE paints with: its colour on an RGB888 device (rgb,
 * fr's port's format, tested once a frame by the callers) when it has
 * one, else its style index. */
static paint paint_of(int rgb, const stp_instr *in)
{
    if (rgb && (in->z & STP_COLOUR_FLAG))
        return in->z;
    return in->x;
}

/* Paint pixels x1..x2 of band row `row` (absolute y) in a style. */
static void put_span(const frame *fr, uint32_t y, uint32_t x1, uint32_t x2, paint style)
{
    uint8_t *row = band_row(fr, y);
    uint32_t x;
    switch (fr->port->format) {
    case STP_PIXEL_MONO1:
    case STP_PIXEL_MONO1_PAGES:
        if (style == fr->pattern_style) {
            uint32_t cy = fr->cell_mask ? (y & fr->cell_mask) : y % fr->cell->height;
            stp_halftone_fill_bits(row, page_bit_of(fr, y), (unsigned)x1, (unsigned)x2, fr->patterns[cy]);
        } else {
            stp_halftone_fillin_line(row, page_bit_of(fr, y), x1, x2, y, fr->cell, level_of(fr, style));
        }
        break;
    case STP_PIXEL_GREY8: {
        uint8_t v = level_of(fr, style);
        for (x = x1; x <= x2; x++)
            row[x] = v;
        break;
    }
    case STP_PIXEL_RGB888: {
        uint8_t c[3];
        if (style & STP_COLOUR_FLAG) {
            /* a colour: each channel's style index through the same levels */
            c[0] = level_of(fr, ((style >> 16) & 0xFF) + 1);
            c[1] = level_of(fr, ((style >> 8) & 0xFF) + 1);
            c[2] = level_of(fr, (style & 0xFF) + 1);
        } else {
            c[0] = c[1] = c[2] = level_of(fr, style);
        }
        for (x = x1; x <= x2; x++) {
            row[3 * x] = c[0];
            row[3 * x + 1] = c[1];
            row[3 * x + 2] = c[2];
        }
        break;
    }
    default: {
        uint8_t v = style_code(fr, style);
        for (x = x1; x <= x2; x++)
            row[x] = v;
        break;
    }
    }
}

#if STP_WITH_GOURAUD
/* A smooth span: pixel x has shade s0 + (x - x1) * step (shades with 16
 * extra fractional bits); each pixel goes through INTENSITY and the gamma
 * table and is compared with its own threshold (the combined scheme). */
static void put_span_smooth(const frame *fr, uint32_t y, uint32_t x1, uint32_t x2, int64_t s0,
                            int64_t step)
{
    uint8_t *row = band_row(fr, y);
    uint32_t x;
    int64_t s = s0;
    for (x = x1; x <= x2; x++, s += step) {
        int64_t sv = stp_asr64(s, 16);
        stp_fix shade = (stp_fix)(sv < 0 ? 0 : (sv > STP_FIX_ONE ? STP_FIX_ONE : sv));
        stp_output_put_shade(row, fr->port->format, x, y, fr->out, fr->cell, fr->r->levels, shade);
    }
}
#endif

#if STP_WITH_TRANSPARENCY
/* Inverse of INTENSITY for an 8-bit drive value: the style whose level is
 * nearest (the gamma table, or the linear ramp). */
static int index_of_level(const frame *fr, uint8_t level)
{
    int levels = fr->r->levels, best = 1, i, dbest = 256;
    if (!fr->out->gamma)
        return (int)(((int32_t)level * (levels - 1) + 127) / 255) + 1; /* > 2^15 */
    for (i = 1; i <= levels; i++) {
        int dd = fr->out->gamma[i - 1] - level;
        if (dd < 0)
            dd = -dd;
        if (dd < dbest) {
            dbest = dd;
            best = i;
        }
    }
    return best;
}

/* (10.20): v = min(1, v_r + t v_t) as a style index, v_r and v_t shades. */
static int blend(const frame *fr, stp_fix v_r, stp_fix t, stp_fix v_t)
{
    return stp_intensity_index(stp_fix_add(v_r, stp_fix_mul(t, v_t)), fr->r->levels);
}

/* A transparent span: each pixel's shade under it is read back from the
 * band through the inverse of INTENSITY and blended with the polygon's. */
static void put_span_blend(const frame *fr, uint32_t y, uint32_t x1, uint32_t x2, paint style,
                           stp_fix t)
{
    uint8_t *row = band_row(fr, y), page_bit = page_bit_of(fr, y);
    int levels = fr->r->levels;
    uint32_t x;
    switch (fr->port->format) {
    case STP_PIXEL_MONO1:
    case STP_PIXEL_MONO1_PAGES: {
        /* one bilevel pixel inverts to 0 or 1: its halftone density is
         * the shade, so blending per pixel keeps it on average */
        stp_fix v_r = stp_intensity_shade((int)style, levels);
        for (x = x1; x <= x2; x++) {
            stp_fix v_t = stp_mono_get(row, page_bit, x) ? STP_FIX_ONE : 0;
            stp_mono_put(row, page_bit, x, stp_cell_on(fr->cell, x, y, level_of(fr, blend(fr, v_r, t, v_t))));
        }
        break;
    }
    case STP_PIXEL_GREY8: {
        stp_fix v_r = stp_intensity_shade((int)style, levels);
        for (x = x1; x <= x2; x++)
            row[x] = level_of(fr, blend(fr, v_r, t, stp_intensity_shade(index_of_level(fr, row[x]), levels)));
        break;
    }
    case STP_PIXEL_RGB888: {
        int c;
        stp_fix v_r[3];
        for (c = 0; c < 3; c++)
            v_r[c] = stp_intensity_shade((int)((style & STP_COLOUR_FLAG) ? ((style >> (16 - 8 * c)) & 0xFF) + 1 : style),
                                         levels);
        for (x = x1; x <= x2; x++)
            for (c = 0; c < 3; c++) {
                uint8_t *p = &row[3 * x + (uint32_t)c];
                *p = level_of(fr, blend(fr, v_r[c], t, stp_intensity_shade(index_of_level(fr, *p), levels)));
            }
        break;
    }
    default: {
        stp_fix v_r = stp_intensity_shade((int)style, levels);
        for (x = x1; x <= x2; x++) {
            int under = fr->out->styles ? stp_style_inverse(fr->out->styles, row[x]) : row[x];
            stp_fix v_t = under > 0 ? stp_intensity_shade(under, levels) : 0;
            row[x] = style_code(fr, blend(fr, v_r, t, v_t));
        }
        break;
    }
    }
}
#endif

/* A run of a span: flat, smooth or transparent. */
static void paint_run_plain(const frame *fr, uint32_t y, uint32_t x1, uint32_t x2, paint style,
                            int smooth, int64_t s0, int64_t sstep, stp_fix t)
{
#if STP_WITH_TRANSPARENCY
    if (t > 0) {
        /* a smooth transparent polygon blends with its flat shade */
        put_span_blend(fr, y, x1, x2, style, t);
        return;
    }
#else
    (void)t;
#endif
#if STP_WITH_GOURAUD
    if (smooth) {
        put_span_smooth(fr, y, x1, x2, s0, sstep);
        return;
    }
#else
    (void)smooth;
    (void)s0;
    (void)sstep;
#endif
    put_span(fr, y, x1, x2, style);
}

#if STP_WITH_SHADOWS
/* Pixels x1..x2 of a shadowed polygon hidden from the lights in `hidden`
 * (render.h, stp_renderer_set_shadow_map): a flat grey polygon takes the style of
 * its shade re-lit without them; a colour polygon's channels and a smooth
 * polygon's interpolated shade are scaled by that shade over its full one. */
static void paint_hidden(const frame *fr, uint32_t y, uint32_t x1, uint32_t x2, paint style,
                         int smooth, int64_t s0, int64_t sstep, stp_fix t, uint32_t hidden)
{
    const stp_shadow_poly *sp = fr->shadow;
    int levels = fr->r->levels;
    stp_fix lit = stp_shadow_shade(sp, ~hidden), ratio = STP_FIX_ONE;
    if (sp->full > 0)
        ratio = (stp_fix)(((int64_t)lit << STP_FIX_FRAC_BITS) / sp->full); /* lit <= full */
    if (style & STP_COLOUR_FLAG) {
        int c;
        paint shaded = STP_COLOUR_FLAG;
        for (c = 0; c < 3; c++) {
            stp_fix v = stp_intensity_shade((int)((style >> (16 - 8 * c)) & 0xFF) + 1, levels);
            shaded |= (paint)(stp_intensity_index(stp_fix_mul(v, ratio), levels) - 1) << (16 - 8 * c);
        }
        style = shaded;
    } else if (sp->grey) {
        style = stp_intensity_index(lit, levels);
    } else {
        style = stp_intensity_index(stp_fix_mul(stp_intensity_shade((int)style, levels), ratio), levels);
    }
    if (smooth) {
        /* shades with 16 extra fractional bits, below 2^(F+18): the
         * products stay below 2^59 */
        s0 = stp_asr64(s0 * ratio, STP_FIX_FRAC_BITS);
        sstep = stp_asr64(sstep * ratio, STP_FIX_FRAC_BITS);
    }
    paint_run_plain(fr, y, x1, x2, style, smooth, s0, sstep, t);
}
#endif

/* A run of a span; with shadow records, split into runs of pixels hidden
 * from the same lights. */
static void paint_run(const frame *fr, uint32_t y, uint32_t x1, uint32_t x2, paint style, int smooth,
                      int64_t s0, int64_t sstep, stp_fix t)
{
#if STP_WITH_SHADOWS
    if (fr->shadow && fr->shadow->count > 0) {
        uint32_t x = x1, hidden = stp_shadow_hidden(fr->r, fr->shadow, x1, y);
        while (x <= x2) {
            uint32_t end = x, next = 0;
            int64_t sx = s0 + (int64_t)(x - x1) * sstep;
            while (end < x2) {
                next = stp_shadow_hidden(fr->r, fr->shadow, end + 1, y);
                if (next != hidden)
                    break;
                end++;
            }
            if (hidden == 0)
                paint_run_plain(fr, y, x, end, style, smooth, sx, sstep, t);
            else
                paint_hidden(fr, y, x, end, style, smooth, sx, sstep, t, hidden);
            x = end + 1;
            hidden = next;
        }
        return;
    }
#endif
    paint_run_plain(fr, y, x1, x2, style, smooth, s0, sstep, t);
}

#if STP_WITH_ZBUFFER

/* What a depth-tested span of a style that does not go straight to the
 * band (paint_setup) paints its runs with: paint_run. */
typedef struct span_paint {
    const frame *fr;
    uint32_t y, x1;
    paint style;
    int smooth;
    int64_t s0, sstep;
    stp_fix t;
} span_paint;

static void span_paint_init(span_paint *sp, const frame *fr, uint32_t y, uint32_t x1, paint style, int smooth,
                            int64_t s0, int64_t sstep, stp_fix t)
{
    sp->fr = fr;
    sp->y = y;
    sp->x1 = x1;
    sp->style = style;
    sp->smooth = smooth;
    sp->s0 = s0;
    sp->sstep = sstep;
    sp->t = t;
}

static void span_paint_run(const span_paint *sp, uint32_t a, uint32_t b)
{
    paint_run(sp->fr, sp->y, a, b, sp->style, sp->smooth, sp->smooth ? sp->s0 + (int64_t)(a - sp->x1) * sp->sstep : 0,
              sp->sstep, sp->t);
}

/* The band row y's Z entries, pixels and pattern byte. */
static uint16_t *z_row(const frame *fr, uint32_t y)
{
    return fr->zbuf + (size_t)(y - fr->rows.y0) * FRAME_WIDTH(fr);
}

static uint8_t pattern_of_row(const frame *fr, uint32_t y)
{
#if STP_WIDE_ARITH
    /* (64-bit hosts: two products, no test, for any height) */
    return fr->patterns[((uint64_t)(uint32_t)(y * fr->cell_mod) * fr->cell_rows) >> 32];
#else
    return fr->patterns[fr->cell_mask ? (y & fr->cell_mask) : y % fr->cell->height];
#endif
}


/* put_span_z's opaque span whose depths fit 32 bits (di at x1's centre,
 * dstep per pixel, every pixel's 1..65535): alternately skip the hidden
 * pixels and take a run of the visible ones, writing their depth. */
static void span_z_opaque(const span_paint *sp, uint16_t *z, uint32_t x1, uint32_t x2, int32_t di, int32_t dstep)
{
    uint32_t x = x1, run;
    for (;;) {
        while (x <= x2 && (uint16_t)((uint32_t)di >> 12) <= z[x]) {
            x++;
            di += dstep;
        }
        if (x > x2)
            return;
        run = x;
        do {
            z[x] = (uint16_t)((uint32_t)di >> 12);
            x++;
            di += dstep;
        } while (x <= x2 && (uint16_t)((uint32_t)di >> 12) > z[x]);
        span_paint_run(sp, run, x - 1);
    }
}

/* put_span_z's transparent span whose depths fit 32 bits (as
 * span_z_opaque): the runs of visible pixels, whose depths stay (a
 * transparent polygon does not hide what is behind it). */
static void span_z_transparent(const span_paint *sp, const uint16_t *z, uint32_t x1, uint32_t x2, int32_t di,
                               int32_t dstep)
{
    uint32_t x, run = 0;
    int in_run = 0;
    for (x = x1; x <= x2; x++, di += dstep) {
        uint16_t depth = (uint16_t)((uint32_t)di >> 12);
        if (depth > z[x]) {
            if (!in_run) {
                run = x;
                in_run = 1;
            }
        } else if (in_run) {
            span_paint_run(sp, run, x - 1);
            in_run = 0;
        }
    }
    if (in_run)
        span_paint_run(sp, run, x2);
}

/* put_span_z's span whose depths may leave 1..65535 (d at x1's centre,
 * ddx per pixel, Q12): each pixel's depth clamped (depth_of); an opaque
 * polygon (t 0) writes the depths of its visible pixels. */
static void span_z_clamped(const span_paint *sp, uint16_t *z, uint32_t x1, uint32_t x2, int64_t d, int64_t ddx,
                           stp_fix t)
{
    uint32_t x, run = 0;
    int in_run = 0;
    for (x = x1; x <= x2; x++, d += ddx) {
        uint16_t depth = depth_of(d);
        if (depth > z[x]) {
            if (t == 0)
                z[x] = depth;
            if (!in_run) {
                run = x;
                in_run = 1;
            }
        } else if (in_run) {
            span_paint_run(sp, run, x - 1);
            in_run = 0;
        }
    }
    if (in_run)
        span_paint_run(sp, run, x2);
}

/* Depth-tested span: runs of pixels that pass are painted whole, so the
 * halftone inner loop stays the same as without a Z buffer.  d: the depth
 * at x1's centre, ddx its change per pixel, both Q12. */
static void put_span_z(const frame *fr, uint32_t y, uint32_t x1, uint32_t x2, paint style,
                       int64_t d, int64_t ddx, int smooth, int64_t s0, int64_t sstep, stp_fix t, int direct)
{
    uint16_t *z = z_row(fr, y);
    int64_t d_end = d + ddx * (int64_t)(x2 - x1);
    const int64_t lo = DEPTH_Q12_MIN, hi = DEPTH_Q12_END;
    span_paint sp;
    if (direct) { /* opaque too: as every route's 1-bit spans */
        span_z_bits(z, band_row(fr, y), page_bit_of(fr, y), pattern_of_row(fr, y), x1, x2, d, ddx);
        return;
    }
    if (d >= lo && d < hi && d_end >= lo && d_end < hi) {
        /* both ends within 1..65535 (so every pixel between): no clamping,
         * and the depth and its step fit 32 bits (|step| <= |d_end - d|) */
        int32_t di = (int32_t)d, dstep = x2 > x1 ? (int32_t)ddx : 0;
        span_paint_init(&sp, fr, y, x1, style, smooth, s0, sstep, t);
        if (t == 0)
            span_z_opaque(&sp, z, x1, x2, di, dstep);
        else
            span_z_transparent(&sp, z, x1, x2, di, dstep);
        return;
    }
    span_paint_init(&sp, fr, y, x1, style, smooth, s0, sstep, t);
    span_z_clamped(&sp, z, x1, x2, d, ddx, t);
}


#if KEY_CACHE > 0
/* its slot of the kept mappings: key bits 3..8, not mixed: a mesh's
 * recent vertices lie near each other in depth, so near keys taking
 * neighbouring slots keep them apart (Cortex-M0+ torus render against the
 * old mix of bits 8..13 into 0..5: bits 3..8 3 800 instructions fewer,
 * bits 0..5 1 300 fewer, a multiplicative hash 14 400 more) */
#define KEY_SLOT(key) ((((uint32_t)(key)) >> 3) & (KEY_CACHE - 1))

static int32_t depth_q12_keep(frame *fr, key_mapping *m, int32_t key)
{
    m->key = key;
    m->q12 = depth_q12_of(&fr->keys, key);
    return m->q12;
}
#endif

/* a key's Q12 depth: kept, or made (and kept); a hit (three in four on a
 * mesh) falls through, a miss branches to its call.  depth_q12_in: the
 * kept mappings' address (fr->cached) a register the caller keeps for
 * several keys (ARMv6-M: the field's offset costs two instructions a load,
 * two loads a key). */
static inline int32_t depth_q12_in(frame *fr, void *cache, int32_t key)
{
#if KEY_CACHE > 0
    key_mapping *m = (key_mapping *)cache + KEY_SLOT(key);
    if (STP_UNLIKELY(m->key != key)) /* every slot holds a true mapping (render_prepare_fill) */
        return depth_q12_keep(fr, m, key);
    return m->q12;
#else
    (void)cache;
    return depth_q12_of(&fr->keys, key);
#endif
}


#if KEY_CACHE > 0
#define DEPTH_KEPT(fr) ((void *)(fr)->cached)
#else
#define DEPTH_KEPT(fr) ((void *)0)
#endif

#if defined(__OPTIMIZE_SIZE__) /* its one caller: depth_setup_triangle's build for size */
static inline int32_t depth_q12(frame *fr, int32_t key)
{
    return depth_q12_in(fr, DEPTH_KEPT(fr), key);
}
#endif

/* A triangle's plane (depth_plane_triangle) from its vertices' Q12
 * depths, the kept mappings' where there are */
DEPTH_TRIANGLE_FN int depth_setup_triangle(frame *fr, const stp_instr *v, depth_plane *pl)
{
#if defined(__OPTIMIZE_SIZE__) /* builds for size: depth_q12's one copy, called (lm3s6965: 16 bytes) */
    int32_t d0 = depth_q12(fr, v[0].z), d1 = depth_q12(fr, v[1].z), d2 = depth_q12(fr, v[2].z);
#else
    void *kept = DEPTH_KEPT(fr);
    int32_t d0 = depth_q12_in(fr, kept, v[0].z), d1 = depth_q12_in(fr, kept, v[1].z), d2 = depth_q12_in(fr, kept, v[2].z);
#endif
    return depth_plane_triangle(v, d0, d1, d2, pl);
}

/* The depth plane of the polygon at `ordinal` (display order) for this
 * band: made in the polygon's first band (the one holding its top: ymin >=
 * the band's top) and kept in the caller's setup array when there is one,
 * taken from there in the bands after.  Returns 0 for an edge-on polygon
 * (kept as centre x = SETUP_EDGE_ON: device coordinates are >=
 * -STP_GUARD_Q4, project_private.h).  A triangle makes its plane at its
 * first span with pixels, so a band may end without it: kept as centre x
 * = SETUP_NOT_MADE (setups_not_made), made by the next band that needs
 * it. */
#define SETUP_EDGE_ON (-STP_GUARD_Q4 - 1)
#define SETUP_NOT_MADE (-STP_GUARD_Q4 - 2)
/* Every kept setup marked not made, once a frame before its first band:
 * a triangle's top may lie in a band above its first row, where its walk
 * ends before tri_setup_mark (the next band would take the setup made for
 * another frame, or the caller's garbage) */
static void setups_not_made(stp_polygon_setup *setup, uint32_t polygons)
{
    uint32_t i;
    for (i = 0; i < polygons; i++)
        setup[i].centre[0] = SETUP_NOT_MADE;
}

static int depth_plane_for(frame *fr, const stp_instr *v, int n, uint32_t ordinal, int32_t ymin,
                           depth_plane *pl)
{
    stp_polygon_setup *kept = fr->setup && ordinal != UINT32_MAX ? &fr->setup[ordinal] : 0;
    int ok;
    if (kept && ymin < fr->rows.top && kept->centre[0] != SETUP_NOT_MADE) {
        if (kept->centre[0] < -STP_GUARD_Q4) /* SETUP_EDGE_ON */
            return 0;
        pl->ddx = kept->plane[0];
        pl->ddy = kept->plane[1];
        pl->dc = kept->plane[2];
        pl->xc = kept->centre[0];
        pl->yc = kept->centre[1];
        return 1;
    }
    ok = n == 3 ? depth_setup_triangle(fr, v, pl) : depth_plane_polygon(&fr->keys, v, n, pl);
    if (kept) {
        kept->plane[0] = pl->ddx;
        kept->plane[1] = pl->ddy;
        kept->plane[2] = pl->dc;
        kept->centre[0] = ok ? pl->xc : SETUP_EDGE_ON;
        kept->centre[1] = pl->yc;
    }
    return ok;
}
#endif

/* What a polygon's spans need before the first is painted: its shadow
 * records and its style's pattern bytes.  Returns whether runs go straight
 * to the band from the pattern bytes (flat, opaque, not shadowed, MONO1
 * with the style's patterns built). */
static int paint_setup(frame *fr, const stp_instr *v, paint style, int smooth, stp_fix t)
{
    int direct = !smooth && t == 0;
#if STP_WITH_SHADOWS
    if (fr->shadow) {
        stp_shadow_polygon(fr->r, (uint32_t)(v - fr->r->df), fr->shadow);
        if (fr->shadow->count > 0)
            direct = 0;
    }
#else
    (void)v;
#endif
    /* pattern bytes are made for MONO1 only (use_style); a MONO1 port
     * under error diffusion is drawn as GREY8 */
    if (!fr->pattern_port || (style & STP_COLOUR_FLAG))
        return 0;
    if (style != fr->pattern_style)
        use_style(fr, style);
    return direct && style == fr->pattern_style;
}

/* Whether the frame gathers no shadow records (set once a frame), and
 * pattern_port's value when that holds too (render_prepare_fill): the
 * triangle path's ready test then reads one field, not two. */
#if STP_WITH_SHADOWS
#define TRIANGLE_SHADOWLESS(fr) ((fr)->shadow == 0)
#else
#define TRIANGLE_SHADOWLESS(fr) 1
#endif
#define PATTERN_PLAIN 2

#if STP_WITH_TRIANGLE_PATH
/* A polygon (its header instruction) with a shade per vertex. */
static int polygon_smooth(const stp_instr *header)
{
#if STP_WITH_GOURAUD
    return header->shade >= 0;
#else
    (void)header;
    return 0;
#endif
}

#if STP_WITH_ZBUFFER

/* The band row a triangle's direct spans go to (span_z_direct): its Z
 * entries and its pixels, set at the triangle's first span (tri_row_at)
 * and stepped a row down with the triangle (tri_row_next) rather than
 * formed again for every span.  (Its pattern byte is formed for each span
 * from the row, pattern_of_row: one value fewer kept across the rows, and
 * no step a row; the Cortex-M0+ torus's triangles have a span or two.) */
typedef struct tri_row {
    uint16_t *z;
    uint8_t *band;
    uint8_t page_bit; /* stp_halftone_fill_bits: 0, or the row's page bit */
} tri_row;

STP_HOT_INLINE void tri_row_at(const frame *fr, tri_row *tr, uint32_t row, int pages)
{
    tr->z = z_row(fr, row);
    tr->band = fr->band + (size_t)(pages ? (row - fr->rows.y0) >> 3 : row - fr->rows.y0) * fr->stride; /* band_row */
    tr->page_bit = pages ? page_bit_of(fr, row) : 0;
}

STP_HOT_INLINE void tri_row_next(const frame *fr, tri_row *tr, int pages)
{
    tr->z += FRAME_WIDTH(fr);
    if (pages) {
        /* the next bit of the page, else the next page's first */
        tr->page_bit = (uint8_t)(tr->page_bit << 1);
        if (tr->page_bit == 0) {
            tr->page_bit = 1;
            tr->band += fr->stride;
        }
    } else {
        tr->band += fr->stride;
    }
}

/* The depth-tested span p1..p2 of a triangle's row: straight to the band
 * (tri_span_straight, at tr: tr NULL when not direct), else through
 * put_span_z. */
STP_HOT_INLINE void tri_span_z(const frame *fr, uint32_t row, uint32_t p1, uint32_t p2, paint style, stp_fix t,
                               const tri_row *tr, const tri_depth *td, const depth_plane *pl, int pages)
{
    int64_t d, ddx;
    if (tr) {
        uint8_t page_bit = pages ? tr->page_bit : 0;
        if (!tri_span_straight(tr->z, tr->band, page_bit, pattern_of_row(fr, row), p1, p2, td, pl, &d, &ddx))
            span_z_clamped_bits(tr->z, tr->band, page_bit, pattern_of_row(fr, row), p1, p2, d, ddx);
        return;
    }
    d = tri_depth_at(td, pl, p1, &ddx);
    put_span_z(fr, row, p1, p2, style, d, ddx, 0, 0, 0, t, 0);
}
#endif

/* paint_setup's answer for an opaque flat triangle without its call when
 * it has nothing to set up: a MONO1 pattern style already made, no
 * shadow records to gather (0: ask paint_setup); its one user is the
 * Z-buffered triangle below. */
#if STP_PATTERN_CACHE > 0 && !defined(__OPTIMIZE_SIZE__) && STP_WITH_ZBUFFER
#define TRIANGLE_PAINT_READY(fr, style, t)                                                                       \
    ((t) == 0 && (fr)->pattern_port == PATTERN_PLAIN && !((style)&STP_COLOUR_FLAG) &&                             \
     ((style) == (fr)->pattern_style || style_kept(fr, style)))

/* TRIANGLE_PAINT_READY's other case: style's pattern rows kept (use_style's
 * cache), made current without paint_setup's call (a torus's neighbouring
 * faces alternate styles: 190 calls a frame at 128x64); not in a build for
 * size, where the call is the smaller code (lm3s6965: 72 bytes), and the
 * test keeps its order there (ATmega2560: 10 bytes, 260 cycles). */
STP_HOT_INLINE int style_kept(frame *fr, paint style)
{
    uint32_t slot = (uint32_t)style & (STP_PATTERN_CACHE - 1);
    if (fr->cached_style[slot] != style) /* slots stay empty for taller cells */
        return 0;
    style_from_slot(fr, style, slot);
    return 1;
}
#else
#define TRIANGLE_PAINT_READY(fr, style, t)                                                                       \
    ((t) == 0 && (style) == (fr)->pattern_style && (fr)->pattern_port && !((style)&STP_COLOUR_FLAG) &&            \
     TRIANGLE_SHADOWLESS(fr))
#endif

#if STP_WITH_ZBUFFER
/* The rows of tri_draw_z that go straight to the band from w's row (span
 * p1..p2) at tr; pages a constant at each call (1: MONO1_PAGES), so the
 * rows' loop keeps no page test. */
STP_HOT_INLINE void tri_rows_direct(const frame *fr, paint style, stp_fix t, stp_tri_walk *w, tri_row *tr, tri_depth *td,
                                    const depth_plane *pl, uint32_t p1, uint32_t p2, int pages)
{
    for (;;) {
        tri_span_z(fr, (uint32_t)w->row, p1, p2, style, t, tr, td, pl, pages);
        do {
            if (!stp_tri_walk_next(w))
                return;
            tri_depth_step(td, pl);
            tri_row_next(fr, tr, pages);
        } while (!stp_tri_walk_span(w, FRAME_WIDTH(fr), &p1, &p2));
    }
}

/* The depth-tested rows of triangle v from walk w's row, whose
 * span p1..p2 is the first with pixels: its plane made (or taken from the
 * kept setups) here; rows straight to the band (tri_row) when
 * paint_setup says they can go. */
STP_HOT_INLINE void tri_draw_z(frame *fr, const stp_instr *v, paint style, stp_fix t,
                               uint32_t ordinal, stp_tri_walk *w, uint32_t p1, uint32_t p2, int pages)
{
    depth_plane pl;
    tri_depth td;
    tri_row tr;
    /* without kept setups the plane is made here (no call, no lookup) */
#if STP_WIDE_ARITH
    /* depth_setup_triangle inlined: pl stays in registers where the kept
     * setups' call takes a copy's address, not pl's (host mesh torus
     * 3 400 instructions a frame fewer; ARMv6-M calls depth_setup_triangle
     * anyway, and the copy cost its torus 800) */
    int made;
    if (fr->setup) {
        depth_plane kept;
        made = depth_plane_for(fr, v, 3, ordinal, w->top->y, &kept);
        pl = kept;
    } else {
        made = depth_setup_triangle(fr, v, &pl);
    }
#else
    int made = fr->setup ? depth_plane_for(fr, v, 3, ordinal, w->top->y, &pl) : depth_setup_triangle(fr, v, &pl);
#endif
    if (!made)
        return; /* edge-on: no area on screen */
    tri_depth_start(&td, &pl, v, w->bot->y - w->top->y, stp_tri_walk_yc(w), made);
    if (!(TRIANGLE_PAINT_READY(fr, style, t) || paint_setup(fr, v, style, 0, t))) {
        for (;;) {
            tri_span_z(fr, (uint32_t)w->row, p1, p2, style, t, 0, &td, &pl, 0);
            do {
                if (!stp_tri_walk_next(w))
                    return;
                tri_depth_step(&td, &pl);
            } while (!stp_tri_walk_span(w, FRAME_WIDTH(fr), &p1, &p2));
        }
    }
    tri_row_at(fr, &tr, (uint32_t)w->row, pages);
    tri_rows_direct(fr, style, t, w, &tr, &td, &pl, p1, p2, pages);
}

/* tri_draw_z into a MONO1_PAGES band: the same code with pages 1, out of
 * line, marked cold and w taken by value, so the rows' copy (inlined in
 * draw_triangle) keeps no page test and its locals stay in registers
 * (one copy with a page test per row cost the host's rows up to 3 % more
 * instructions, a copy taking w's address 4 %: tools/bench/torus_bench.sh). */
#if defined(__GNUC__)
#define PAGES_COPY static __attribute__((noinline, cold))
#else
#define PAGES_COPY static
#endif
PAGES_COPY void tri_draw_z_pages(frame *fr, const stp_instr *v, paint style, stp_fix t,
                                   uint32_t ordinal, stp_tri_walk w, uint32_t p1, uint32_t p2)
{
    tri_draw_z(fr, v, style, t, ordinal, &w, p1, p2, 1);
}
#endif

/* The kept setup of the triangle at `ordinal` (walk w started, rows in
 * this band) marked not made in the band holding its top: made at its
 * first span.  setups_not_made marked it so already; the mark stays as
 * GCC 12 lays draw_triangle out better with it (without: 6 400 more
 * instructions a Cortex-M0+ mesh torus frame, 8 800 with 8-row bands). */
STP_HOT_INLINE void tri_setup_mark(frame *fr, int use_z, uint32_t ordinal, const stp_tri_walk *w)
{
#if STP_WITH_ZBUFFER
    /* (setup tested first: one test and branch without kept setups) */
    if (fr->setup && use_z && ordinal != UINT32_MAX && w->top->y >= fr->rows.top)
        fr->setup[ordinal].centre[0] = SETUP_NOT_MADE;
#else
    (void)fr;
    (void)use_z;
    (void)ordinal;
    (void)w;
#endif
}

/* A flat triangle (vertices v, in the display file) in the current band:
 * the general path's fill rule and depths, set up for what the triangle
 * needs.  Its vertices sorted by y (top, mid, bottom), each row centre is
 * crossed by the long edge top-bottom and by top-mid above mid,
 * mid-bottom from mid down; the two crossings bound the row's span.
 * Nothing is set up before the first span with pixels: a small triangle
 * often covers no pixel centre.  Coordinates are >= 0 (project()), so are
 * the crossings. */
#if STP_WIDE_ARITH
/* in line in replay's triangle loop where registers are plenty (64-bit
 * hosts: no call and no saved registers a triangle); a call elsewhere */
#define DRAW_TRIANGLE_DEF STP_HOT_INLINE void draw_triangle_run
#else
#define DRAW_TRIANGLE_DEF static void draw_triangle
#define draw_triangle_run draw_triangle
#endif
DRAW_TRIANGLE_DEF(frame *fr, const stp_instr *v, paint style, int use_z, stp_fix t, uint32_t ordinal)
{
    stp_tri_walk w;
    uint32_t p1, p2, width = FRAME_WIDTH(fr);
    if (!stp_tri_walk_start(&v[0], &v[1], &v[2], &fr->rows, &w))
        return;
    tri_setup_mark(fr, use_z, ordinal, &w);
    while (!stp_tri_walk_span(&w, width, &p1, &p2))
        if (!stp_tri_walk_next(&w))
            return; /* no pixel centre */
#if STP_WITH_ZBUFFER
    if (use_z) {
        if (STP_WITH_PAGES && fr->page_one)
            tri_draw_z_pages(fr, v, style, t, ordinal, w, p1, p2);
        else
            tri_draw_z(fr, v, style, t, ordinal, &w, p1, p2, 0);
        return;
    }
#else
    (void)use_z;
    (void)ordinal;
#endif
    (void)paint_setup(fr, v, style, 0, t);
    for (;;) {
        paint_run(fr, (uint32_t)w.row, p1, p2, style, 0, 0, 0, t);
        do {
            if (!stp_tri_walk_next(&w))
                return;
        } while (!stp_tri_walk_span(&w, width, &p1, &p2));
    }
}
#if STP_WIDE_ARITH
static void draw_triangle(frame *fr, const stp_instr *v, paint style, int use_z, stp_fix t, uint32_t ordinal)
{
    draw_triangle_run(fr, v, style, use_z, t, ordinal);
}
#endif
#endif /* STP_WITH_TRIANGLE_PATH */

/* Flat triangles take their own path unless the edge pass is on (it reads
 * the general path's crossings) or they reach x = 2^14 (1024 pixels:
 * tri_edge's 32 bits). */
#if !STP_WITH_TRIANGLE_PATH
#define TRIANGLE_PATH(fr) 0
#elif STP_WITH_EDGE_AA
#define TRIANGLE_PATH(fr) ((fr)->aa.out == 0)
#else
#define TRIANGLE_PATH(fr) 1
#endif

#if STP_WITH_EDGE_AA
#if STP_WITH_ZBUFFER
#define EDGE_AA_DEPTH(v) (v)
#else
#define EDGE_AA_DEPTH(v) 0
#endif
#if STP_WITH_SHADOWS
#define EDGE_AA_UNSHADOWED(fr) (!(fr)->shadow || (fr)->shadow->count == 0)
#else
#define EDGE_AA_UNSHADOWED(fr) 1
#endif
#endif

#if STP_WITH_GOURAUD
/* The shade along a span from its two crossings c[0] and c[1], at pixel
 * centres with 16 extra fractional bits: *s0 at p1's, *sstep per pixel. */
STP_HOT_INLINE void span_shades(const stp_crossing *c, uint32_t p1, int64_t *s0, int64_t *sstep)
{
    int64_t sl = c[0].shade, sr = c[1].shade;
    int64_t width = (int64_t)c[1].x - c[0].x;
    *sstep = width > 0 ? ((sr - sl) * 65536 * (1 << SUB)) / width : 0;
    *s0 = sl * 65536 + (width > 0 ? ((sr - sl) * 65536 * (((int64_t)p1 << SUB) + HALF_PIXEL - c[0].x)) / width : 0);
}
#endif

/* The spans of a polygon's row y between its nc crossings (r->crossings,
 * in pairs): pixels whose centre c satisfies x_left <= c < x_right.  With
 * the Z buffer, d_row is the Q12 depth at device x = 0 of the row centre
 * and ddx its change per subpixel. */
STP_HOT_INLINE void polygon_row(const frame *fr, uint32_t y, int nc, paint style, int use_z, stp_fix t, int smooth,
                                int direct, int64_t d_row, int64_t ddx)
{
    const stp_renderer *r = fr->r;
    int k;
    for (k = 0; k + 1 < nc; k += 2) {
        int64_t s0 = 0, sstep = 0;
        uint32_t p1, p2;
        if (!stp_span_pixels(r->crossings[k].x, r->crossings[k + 1].x, r->width, &p1, &p2))
            continue;
#if STP_WITH_GOURAUD
        if (smooth)
            span_shades(&r->crossings[k], p1, &s0, &sstep);
#endif
#if STP_WITH_ZBUFFER
        if (use_z) {
            put_span_z(fr, y, p1, p2, style, depth_plane_at(d_row, ddx, p1), ddx * (1 << SUB), smooth, s0, sstep, t,
                       direct);
            continue;
        }
#else
        (void)use_z;
        (void)direct;
        (void)d_row;
        (void)ddx;
#endif
        paint_run(fr, y, p1, p2, style, smooth, s0, sstep, t);
    }
}

/* Scan-convert the polygon whose header is df[at] into the current band;
 * ordinal: its place among the visible polygons in display order
 * (UINT32_MAX: no kept setup). */
static void draw_polygon(frame *fr, uint32_t at, paint style, int use_z, stp_fix t, uint32_t ordinal)
{
    stp_renderer *r = fr->r;
    const stp_instr *v = &r->df[at];
    int n = (int)v[0].op, ne; /* a vertex count, <= STP_MAX_POLYGON_VERTICES */
#if STP_WITH_GOURAUD
    int smooth = v[0].shade >= 0;
#else
    const int smooth = 0;
#endif
    int32_t ymin, ymax, first, last;
    int direct;
    int32_t band_top = fr->rows.top, band_bottom = fr->rows.end;
    uint32_t y, y_first, y_last;
    int64_t d_row = 0, ddx = 0;
#if STP_WITH_ZBUFFER
    depth_plane pl = {0, 0, 0, 0, 0};
#endif
#if STP_WITH_TRIANGLE_PATH
    if (n == 3 && !smooth && TRIANGLE_PATH(fr) && STP_TRIANGLE_NARROW(v)) {
        draw_triangle(fr, v, style, use_z, t, ordinal); /* the painter's order comes here */
        return;
    }
#endif
    stp_polygon_y_extent(v, n, &ymin, &ymax);
    if (ymax <= band_top || ymin >= band_bottom)
        return;
#if STP_WITH_ZBUFFER
    if (use_z && !depth_plane_for(fr, v, n, ordinal, ymin, &pl))
        return; /* edge-on: no area on screen */
#else
    (void)ordinal;
#endif
    direct = paint_setup(fr, v, style, smooth, t);
    ne = stp_polygon_edges(r->edges, v, n, smooth);
    stp_polygon_rows(r->edges, ne, ymin, ymax, band_top, band_bottom, (int32_t)(fr->rows.y0 + fr->rows.count - 1u),
                     smooth, &first, &last);
    y_first = (uint32_t)first;
    y_last = (uint32_t)last;
#if STP_WITH_ZBUFFER
    /* the depth at device x = 0 of the current row centre, stepped down
     * (Q12; |ddx|, |ddy| <= 2^40 and coordinates below 2^20, so every
     * term and the sum stay below 2^62) */
    if (use_z)
        d_row = depth_plane_row(&pl, y_first);
    ddx = pl.ddx;
#endif
    for (y = y_first; y <= y_last; y++) {
        int nc = stp_edges_row(r->edges, ne, (int32_t)(y << SUB) + HALF_PIXEL, smooth, r->crossings);
        polygon_row(fr, y, nc, style, use_z, t, smooth, direct, d_row, ddx);
#if STP_WITH_EDGE_AA
        /* the pixels just outside this row's spans (opaque, unshadowed) */
        if (fr->aa.out && t == 0 && EDGE_AA_UNSHADOWED(fr))
            stp_edge_aa_row(&fr->aa, band_row(fr, y),
                            use_z ? fr->zbuf + (size_t)(y - fr->rows.y0) * r->width : 0, r->crossings, nc,
                            style, smooth, EDGE_AA_DEPTH(d_row), EDGE_AA_DEPTH(ddx));
#endif
#if STP_WITH_ZBUFFER
        d_row += pl.ddy * (1 << SUB);
#endif
    }
}

#if STP_WITH_LINES
/* Bresenham from pixel centre to pixel centre; only the rows of the band. */
static void draw_line(const frame *fr, const stp_instr *a, const stp_instr *b, paint style)
{
    int32_t x0 = a->x >> SUB, y0 = a->y >> SUB, x1 = b->x >> SUB, y1 = b->y >> SUB;
    int32_t dx = x1 > x0 ? x1 - x0 : x0 - x1, dy = y1 > y0 ? y0 - y1 : y1 - y0;
    int32_t sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1, err = dx + dy;
    int32_t w = (int32_t)fr->r->width - 1, h = (int32_t)fr->r->height - 1;
    for (;;) {
        int32_t px = x0 > w ? w : x0, py = y0 > h ? h : y0;
        if ((uint32_t)py >= fr->rows.y0 && (uint32_t)py < fr->rows.y0 + fr->rows.count)
            put_span(fr, (uint32_t)py, (uint32_t)px, (uint32_t)px, style);
        if (x0 == x1 && y0 == y1)
            break;
        {
            int32_t e2 = 2 * err;
            if (e2 >= dy) {
                err += dy;
                x0 += sx;
            }
            if (e2 <= dx) {
                err += dx;
                y0 += sy;
            }
        }
    }
}
#endif

/* The display file's line instruction in (any other op: nothing) with the
 * line style and pen (the line's start) it changes. */
static inline void replay_line_op(const frame *fr, const stp_instr *in, const stp_instr **pen, paint *line_style)
{
    if (in->op == STP_OP_LINE_STYLE) {
        *line_style = in->x;
    } else if (in->op == STP_OP_MOVE) {
        *pen = in;
    } else if (in->op == STP_OP_LINE) {
#if STP_WITH_LINES
        if (*pen)
            draw_line(fr, *pen, in, *line_style);
#else
        (void)fr;
#endif
        *pen = in;
    }
}

/* Whether replay's pass (0 all, 1 opaque only, 2 transparent only) draws
 * the polygons under transmission t. */
static int replay_draws(int skip_polygons, int pass, stp_fix t)
{
    return !skip_polygons && (pass == 0 || (pass == 1) == (t == 0));
}

/* How replay draws the flat narrow triangles: 0 by draw_polygon; 1 by
 * draw_triangle; 2 by draw_triangle with several bands, where a triangle
 * off the band is skipped in replay rather than called (the call's
 * arguments cost more than the test). */
static int replay_triangle_path(const frame *fr)
{
    if (!TRIANGLE_PATH(fr))
        return 0;
    return !STP_LEAN_CODE && fr->rows.count < fr->r->height ? 2 : 1;
}

#if STP_WITH_TRIANGLE_PATH && !STP_LEAN_CODE
/* Whether triangle v lies above or below the band's rows (rows: band
 * top and end, Q27.4): draw_triangle and draw_polygon would return at
 * once, having changed nothing. */
STP_HOT_INLINE int triangle_off_band(const stp_instr *v, const stp_band_rows *rows)
{
    int32_t top = rows->top, end = rows->end;
    return (v[0].y <= top && v[1].y <= top && v[2].y <= top) || (v[0].y >= end && v[1].y >= end && v[2].y >= end);
}

/* replay's triangle record v (df[k]) with several bands: 1 when skipped
 * off the band or drawn by draw_triangle, 0 when it is draw_polygon's
 * (smooth, or too wide). */
STP_HOT_INLINE int replay_banded_triangle(frame *fr, const stp_instr *v, paint style, int use_z,
                                          stp_fix t, uint32_t ordinal)
{
    if (triangle_off_band(v, &fr->rows))
        return 1;
    if (polygon_smooth(v) || !STP_TRIANGLE_NARROW(v))
        return 0;
    draw_triangle(fr, v, style, use_z, t, ordinal);
    return 1;
}
#endif

/* Walk the visible segments in display order: polygons (unless skip_polygons)
 * and lines, each with the style in force. */
/* pass: which polygons to draw: 0 all, 1 opaque only, 2 transparent only. */
static void replay(frame *fr, int skip_polygons, int use_z, int pass)
{
    stp_renderer *r = fr->r;
    uint32_t ordinal = 0;
    int s, tri_path = replay_triangle_path(fr); /* once, not per polygon */
    int rgb = fr->port->format == STP_PIXEL_RGB888;
    (void)tri_path; /* read only with the triangle path compiled in */
    for (s = 0; s < STP_MAX_SEGMENTS; s++) {
        const stp_segment *seg = &r->segments[s];
        paint style = r->fill_style, line_style = r->fill_style;
        stp_fix t = 0;
        const stp_instr *pen = 0; /* a line's start */
        /* locals, not r's fields: the draws store through pointers that
         * may alias r, which would reload them every record */
        const stp_instr *in = &r->df[seg->start];
        uint32_t k, end = seg->end;
        /* whether this pass draws the polygons that follow (t as it
         * stands); tri: and triangles by the triangle path (tri_path) */
        int draw = replay_draws(skip_polygons, pass, 0), tri = draw ? tri_path : 0;
        if (!seg->used || !seg->visible)
            continue;
        for (k = seg->start; k < end; k++, in++) {
            int32_t op = in->op;
#if STP_WITH_TRIANGLE_PATH && defined(__OPTIMIZE_SIZE__)
            if (op == 3 && tri == 1 && !polygon_smooth(in) && STP_TRIANGLE_NARROW(in)) {
                draw_triangle(fr, in, style, use_z, t, ordinal);
                ordinal++;
                k += 2;
                in += 2;
                continue;
            }
#elif STP_WITH_TRIANGLE_PATH
            /* the common record first, in a loop of its own laid out to
             * fall through, its advance one constant (measured: 6 800
             * Cortex-M0+ cycles less a mesh torus frame; builds for size
             * keep one test, 92 bytes less) */
            while (!STP_UNLIKELY(op != 3 || tri != 1 || polygon_smooth(in) || !STP_TRIANGLE_NARROW(in))) {
                draw_triangle_run(fr, in, style, use_z, t, ordinal);
                ordinal++;
                k += 3;
                in += 3;
                if (k >= end)
                    break;
                op = in->op;
            }
            if (k >= end)
                break;
#endif
            if (op == STP_OP_SHADE) { /* the run's other record: tested first */
                style = paint_of(rgb, in);
            } else
#if STP_WITH_TRIANGLE_PATH && !STP_LEAN_CODE
            if (op == 3 && tri == 2 && replay_banded_triangle(fr, in, style, use_z, t, ordinal)) {
                ordinal++;
                k += 2;
                in += 2;
            } else
#endif
            if (op >= 3) {
                if (draw)
                    draw_polygon(fr, k, style, use_z, t, ordinal);
                ordinal++;
                k += (uint32_t)op - 1;
                in += op - 1;
            } else if (op == STP_OP_TRANSPARENCY) {
                t = in->x;
                draw = replay_draws(skip_polygons, pass, t);
                tri = draw ? tri_path : 0;
                (void)tri; /* read only with the triangle path compiled in */
            } else {
                replay_line_op(fr, in, &pen, &line_style);
            }
        }
    }
}

/* Whether the Z buffer's scan (scan_triangles) widens the device x
 * extent: not on 64-bit hosts, whose Z buffer is then cleared in whole
 * rows (frame_extent) for a third of the scan's tests (the depth keys'
 * extent stays exact: it sets the depths) */
#define SCAN_X (!STP_WIDE_ARITH)
/* On 64-bit hosts a frame drawn in one band of at most 16 384 pixels is
 * cleared in every row rather than scanned for its rows: a Z buffer row's
 * clear costs the host a few instructions (memset), a triangle's y tests
 * about five (128x64 spinning torus: 5 000 instructions a frame fewer; at
 * 640x480 clearing every row would cost 19 000 more).  Elsewhere (and
 * with several bands, whose skipping needs the rows) always scanned. */
#if STP_WIDE_ARITH
static int scan_y_wanted(const stp_renderer *r, const stp_frame_memory *mem)
{
    return mem->band_rows < r->height || (uint32_t)r->width * r->height > 16384u;
}
#endif

/* The extent of the visible polygons' vertices: device x and y (Q27.4)
 * and depth keys, each as its least value and its width (the greatest
 * minus the least, modulo 2^32: the int32 range's width fits a uint32).
 * One unsigned test, v - lo > width, finds a value outside [lo, lo +
 * width]: a mesh's vertices mostly fall inside, and the test costs one
 * compare-and-branch where a minimum and a maximum take two. */
typedef struct extent {
    int32_t x_lo, y_lo, key_min;
    uint32_t x_width, y_width, key_width;
} extent;

/* lo and width widened to include v; made v alone when first (the
 * frame's first vertex: lo and width are 0 before it, which is already v
 * alone when v is 0, the one value the test finds inside). */
static inline void extent_widen(int32_t *lo, uint32_t *width, int32_t v, int first)
{
    uint32_t d = (uint32_t)v - (uint32_t)*lo;
    if (d > *width) {
        if (first) {
            *width = 0;
            *lo = v;
        } else if (v < *lo) {
            *width += (uint32_t)*lo - (uint32_t)v;
            *lo = v;
        } else {
            *width = d;
        }
    }
}

/* Widen ex by vertex v, the frame's first when first. */
static inline void extent_vertex(extent *ex, const stp_instr *v, int first)
{
    extent_widen(&ex->key_min, &ex->key_width, v->z, first);
    extent_widen(&ex->x_lo, &ex->x_width, v->x, first);
    extent_widen(&ex->y_lo, &ex->y_width, v->y, first);
}

/* Widen ex by the n >= 3 vertices of the polygon in[0..n-1], the frame's
 * first polygon when count is 0.  A triangle's three without a loop:
 * ARMv6-M has too few registers for the extent, a counter and a limit. */
static inline void extent_add(extent *ex, const stp_instr *in, int32_t n, uint32_t count)
{
    int32_t i;
    extent_vertex(ex, &in[0], count == 0);
    extent_vertex(ex, &in[1], 0);
    extent_vertex(ex, &in[2], 0);
    for (i = 3; i < n; i++)
        extent_vertex(ex, &in[i], 0);
}

/* The painter's entry of the polygon df[k] (n vertices in[0..n-1]): keyed
 * by its farthest vertex. */
static inline void sort_entry_set(stp_sort_entry *e, uint32_t k, const stp_instr *in, int32_t n, paint style,
                                  stp_fix t)
{
    int32_t far_key = in[0].z, i;
    for (i = 1; i < n; i++)
        far_key = in[i].z < far_key ? in[i].z : far_key;
    e->index = k;
    e->key = far_key;
    e->style = style;
    e->transmission = t;
}

/* The pixels [*first, *last] (from 0) a coordinate extent [lo, lo + w]
 * (Q27.4) reaches: floor(lo / 16) and floor((lo + w) / 16), the extent
 * moved by the guard band (project_private.h: coordinates from
 * -STP_GUARD_Q4) for an unsigned shift, the part left of or above pixel 0
 * left out; *first > *last when nothing is left.  Without the guard band
 * the coordinates are >= 0 (project() clamps them). */
static void extent_pixels(int32_t lo, uint32_t w, uint32_t *first, uint32_t *last)
{
#if STP_GUARD_BAND
    const uint32_t guard = (uint32_t)STP_GUARD_Q4 >> SUB; /* in pixels */
    uint32_t a = ((uint32_t)lo + (uint32_t)STP_GUARD_Q4) >> SUB, b = ((uint32_t)lo + (uint32_t)STP_GUARD_Q4 + w) >> SUB;
    if (b < guard) {
        *first = 1;
        *last = 0;
        return;
    }
    *first = a > guard ? a - guard : 0;
    *last = b - guard;
#else
    *first = (uint32_t)lo >> SUB;
    *last = ((uint32_t)lo + w) >> SUB;
#endif
}

/* The frame's depth-key range and the pixels the count visible polygons
 * can cover: a pixel a polygon covers has its centre within the polygon's
 * vertices' extent (extent_pixels). */
static void frame_extent(frame *fr, uint32_t count, const extent *ex)
{
    fr->keys.key_min = INT32_MAX;
    fr->keys.key_max = INT32_MIN;
    fr->x_min = fr->y_min = 1;
    fr->x_max = fr->y_max = 0;
    if (count == 0)
        return;
    fr->keys.key_min = ex->key_min;
    fr->keys.key_max = (int32_t)((uint32_t)ex->key_min + ex->key_width); /* within [key_min, INT32_MAX] */
    extent_pixels(ex->x_lo, ex->x_width, &fr->x_min, &fr->x_max);
    extent_pixels(ex->y_lo, ex->y_width, &fr->y_min, &fr->y_max);
    if (fr->x_max > fr->r->width - 1 || !SCAN_X)
        fr->x_max = fr->r->width - 1;
    if (!SCAN_X) /* whole rows: the scan left x out */
        fr->x_min = 0;
    if (fr->y_max > fr->r->height - 1 || !FRAME_SCAN_Y(fr))
        fr->y_max = fr->r->height - 1;
    if (!FRAME_SCAN_Y(fr)) /* every row: the scan left y out */
        fr->y_min = 0;
}

/* Whether vertex v lies outside the extent (lo, w) of each coordinate. */
#define VERTEX_OUTSIDE(v, lo, w, xlo, xw, ylo, yw, with_y)                                                           \
    ((uint32_t)(v).z - (uint32_t)(lo) > (w) || (SCAN_X && (uint32_t)(v).x - (uint32_t)(xlo) > (xw)) ||              \
     ((with_y) && (uint32_t)(v).y - (uint32_t)(ylo) > (yw)))

/* Widen *ex by the run of triangles and SHADE records from in (a
 * triangle), to end or the first other record, for the Z buffer's scan
 * (no sort entries, so no styles); *count counts the triangles (0 before
 * the frame's first: ex is then made its first vertex).  Returns where
 * the run stopped.  Out of line, with the extent in locals: its six
 * values, the record pointer and a scratch register are ARMv6-M's eight
 * low registers, so a triangle within the extent costs nine loads,
 * subtractions and compares, and no update.  Builds for size take the
 * general loop (scan_polygons) alone. */
#if !defined(__OPTIMIZE_SIZE__)
#if STP_WIDE_ARITH
#define SCAN_WITH_Y with_y /* scan_triangles' two forms (scan_y) */
STP_HOT_INLINE const stp_instr *scan_run(extent *ex_io, const stp_instr *in, const stp_instr *end,
                                         uint32_t *count_io, const int with_y)
#else
#define SCAN_WITH_Y 1 /* one form, a function of its own */
STP_NOINLINE const stp_instr *scan_triangles(extent *ex_io, const stp_instr *in, const stp_instr *end,
                                             uint32_t *count_io)
#endif
{
    const stp_instr *v;
    uint32_t shades = 0, w, xw, yw;
    int32_t lo, xlo, ylo, i;
    if (*count_io == 0)
        extent_vertex(ex_io, in, 1);
    lo = ex_io->key_min;
    w = ex_io->key_width;
    xlo = ex_io->x_lo;
    xw = ex_io->x_width;
    ylo = ex_io->y_lo;
    yw = ex_io->y_width;
    for (v = in; v < end; v++) {
        if (STP_UNLIKELY(v->op != 3)) {
            if (v->op != STP_OP_SHADE)
                break;
            shades++;
            continue;
        }
        /* the widening a loop: unrolled, the compiler keeps the loads of
         * the test for it, which takes registers the test needs */
        if (STP_UNLIKELY(VERTEX_OUTSIDE(v[0], lo, w, xlo, xw, ylo, yw, SCAN_WITH_Y) ||
                         VERTEX_OUTSIDE(v[1], lo, w, xlo, xw, ylo, yw, SCAN_WITH_Y) ||
                         VERTEX_OUTSIDE(v[2], lo, w, xlo, xw, ylo, yw, SCAN_WITH_Y)))
            for (i = 0; i < 3; i++) {
                extent_widen(&lo, &w, v[i].z, 0);
                if (SCAN_X)
                    extent_widen(&xlo, &xw, v[i].x, 0);
                if (SCAN_WITH_Y)
                    extent_widen(&ylo, &yw, v[i].y, 0);
            }
        v += 2;
    }
    ex_io->key_min = lo;
    ex_io->key_width = w;
    ex_io->x_lo = xlo;
    ex_io->x_width = xw;
    ex_io->y_lo = ylo;
    ex_io->y_width = yw;
    /* the triangles counted at the end: the run's records less its
     * SHADE records, three a triangle (the count a register too many) */
    *count_io += ((uint32_t)(v - in) - shades) / 3u;
    return v;
}

/* scan_run with its y tests where the frame asks for them (scan_y, 64-bit
 * hosts), one loop each. */
#if STP_WIDE_ARITH
STP_NOINLINE const stp_instr *scan_triangles(extent *ex_io, const stp_instr *in, const stp_instr *end,
                                             uint32_t *count_io, int with_y)
{
    return with_y ? scan_run(ex_io, in, end, count_io, 1) : scan_run(ex_io, in, end, count_io, 0);
}
#define SCAN_TRIANGLES(ex, in, end, count, fr) scan_triangles(ex, in, end, count, (fr)->scan_y)
#else
#define SCAN_TRIANGLES(ex, in, end, count, fr) scan_triangles(ex, in, end, count)
#endif
#endif

/* Collect visible polygons for the painter (sort != NULL: entries keyed by
 * their farthest vertex) and the depth-key range. */
static uint32_t scan_polygons(frame *fr, stp_sort_entry *sort)
{
    stp_renderer *r = fr->r;
    const stp_instr *df = r->df;
    uint32_t count = 0, t_count = 0; /* t_count: the count when t was set */
    int s;
    /* a local, not fr's fields: a store through fr may alias the display
     * file; 0 until the first polygon's first vertex (extent_widen) */
    extent ex = {0, 0, 0, 0, 0, 0};
    int second_pass = 0;
    for (s = 0; s < STP_MAX_SEGMENTS; s++) {
        const stp_segment *seg = &r->segments[s];
        const stp_instr *in, *end = df + seg->end;
        paint style = r->fill_style;
        stp_fix t = 0;
        if (!seg->used || !seg->visible)
            continue;
        for (in = df + seg->start; in < end; in++) {
            int32_t op = in->op;
#if !defined(__OPTIMIZE_SIZE__)
            if (op == 3 && !sort) { /* the usual run: a mesh's triangles */
                in = SCAN_TRIANGLES(&ex, in, end, &count, fr) - 1;
            } else
#endif
            if (op >= 3) {
                extent_add(&ex, in, op, count);
                if (sort)
                    sort_entry_set(&sort[count], (uint32_t)(in - df), in, op, style, t);
                count++;
                in += op - 1;
            } else if (op == STP_OP_SHADE) {
                style = paint_of(fr->port->format == STP_PIXEL_RGB888, in);
            } else if (op == STP_OP_TRANSPARENCY) {
                /* a second pass for the polygons drawn since under t > 0:
                 * a test per change of t, not per polygon */
                second_pass |= t > 0 && count != t_count;
                t = in->x;
                t_count = count;
            } else if (op == STP_OP_LINE) {
                second_pass = 1;
            }
        }
        second_pass |= t > 0 && count != t_count;
    }
    fr->second_pass = second_pass;
    frame_extent(fr, count, &ex);
    return count;
}

/* Whether stp_renderer_render's pointers are there and the port is the
 * renderer's size. */
static int render_args_ok(const stp_renderer *r, const stp_port *port, const stp_frame_memory *mem)
{
    return r != 0 && port != 0 && mem != 0 && port->flush != 0 && mem->band != 0 && port->width == r->width &&
           port->height == r->height;
}

#if STP_WITH_EDGE_AA
/* Whether pixel culling (stp_renderer_set_pixel_cull) dropped a triangle
 * of a visible segment: a sliver edge anti-aliasing would draw. */
static int pixel_culled(const stp_renderer *r)
{
    int s;
    for (s = 0; s < STP_MAX_SEGMENTS; s++)
        if (r->segments[s].used && r->segments[s].visible && r->segments[s].pixel_culled)
            return 1;
    return 0;
}
#endif

/* Whether a port's pixels are 1 bit: rows or pages. */
static int one_bit(stp_pixel_format format)
{
    return format == STP_PIXEL_MONO1 || format == STP_PIXEL_MONO1_PAGES;
}

/* The port the bands are drawn for: port itself, or a GREY8 copy of a
 * 1-bit port in *grey when the output diffuses errors or anti-aliases
 * edges (the band is thresholded at flush).  STP_OK or the error. */
static int render_drawn_port(frame *fr, const stp_port *port, const stp_output *output, stp_port *grey,
                             const stp_port **drawn)
{
    *drawn = port;
#if STP_WITH_EDGE_AA
    fr->aa.out = 0;
    if (output->edge_aa && one_bit(port->format)) {
        *grey = *port; /* drawn grey, thresholded by the cell at flush */
        grey->format = STP_PIXEL_GREY8;
        *drawn = grey;
    }
#else
    (void)fr;
    if (output->edge_aa)
        return STP_ERR_UNSUPPORTED;
#endif
    if (output->diffusion && one_bit(port->format)) {
#if STP_WITH_DIFFUSION
        int status = stp_diffusion_check(output->diffusion, port->width);
        if (status != STP_OK)
            return status;
        *grey = *port;
        grey->format = STP_PIXEL_GREY8;
        *drawn = grey;
#else
        return STP_ERR_UNSUPPORTED;
#endif
    }
#if !STP_WITH_DIFFUSION && !STP_WITH_EDGE_AA
    (void)grey;
#endif
    return STP_OK;
}

/* The caller's frame memory against what the hidden-surface method and
 * the drawn format need: STP_OK, STP_ERR_MEMORY, STP_ERR_ARG (also a page
 * port's band_rows neither whole pages nor the height, port.h) or
 * STP_ERR_UNSUPPORTED (a method compiled out). */
static int render_check_memory(const stp_renderer *r, const stp_port *port, const stp_output *output,
                               const stp_frame_memory *mem, stp_pixel_format drawn)
{
    size_t stride = stp_row_bytes(drawn, port->width);
    if (!STP_WITH_PAGES && port->format == STP_PIXEL_MONO1_PAGES)
        return STP_ERR_UNSUPPORTED;
    if (stride == 0 || mem->band_rows < 1 || mem->band_rows > r->height)
        return STP_ERR_ARG;
    if (port->format == STP_PIXEL_MONO1_PAGES && mem->band_rows % 8u != 0 && mem->band_rows != r->height)
        return STP_ERR_ARG;
    if (mem->band_size < stp_band_bytes(drawn, port->width, mem->band_rows))
        return STP_ERR_MEMORY;
    /* STYLE8 without a table stores the index in a byte: 1..255 */
    if (port->format == STP_PIXEL_STYLE8 && output->styles == 0 && r->levels > 255)
        return STP_ERR_ARG;
    if (output->hidden == STP_HIDDEN_ZBUFFER) {
#if STP_WITH_ZBUFFER
        if (mem->zbuf == 0 || mem->zbuf_count < (size_t)r->width * mem->band_rows)
            return STP_ERR_MEMORY;
#else
        return STP_ERR_UNSUPPORTED;
#endif
    } else if (output->hidden == STP_HIDDEN_PAINTER) {
#if STP_WITH_PAINTER
        if (mem->sort == 0 || mem->sort_count < stp_renderer_polygon_count(r))
            return STP_ERR_MEMORY;
#else
        return STP_ERR_UNSUPPORTED;
#endif
    } else if (output->hidden != STP_HIDDEN_NONE) {
        return STP_ERR_ARG;
    }
    return STP_OK;
}

/* The frame's cell (the output's, else Bayer 4 x 4) and background style
 * into fr->cell and *background.  STP_OK, or STP_ERR_UNSUPPORTED when no
 * cell is given and the default one is compiled out. */
static int render_cell_and_background(frame *fr, const stp_port *port, const stp_output *output,
                                      paint *background)
{
    const stp_renderer *r = fr->r;
    if (output->cell) {
        fr->cell = output->cell;
    } else {
#if STP_WITH_DEFAULT_CELL
        stp_cell_default(&fr->default_cell);
        fr->cell = &fr->default_cell;
#else
        return STP_ERR_UNSUPPORTED;
#endif
    }
    *background = stp_intensity_index(output->background, r->levels);
    if (port->format == STP_PIXEL_RGB888 && output->background_colour) {
        int c;
        *background = STP_COLOUR_FLAG;
        for (c = 0; c < 3; c++)
            *background |= (paint)(stp_intensity_index(output->background_colour[c], r->levels) - 1)
                           << (16 - 8 * c);
    }
    /* port.h: STYLE8 without a table holds 0 where nothing is drawn and the
     * background is 0 (style_code passes 0 through) */
    if (port->format == STP_PIXEL_STYLE8 && output->styles == 0 && output->background <= 0)
        *background = 0;
    return STP_OK;
}

/* The depth keys' range and scale, the caches and the span fill's state,
 * once the polygons are scanned. */
static void render_prepare_fill(frame *fr, const stp_port *port, const stp_port *drawn, const stp_output *output,
                                paint background)
{
    uint32_t i;
    depth_keys_set(&fr->keys, fr->keys.key_min, fr->keys.key_max);
#if KEY_CACHE > 0
    /* each slot starts as key_max's mapping, 65535 2^12 (depth_q12_made's:
     * u = range gives quotient 65534 2^12 exactly; with no range every key
     * maps there), right wherever it is found, so a lookup tests the key
     * alone */
    for (i = 0; i < KEY_CACHE; i++) {
        fr->cached[i].key = fr->keys.key_max;
        fr->cached[i].q12 = (int32_t)65535 << 12;
    }
#endif
    fr->mono_fill = one_bit(port->format) && fr->cell->kind == STP_CELL_THRESHOLD &&
                    fr->cell->width > 0 && 8u % fr->cell->width == 0 && fr->cell->height > 0 &&
                    fr->cell->height <= STP_CELL_MAX; /* patterns[] holds a row each */
    fr->pattern_port = (one_bit(drawn->format) && fr->mono_fill) << (TRIANGLE_SHADOWLESS(fr) != 0); /* PATTERN_PLAIN 2 */
    fr->cell_mask = (fr->cell->height & (fr->cell->height - 1u)) == 0 ? fr->cell->height - 1u : 0;
#if STP_WIDE_ARITH
    fr->cell_rows = fr->cell->height;
    fr->cell_mod = fr->cell->height > 1 ? (uint32_t)(0xFFFFFFFFu / fr->cell->height + 1u) : 0u;
#endif
    fr->pattern_style = -1;
#if STP_PATTERN_CACHE > 0
    patterns_start(fr);
#endif
    (void)i;
    use_style(fr, background);
#if STP_WITH_EDGE_AA
    if (output->edge_aa) {
        fr->aa.out = output;
        fr->aa.format = drawn->format;
        fr->aa.levels = fr->r->levels;
        fr->aa.width = fr->r->width;
    }
#else
    (void)output;
#endif
}

/* The clearing loops below store a word at a time, four a step, on
 * 32-bit targets built for speed (a Cortex-M0+ spends as much on a loop's
 * count, compare and branch as on two stores, a byte store costs what a
 * word store does, and the compiler leaves a counted loop a loop there);
 * the plain loop elsewhere: 64-bit hosts make it memset, builds for size
 * keep it small.  The words are written through a may_alias type (GCC's,
 * the only compilers of these builds; others keep the plain loop), from
 * the first word boundary: the band and the Z buffer are the caller's
 * bytes and entries, of any alignment. */
#if !defined(__OPTIMIZE_SIZE__) && UINTPTR_MAX <= 0xFFFFFFFFu && UINTPTR_MAX > 0xFFFFu && defined(__GNUC__)
#define STORES_UNROLLED 1
typedef uint32_t __attribute__((__may_alias__)) clear_word;
#else
#define STORES_UNROLLED 0
#endif

#if STORES_UNROLLED
/* count bytes from p set to v (v repeated in word w): the bytes before a
 * word boundary, then 16 a step as four words; returns the bytes done. */
static size_t fill_words(uint8_t *p, size_t count, uint8_t v, uint32_t w)
{
    size_t i = 0;
    for (; i < count && ((uintptr_t)(p + i) & 3u) != 0; i++)
        p[i] = v;
    for (; count - i >= 16u; i += 16u) {
        clear_word *q = (clear_word *)(void *)(p + i);
        q[0] = w;
        q[1] = w;
        q[2] = w;
        q[3] = w;
    }
    return i;
}
#endif

/* count bytes from p set to v. */
static void fill_bytes(uint8_t *p, size_t count, uint8_t v)
{
    size_t i = 0;
#if STORES_UNROLLED
    i = fill_words(p, count, v, (uint32_t)v * 0x01010101u);
#endif
    for (; i < count; i++)
        p[i] = v;
}

#if STP_WITH_ZBUFFER
/* count Z-buffer entries from z set to 0, as fill_bytes (an odd address
 * cannot hold a uint16_t: the bytes before a word boundary are whole
 * entries). */
static void zero_entries(uint16_t *z, size_t count)
{
    size_t i = 0;
#if STORES_UNROLLED
    i = fill_words((uint8_t *)(void *)z, 2u * count, 0, 0) / 2u;
#endif
    for (; i < count; i++)
        z[i] = 0;
}
#endif

/* Band y0's rows cleared to the background and, with the Z buffer, its
 * entries where a polygon can reach set farther than any polygon. */
/* A MONO1 band whose rows hold no padding bits (width 8 stride) cleared
 * to a background whose pattern bytes (use_style) are one byte for every
 * cell row: one fill of the whole band, what put_span would write row by
 * row.  0 (nothing written) when the band is not so. */
static int band_clear_uniform(frame *fr, const stp_port *drawn, paint background)
{
    size_t count = fr->stride * (size_t)fr->rows.count; /* below band_size */
    uint32_t cy;
    uint8_t pattern;
    if (drawn->format != STP_PIXEL_MONO1 || (size_t)fr->r->width != 8u * fr->stride)
        return 0;
    use_style(fr, background); /* patterns[] for the background, when mono_fill */
    if (background != fr->pattern_style)
        return 0;
    pattern = fr->patterns[0];
    for (cy = 1; cy < fr->cell->height; cy++)
        if (fr->patterns[cy] != pattern)
            return 0;
    fill_bytes(fr->band, count, pattern);
    return 1;
}

/* Page k of a MONO1_PAGES band filled with the background's pattern rows
 * (patterns[], made by use_style): pixel x of row r takes bit 7 - (x mod
 * 8) of its row's pattern byte, so the page repeats every 8 columns, and
 * column c's byte gathers bit 7 - c of its rows' bytes, bit r for row r;
 * rows past the band's last stay 0. */
static void page_fill_background(const frame *fr, uint8_t *page, uint32_t k)
{
    uint8_t column[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    uint32_t r, c, first = fr->rows.y0 + 8u * k, n = fr->rows.count - 8u * k < 8u ? fr->rows.count - 8u * k : 8u;
    size_t x;
    for (r = 0; r < n; r++) {
        uint32_t y = first + r;
        uint8_t pattern = fr->patterns[fr->cell_mask ? (y & fr->cell_mask) : y % fr->cell->height];
        for (c = 0; c < 8u; c++)
            column[c] = (uint8_t)(column[c] | (((pattern >> (7u - c)) & 1u) << r));
    }
    for (x = 0; x < fr->stride; x++) /* stride: the width, a page's bytes */
        page[x] = column[x & 7u];
}

/* A MONO1_PAGES band's pages cleared: to the background's pattern when it
 * has one (1: the band is the background), else to 0 (0: the rows are
 * painted over it); the bits of rows past the frame's last row stay 0
 * either way.  Filling a page a byte per column beats painting its rows,
 * which set one bit of each byte (stp_halftone_fill_page_run). */
static int band_clear_pages(frame *fr, paint background)
{
    size_t count = fr->stride * (((size_t)fr->rows.count + 7u) / 8u); /* within band_size */
    uint32_t k;
    uint8_t *band = fr->band; /* a local: a byte store may alias fr */
    use_style(fr, background); /* patterns[] for the background, when mono_fill */
    if (background != fr->pattern_style) {
        fill_bytes(band, count, 0);
        return 0;
    }
    for (k = 0; 8u * k < fr->rows.count; k++)
        page_fill_background(fr, band + k * fr->stride, k);
    return 1;
}

static void render_band_clear(frame *fr, const stp_port *drawn, stp_hidden hidden, paint background)
{
    const stp_renderer *r = fr->r;
    uint32_t y, y0 = fr->rows.y0;
    int cleared = STP_PAGES_FORMAT(drawn->format) ? band_clear_pages(fr, background)
                                                         : band_clear_uniform(fr, drawn, background);
    for (y = cleared ? y0 + fr->rows.count : y0; y < y0 + fr->rows.count; y++) {
        /* MONO1 padding bits past the width reach the port too: make
         * them 0 rather than whatever the caller's buffer held */
        if (drawn->format == STP_PIXEL_MONO1)
            fr->band[(size_t)(y - y0) * fr->stride + fr->stride - 1] = 0;
        put_span(fr, y, 0, r->width - 1, background);
    }
#if STP_WITH_ZBUFFER
    if (hidden == STP_HIDDEN_ZBUFFER && fr->x_min <= fr->x_max) {
        /* farther than any polygon (they map to >= 1), where one can
         * reach: a Z test reads no other entry */
        uint32_t y_end = y0 + fr->rows.count - 1 < fr->y_max ? y0 + fr->rows.count - 1 : fr->y_max;
        size_t count = (size_t)(fr->x_max - fr->x_min) + 1u;
        for (y = y0 > fr->y_min ? y0 : fr->y_min; y <= y_end; y++)
            zero_entries(fr->zbuf + (size_t)(y - y0) * r->width + fr->x_min, count);
    }
#else
    (void)hidden;
#endif
}

#if !STP_LEAN_CODE
/* Whether a visible polygon can reach the band's rows: the rows of their
 * extent (frame_extent), none when there are no polygons.  (Left out
 * where 32-bit comparisons cost more code than they save time.) */
static int band_reached(const frame *fr)
{
    return fr->y_min <= fr->y_max && fr->rows.y0 <= fr->y_max && fr->rows.y0 + fr->rows.count > fr->y_min;
}
#endif

/* The band's polygons and lines by the hidden-surface method. */
static void render_band_draw(frame *fr, stp_hidden hidden, const stp_frame_memory *mem, uint32_t polygons)
{
#if STP_WITH_PAINTER
    if (hidden == STP_HIDDEN_PAINTER) {
        uint32_t i;
        for (i = 0; i < polygons; i++)
            draw_polygon(fr, mem->sort[i].index, mem->sort[i].style, 0, mem->sort[i].transmission, UINT32_MAX);
        replay(fr, 1, 0, 0); /* lines on top, in display order */
        return;
    }
#else
    (void)mem;
    (void)polygons;
#endif
#if !STP_LEAN_CODE
    if (!fr->second_pass && !band_reached(fr))
        return; /* no line, and no polygon reaches the band: replay would draw nothing */
#endif
    if (hidden == STP_HIDDEN_ZBUFFER) {
        /* opaque first, then the transparent ones over them */
        replay(fr, 0, 1, 1);
        if (fr->second_pass)
            replay(fr, 0, 1, 2);
    } else {
        replay(fr, 0, 0, 0);
    }
}

/* A grey band for a 1-bit port made MONO1 rows (pages: MONO1_PAGES) in
 * place, row by row, by error diffusion or the cell. */
static void render_band_threshold(frame *fr, const stp_output *output, int pages)
{
#if STP_WITH_DIFFUSION || STP_WITH_EDGE_AA
    uint32_t y;
    (void)output; /* read only with diffusion */
    for (y = fr->rows.y0; y < fr->rows.y0 + fr->rows.count; y++) {
        /* a page port's row r goes to page r / 8, on grey row r / 8:
         * read already (diffuse_private.h) */
        uint8_t *row = fr->band + (size_t)(y - fr->rows.y0) * fr->stride;
        uint8_t *page = pages ? fr->band + (size_t)((y - fr->rows.y0) >> 3) * fr->stride : 0;
#if STP_WITH_DIFFUSION
        if (output->diffusion) {
            if (page)
                stp_diffuse_row_page(output->diffusion, row, fr->r->width, y, page);
            else
                stp_diffuse_row(output->diffusion, row, fr->r->width, y);
            continue;
        }
#endif
#if STP_WITH_EDGE_AA
        if (page)
            stp_edge_aa_threshold_page(row, fr->r->width, y, fr->cell, page);
        else
            stp_edge_aa_threshold_row(row, fr->r->width, y, fr->cell);
#endif
    }
#else
    (void)fr;
    (void)output;
    (void)pages;
#endif
}

int stp_renderer_render(stp_renderer *r, stp_port *port, const stp_output *output,
               const stp_frame_memory *mem)
{
    frame fr;
#if STP_WITH_SHADOWS
    stp_shadow_poly shadow_poly;
#endif
    stp_port grey_port; /* error diffusion, edge anti-aliasing: the band is drawn as GREY8 */
    const stp_port *drawn;
    uint32_t y0, polygons;
    paint background_style;
    stp_output default_output;
    int status;
    if (output == 0) {
        (void)stp_output_default(&default_output);
        output = &default_output;
    }
    if (!render_args_ok(r, port, mem))
        return STP_ERR_ARG;
#if STP_WITH_EDGE_AA
    if (output->edge_aa && pixel_culled(r))
        return STP_ERR_UNSUPPORTED; /* render.h: stp_renderer_set_pixel_cull */
#endif
    if ((status = render_drawn_port(&fr, port, output, &grey_port, &drawn)) != STP_OK)
        return status;
    fr.stride = stp_row_bytes(drawn->format, port->width);
    fr.line_shift = drawn->format == STP_PIXEL_MONO1_PAGES ? 3u : 0u;
    fr.page_one = drawn->format == STP_PIXEL_MONO1_PAGES ? 1u : 0u;
    if ((status = render_check_memory(r, port, output, mem, drawn->format)) != STP_OK)
        return status;
    fr.r = r;
#if FRAME_WORD_LAYOUT
    fr.width = r->width;
#endif
    fr.port = drawn;
    fr.out = output;
    fr.band = mem->band;
    fr.zbuf = mem->zbuf;
#if STP_WITH_SHADOWS
    shadow_poly.count = 0;
    fr.shadow = stp_shadow_any(r) ? &shadow_poly : 0;
#endif
    if ((status = render_cell_and_background(&fr, port, output, &background_style)) != STP_OK)
        return status;
#if STP_WIDE_ARITH
    fr.scan_y = scan_y_wanted(r, mem);
#endif
    polygons = scan_polygons(&fr, output->hidden == STP_HIDDEN_PAINTER ? mem->sort : 0);
    fr.setup = 0;
#if STP_WITH_ZBUFFER
    if (output->hidden == STP_HIDDEN_ZBUFFER && mem->setup) {
        if (mem->setup_count < polygons)
            return STP_ERR_MEMORY;
        fr.setup = mem->setup;
        setups_not_made(mem->setup, polygons);
    }
#endif
    render_prepare_fill(&fr, port, drawn, output, background_style);
#if STP_WITH_PAINTER
    if (output->hidden == STP_HIDDEN_PAINTER)
        stp_sort_far_to_near(mem->sort, (size_t)polygons);
#endif
    for (y0 = 0; y0 < r->height; y0 += mem->band_rows) {
        fr.rows.y0 = y0;
        fr.rows.count = r->height - y0 < mem->band_rows ? r->height - y0 : mem->band_rows;
        fr.rows.top = (int32_t)(y0 << SUB); /* heights below 2^15: no overflow */
        fr.rows.end = (int32_t)((y0 + fr.rows.count) << SUB);
        render_band_clear(&fr, drawn, output->hidden, background_style);
        render_band_draw(&fr, output->hidden, mem, polygons);
        if (drawn == &grey_port)
            render_band_threshold(&fr, output, STP_PAGES_FORMAT(port->format));
        if (port->flush(port, y0, fr.rows.count, fr.band, fr.stride) < 0)
            return STP_ERR_PORT;
    }
    return STP_OK;
}
