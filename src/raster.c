/* SPDX-License-Identifier: MIT */
/* The display-file interpreter: hidden surfaces, scan conversion and band
 * output.  See the fill rule in include/stipple/render.h. */
#include "render_private.h"
#include "output_private.h"

#define SUB STP_SUBPIXEL_BITS
#define HALF_PIXEL (1 << (SUB - 1))

size_t stp_row_bytes(stp_pixel_format fmt, uint32_t width)
{
    switch (fmt) {
    case STP_PIXEL_MONO1: return ((size_t)width + 7u) / 8u;
    case STP_PIXEL_GREY8:
    case STP_PIXEL_STYLE8: return width;
    case STP_PIXEL_RGB888: return (size_t)width * 3u;
    default: return 0;
    }
}

/* Everything one frame's interpretation needs, built once per stp_renderer_render. */
typedef struct frame {
    stp_renderer *r;
    const stp_port *port;
    const stp_output *out;
    const stp_cell *cell;
    stp_cell default_cell;
    size_t stride;
    uint8_t *band;
    uint16_t *zbuf;
    uint32_t y0, rows; /* current band */
    int32_t key_min, key_max; /* depth-key range of the visible polygons */
#if STP_WITH_SHADOWS
    stp_shadow_poly *shadow; /* the polygon being drawn's shadow records;
                                NULL when no light has a map */
#endif
} frame;

/* 8-bit drive value of a style index (gamma table or linear). */
static uint8_t level_of(const frame *fr, int index)
{
    return stp_output_level(fr->out, fr->r->levels, index);
}

/* indices entered under more levels than are now set show as the top
 * style (0 stays 0: "nothing drawn") */
static uint8_t style_code(const frame *fr, int index)
{
    return stp_output_style_code(fr->out, fr->r->levels, index);
}

/* What a STP_OP_SHADE paints with: its colour on an RGB888 device when it
 * has one, else its style index. */
static int paint_of(const frame *fr, const stp_instr *in)
{
    if (fr->port->format == STP_PIXEL_RGB888 && (in->z & STP_COLOUR_FLAG))
        return in->z;
    return in->x;
}

/* Paint pixels x1..x2 of band row `row` (absolute y) in a style. */
static void put_span(const frame *fr, uint32_t y, uint32_t x1, uint32_t x2, int style)
{
    uint8_t *row = fr->band + (size_t)(y - fr->y0) * fr->stride;
    uint32_t x;
    switch (fr->port->format) {
    case STP_PIXEL_MONO1:
        stp_halftone_fillin(row, x1, x2, y, fr->cell, level_of(fr, style));
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
    uint8_t *row = fr->band + (size_t)(y - fr->y0) * fr->stride;
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
        return (level * (levels - 1) + 127) / 255 + 1;
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
static void put_span_blend(const frame *fr, uint32_t y, uint32_t x1, uint32_t x2, int style,
                           stp_fix t)
{
    uint8_t *row = fr->band + (size_t)(y - fr->y0) * fr->stride;
    int levels = fr->r->levels;
    uint32_t x;
    switch (fr->port->format) {
    case STP_PIXEL_MONO1: {
        /* one bilevel pixel inverts to 0 or 1: its halftone density is
         * the shade, so blending per pixel keeps it on average */
        stp_fix v_r = stp_intensity_shade(style, levels);
        for (x = x1; x <= x2; x++) {
            uint8_t bit = (uint8_t)(0x80u >> (x & 7u));
            stp_fix v_t = (row[x >> 3] & bit) ? STP_FIX_ONE : 0;
            if (stp_cell_on(fr->cell, x, y, level_of(fr, blend(fr, v_r, t, v_t))))
                row[x >> 3] = (uint8_t)(row[x >> 3] | bit);
            else
                row[x >> 3] = (uint8_t)(row[x >> 3] & ~bit);
        }
        break;
    }
    case STP_PIXEL_GREY8: {
        stp_fix v_r = stp_intensity_shade(style, levels);
        for (x = x1; x <= x2; x++)
            row[x] = level_of(fr, blend(fr, v_r, t, stp_intensity_shade(index_of_level(fr, row[x]), levels)));
        break;
    }
    case STP_PIXEL_RGB888: {
        int c;
        stp_fix v_r[3];
        for (c = 0; c < 3; c++)
            v_r[c] = stp_intensity_shade((style & STP_COLOUR_FLAG) ? ((style >> (16 - 8 * c)) & 0xFF) + 1 : style,
                                         levels);
        for (x = x1; x <= x2; x++)
            for (c = 0; c < 3; c++) {
                uint8_t *p = &row[3 * x + (uint32_t)c];
                *p = level_of(fr, blend(fr, v_r[c], t, stp_intensity_shade(index_of_level(fr, *p), levels)));
            }
        break;
    }
    default: {
        stp_fix v_r = stp_intensity_shade(style, levels);
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
static void paint_run_plain(const frame *fr, uint32_t y, uint32_t x1, uint32_t x2, int style,
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
static void paint_hidden(const frame *fr, uint32_t y, uint32_t x1, uint32_t x2, int style,
                         int smooth, int64_t s0, int64_t sstep, stp_fix t, uint32_t hidden)
{
    const stp_shadow_poly *sp = fr->shadow;
    int levels = fr->r->levels;
    stp_fix lit = stp_shadow_shade(sp, ~hidden), ratio = STP_FIX_ONE;
    if (sp->full > 0)
        ratio = (stp_fix)(((int64_t)lit << STP_FIX_FRAC_BITS) / sp->full); /* lit <= full */
    if (style & STP_COLOUR_FLAG) {
        int c, shaded = STP_COLOUR_FLAG;
        for (c = 0; c < 3; c++) {
            stp_fix v = stp_intensity_shade(((style >> (16 - 8 * c)) & 0xFF) + 1, levels);
            shaded |= (stp_intensity_index(stp_fix_mul(v, ratio), levels) - 1) << (16 - 8 * c);
        }
        style = shaded;
    } else if (sp->grey) {
        style = stp_intensity_index(lit, levels);
    } else {
        style = stp_intensity_index(stp_fix_mul(stp_intensity_shade(style, levels), ratio), levels);
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
static void paint_run(const frame *fr, uint32_t y, uint32_t x1, uint32_t x2, int style, int smooth,
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
/* Depth-tested span: runs of pixels that pass are painted with put_span, so
 * the halftone inner loop stays the same as without a Z buffer. */
static void put_span_z(const frame *fr, uint32_t y, uint32_t x1, uint32_t x2, int style,
                       int64_t d, int64_t ddx, int smooth, int64_t s0, int64_t sstep, stp_fix t)
{
    uint16_t *z = fr->zbuf + (size_t)(y - fr->y0) * fr->r->width;
    uint32_t x, run = 0;
    int in_run = 0;
    for (x = x1; x <= x2; x++, d += ddx) {
        int64_t dv = stp_asr64(d, 12);
        uint16_t depth = (uint16_t)(dv < 1 ? 1 : (dv > 65535 ? 65535 : dv));
        if (depth > z[x]) {
            if (t == 0)
                z[x] = depth; /* transparent polygons do not hide what follows */
            if (!in_run) {
                run = x;
                in_run = 1;
            }
        } else if (in_run) {
            paint_run(fr, y, run, x - 1, style, smooth, s0 + (int64_t)(run - x1) * sstep, sstep, t);
            in_run = 0;
        }
    }
    if (in_run)
        paint_run(fr, y, run, x2, style, smooth, s0 + (int64_t)(run - x1) * sstep, sstep, t);
}

/* Depth key mapped to the Z buffer's 1..65535 with 12 fractional bits. */
static int64_t depth_q12(const frame *fr, int32_t key)
{
    int64_t range = (int64_t)fr->key_max - fr->key_min;
    if (range <= 0)
        return (int64_t)65535 << 12;
    return ((int64_t)1 << 12) + (((int64_t)key - fr->key_min) * ((int64_t)65534 << 12)) / range;
}
#endif

/* Scan-convert the polygon whose header is df[at] into the current band. */
static void draw_polygon(const frame *fr, uint32_t at, int style, int use_z, stp_fix t)
{
    stp_renderer *r = fr->r;
    const stp_instr *v = &r->df[at];
    int n = v[0].op, i, ne = 0;
#if STP_WITH_GOURAUD
    int smooth = v[0].shade >= 0;
#else
    const int smooth = 0;
#endif
    int32_t ymin = INT32_MAX, ymax = INT32_MIN;
    int32_t band_top = (int32_t)(fr->y0 << SUB), band_bottom = (int32_t)((fr->y0 + fr->rows) << SUB);
    uint32_t y, y_first, y_last;
#if STP_WITH_ZBUFFER
    int64_t plane_c = 0, ddx = 0, ddy = 0, xc = 0, yc = 0, dc = 0;
#endif
    for (i = 0; i < n; i++) {
        if (v[i].y < ymin)
            ymin = v[i].y;
        if (v[i].y > ymax)
            ymax = v[i].y;
    }
    if (ymax <= band_top || ymin >= band_bottom)
        return;
#if STP_WITH_SHADOWS
    if (fr->shadow)
        stp_shadow_polygon(r, at, fr->shadow);
#endif
    /* edges oriented top to bottom, horizontal ones dropped */
    for (i = 0; i < n; i++) {
        const stp_instr *a = &v[i], *b = &v[(i + 1) % n];
        stp_edge *e = &r->edges[ne];
        if (a->y == b->y)
            continue;
        if (a->y > b->y) {
            const stp_instr *swap = a;
            a = b;
            b = swap;
        }
        e->xa = a->x;
        e->ya = a->y;
        e->yb = b->y;
        e->slope = (((int64_t)b->x - a->x) * 65536) / ((int64_t)b->y - a->y);
#if STP_WITH_GOURAUD
        if (smooth) {
            e->sa = a->shade;
            e->shade_slope = (((int64_t)b->shade - a->shade) * 65536) / ((int64_t)b->y - a->y);
        }
#endif
        ne++;
    }
#if STP_WITH_ZBUFFER
    if (use_z) {
        /* depth plane through the projected vertices, by Newell's sums on
         * (x, y, depth): exact for planar polygons, a best fit otherwise */
        int64_t a = 0, b = 0, c = 0, sx = 0, sy = 0, sd = 0;
        for (i = 0; i < n; i++) {
            const stp_instr *p = &v[i == 0 ? n - 1 : i - 1], *q = &v[i];
            int64_t dp = depth_q12(fr, p->z) >> 12, dq = depth_q12(fr, q->z) >> 12;
            a += ((int64_t)p->y - q->y) * (dp + dq);
            b += (dp - dq) * ((int64_t)p->x + q->x);
            c += ((int64_t)p->x - q->x) * ((int64_t)p->y + q->y);
            sx += q->x;
            sy += q->y;
            sd += depth_q12(fr, q->z);
        }
        plane_c = c;
        if (c != 0) {
            /* gradients per subpixel unit with 12 fractional bits */
            ddx = (-a * 4096) / c;
            ddy = (-b * 4096) / c;
            if (ddx > ((int64_t)1 << 40)) ddx = (int64_t)1 << 40;
            if (ddx < -((int64_t)1 << 40)) ddx = -((int64_t)1 << 40);
            if (ddy > ((int64_t)1 << 40)) ddy = (int64_t)1 << 40;
            if (ddy < -((int64_t)1 << 40)) ddy = -((int64_t)1 << 40);
        }
        xc = sx / n;
        yc = sy / n;
        dc = sd / n;
    }
#else
    (void)use_z;
#endif
    /* rows whose centres lie in [ymin, ymax) and in the band */
    y_first = (uint32_t)((ymin < band_top ? band_top : ymin) >> SUB);
    y_last = (uint32_t)((ymax > band_bottom ? band_bottom : ymax) >> SUB);
    if (y_last >= fr->y0 + fr->rows)
        y_last = fr->y0 + fr->rows - 1;
    for (y = y_first; y <= y_last; y++) {
        int32_t yc_row = (int32_t)(y << SUB) + HALF_PIXEL;
        int nc = 0, k;
        for (i = 0; i < ne; i++) {
            const stp_edge *e = &r->edges[i];
            if (e->ya <= yc_row && yc_row < e->yb) {
                stp_crossing c;
                c.x = (int32_t)(e->xa + stp_floordiv64((int64_t)(yc_row - e->ya) * e->slope, 65536));
#if STP_WITH_GOURAUD
                if (smooth)
                    c.shade = (int32_t)(e->sa + stp_floordiv64((int64_t)(yc_row - e->ya) * e->shade_slope, 65536));
#endif
                /* insertion sort: crossings are few */
                for (k = nc; k > 0 && r->crossings[k - 1].x > c.x; k--)
                    r->crossings[k] = r->crossings[k - 1];
                r->crossings[k] = c;
                nc++;
            }
        }
        for (k = 0; k + 1 < nc; k += 2) {
            /* pixels whose centre c satisfies x_left <= c < x_right */
            int64_t xl = r->crossings[k].x, xr = r->crossings[k + 1].x;
            int64_t s0 = 0, sstep = 0;
            int64_t p1 = stp_floordiv64(xl - HALF_PIXEL + (1 << SUB) - 1, 1 << SUB);
            int64_t p2 = stp_floordiv64(xr - HALF_PIXEL + (1 << SUB) - 1, 1 << SUB) - 1;
            if (p1 < 0)
                p1 = 0;
            if (p2 > (int64_t)r->width - 1)
                p2 = (int64_t)r->width - 1;
            if (p1 > p2)
                continue;
#if STP_WITH_GOURAUD
            if (smooth) {
                /* shade along the span from its two crossings, at pixel
                 * centres, with 16 extra fractional bits */
                int64_t sl = r->crossings[k].shade, sr = r->crossings[k + 1].shade;
                int64_t width = xr - xl;
                sstep = width > 0 ? ((sr - sl) * 65536 * (1 << SUB)) / width : 0;
                s0 = sl * 65536 + (width > 0 ? ((sr - sl) * 65536 * ((p1 << SUB) + HALF_PIXEL - xl)) / width : 0);
            }
#endif
#if STP_WITH_ZBUFFER
            if (use_z) {
                int64_t d;
                if (plane_c == 0)
                    continue; /* edge-on: no area on screen */
                d = dc + ddx * (((int64_t)p1 << SUB) + HALF_PIXEL - xc) +
                    ddy * ((int64_t)yc_row - yc);
                put_span_z(fr, y, (uint32_t)p1, (uint32_t)p2, style, d, ddx * (1 << SUB), smooth, s0,
                           sstep, t);
                continue;
            }
#endif
            paint_run(fr, y, (uint32_t)p1, (uint32_t)p2, style, smooth, s0, sstep, t);
        }
    }
}

#if STP_WITH_LINES
/* Bresenham from pixel centre to pixel centre; only the rows of the band. */
static void draw_line(const frame *fr, const stp_instr *a, const stp_instr *b, int style)
{
    int32_t x0 = a->x >> SUB, y0 = a->y >> SUB, x1 = b->x >> SUB, y1 = b->y >> SUB;
    int32_t dx = x1 > x0 ? x1 - x0 : x0 - x1, dy = y1 > y0 ? y0 - y1 : y1 - y0;
    int32_t sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1, err = dx + dy;
    int32_t w = (int32_t)fr->r->width - 1, h = (int32_t)fr->r->height - 1;
    for (;;) {
        int32_t px = x0 > w ? w : x0, py = y0 > h ? h : y0;
        if ((uint32_t)py >= fr->y0 && (uint32_t)py < fr->y0 + fr->rows)
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

/* Walk the visible segments in display order: polygons (unless skip_polygons)
 * and lines, each with the style in force. */
/* pass: which polygons to draw: 0 all, 1 opaque only, 2 transparent only. */
static void replay(const frame *fr, int skip_polygons, int use_z, int pass)
{
    stp_renderer *r = fr->r;
    int s;
    for (s = 0; s < STP_MAX_SEGMENTS; s++) {
        const stp_segment *seg = &r->segments[s];
        int style = r->fill_style, line_style = r->fill_style;
        stp_fix t = 0;
        const stp_instr *pen = 0;
        uint32_t k;
        if (!seg->used || !seg->visible)
            continue;
        for (k = seg->start; k < seg->end; k++) {
            const stp_instr *in = &r->df[k];
            if (in->op >= 3) {
                if (!skip_polygons && (pass == 0 || (pass == 1) == (t == 0)))
                    draw_polygon(fr, k, style, use_z, t);
                k += (uint32_t)in->op - 1;
            } else if (in->op == STP_OP_TRANSPARENCY) {
                t = in->x;
            } else if (in->op == STP_OP_SHADE) {
                style = paint_of(fr, in);
            } else if (in->op == STP_OP_LINE_STYLE) {
                line_style = in->x;
            } else if (in->op == STP_OP_MOVE) {
                pen = in;
            } else if (in->op == STP_OP_LINE) {
#if STP_WITH_LINES
                if (pen)
                    draw_line(fr, pen, in, line_style);
#endif
                pen = in;
            }
            (void)pen; /* read only when lines are compiled in */
        }
        (void)line_style;
    }
}

#if STP_WITH_PAINTER
static int sort_less(const stp_sort_entry *a, const stp_sort_entry *b)
{
    return a->key != b->key ? a->key < b->key : a->index < b->index;
}

/* Heap sort: in place, no recursion, O(n log n); ties by display order so
 * the result does not depend on the sort's own order of work. */
static void sort_entries(stp_sort_entry *e, size_t n)
{
    size_t start = n / 2, end = n;
    while (end > 1) {
        size_t root, child;
        stp_sort_entry t;
        if (start > 0) {
            start--;
        } else {
            end--;
            t = e[0];
            e[0] = e[end];
            e[end] = t;
        }
        root = start;
        while ((child = 2 * root + 1) < end) {
            if (child + 1 < end && sort_less(&e[child], &e[child + 1]))
                child++;
            if (!sort_less(&e[root], &e[child]))
                break;
            t = e[root];
            e[root] = e[child];
            e[child] = t;
            root = child;
        }
    }
}
#endif

/* Collect visible polygons for the painter (sort != NULL: entries keyed by
 * their farthest vertex) and the depth-key range. */
static uint32_t scan_polygons(frame *fr, stp_sort_entry *sort)
{
    stp_renderer *r = fr->r;
    uint32_t count = 0, k;
    int s, i;
    fr->key_min = INT32_MAX;
    fr->key_max = INT32_MIN;
    for (s = 0; s < STP_MAX_SEGMENTS; s++) {
        const stp_segment *seg = &r->segments[s];
        int style = r->fill_style;
        stp_fix t = 0;
        if (!seg->used || !seg->visible)
            continue;
        for (k = seg->start; k < seg->end; k++) {
            const stp_instr *in = &r->df[k];
            if (in->op == STP_OP_SHADE)
                style = paint_of(fr, in);
            if (in->op == STP_OP_TRANSPARENCY)
                t = in->x;
            if (in->op >= 3) {
                int32_t far_key = INT32_MAX;
                for (i = 0; i < in->op; i++) {
                    int32_t z = in[i].z;
                    if (z < far_key)
                        far_key = z;
                    if (z < fr->key_min)
                        fr->key_min = z;
                    if (z > fr->key_max)
                        fr->key_max = z;
                }
                if (sort) {
                    sort[count].index = k;
                    sort[count].key = far_key;
                    sort[count].style = style;
                    sort[count].transmission = t;
                }
                count++;
                k += (uint32_t)in->op - 1;
            }
        }
    }
    return count;
}

int stp_renderer_render(stp_renderer *r, stp_port *port, const stp_output *output,
               const stp_frame_memory *mem)
{
    frame fr;
#if STP_WITH_SHADOWS
    stp_shadow_poly shadow_poly;
#endif
    uint32_t y0, polygons = 0;
    int background_style;
    stp_hidden hidden;
    stp_output default_output;
    if (output == 0) {
        (void)stp_output_default(&default_output);
        output = &default_output;
    }
    if (r == 0 || port == 0 || mem == 0 || port->flush == 0 || mem->band == 0)
        return STP_ERR_ARG;
    if (port->width != r->width || port->height != r->height)
        return STP_ERR_ARG;
    fr.stride = stp_row_bytes(port->format, port->width);
    if (fr.stride == 0 || mem->band_rows < 1 || mem->band_rows > r->height)
        return STP_ERR_ARG;
    if (mem->band_size < fr.stride * mem->band_rows)
        return STP_ERR_MEMORY;
    /* STYLE8 without a table stores the index in a byte: 1..255 */
    if (port->format == STP_PIXEL_STYLE8 && output->styles == 0 && r->levels > 255)
        return STP_ERR_ARG;
    hidden = output->hidden;
    if (hidden == STP_HIDDEN_ZBUFFER) {
#if STP_WITH_ZBUFFER
        if (mem->zbuf == 0 || mem->zbuf_count < (size_t)r->width * mem->band_rows)
            return STP_ERR_MEMORY;
#else
        return STP_ERR_UNSUPPORTED;
#endif
    } else if (hidden == STP_HIDDEN_PAINTER) {
#if STP_WITH_PAINTER
        if (mem->sort == 0 || mem->sort_count < stp_renderer_polygon_count(r))
            return STP_ERR_MEMORY;
#else
        return STP_ERR_UNSUPPORTED;
#endif
    } else if (hidden != STP_HIDDEN_NONE) {
        return STP_ERR_ARG;
    }
    fr.r = r;
    fr.port = port;
    fr.out = output;
    fr.band = mem->band;
    fr.zbuf = mem->zbuf;
#if STP_WITH_SHADOWS
    shadow_poly.count = 0;
    fr.shadow = stp_shadow_any(r) ? &shadow_poly : 0;
#endif
    if (output->cell) {
        fr.cell = output->cell;
    } else {
        (void)stp_cell_bayer(&fr.default_cell, 4);
        fr.cell = &fr.default_cell;
    }
    background_style = stp_intensity_index(output->background, r->levels);
    if (port->format == STP_PIXEL_RGB888 && output->background_colour) {
        int c;
        background_style = STP_COLOUR_FLAG;
        for (c = 0; c < 3; c++)
            background_style |= (stp_intensity_index(output->background_colour[c], r->levels) - 1)
                                << (16 - 8 * c);
    }
    /* port.h: STYLE8 without a table holds 0 where nothing is drawn and the
     * background is 0 (style_code passes 0 through) */
    if (port->format == STP_PIXEL_STYLE8 && output->styles == 0 && output->background <= 0)
        background_style = 0;

    polygons = scan_polygons(&fr, hidden == STP_HIDDEN_PAINTER ? mem->sort : 0);
    (void)polygons; /* read only by the painter's sort */
#if STP_WITH_PAINTER
    if (hidden == STP_HIDDEN_PAINTER)
        sort_entries(mem->sort, polygons);
#endif

    for (y0 = 0; y0 < r->height; y0 += mem->band_rows) {
        uint32_t y;
        fr.y0 = y0;
        fr.rows = r->height - y0 < mem->band_rows ? r->height - y0 : mem->band_rows;
        for (y = y0; y < y0 + fr.rows; y++) {
            /* MONO1 padding bits past the width reach the port too: make
             * them 0 rather than whatever the caller's buffer held */
            if (port->format == STP_PIXEL_MONO1)
                fr.band[(size_t)(y - y0) * fr.stride + fr.stride - 1] = 0;
            put_span(&fr, y, 0, r->width - 1, background_style);
        }
#if STP_WITH_ZBUFFER
        if (hidden == STP_HIDDEN_ZBUFFER) {
            size_t i, n = (size_t)r->width * fr.rows;
            for (i = 0; i < n; i++)
                fr.zbuf[i] = 0; /* farther than any polygon (they map to >= 1) */
        }
#endif
#if STP_WITH_PAINTER
        if (hidden == STP_HIDDEN_PAINTER) {
            uint32_t i;
            for (i = 0; i < polygons; i++)
                draw_polygon(&fr, mem->sort[i].index, mem->sort[i].style, 0, mem->sort[i].transmission);
            replay(&fr, 1, 0, 0); /* lines on top, in display order */
        } else
#endif
        {
            if (hidden == STP_HIDDEN_ZBUFFER) {
                /* opaque first, then the transparent ones over them */
                replay(&fr, 0, 1, 1);
                replay(&fr, 0, 1, 2);
            } else {
                replay(&fr, 0, 0, 0);
            }
        }
        if (port->flush(port, y0, fr.rows, fr.band, fr.stride) < 0)
            return STP_ERR_PORT;
    }
    return STP_OK;
}
