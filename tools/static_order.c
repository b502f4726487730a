/* SPDX-License-Identifier: MIT */
/* A Z-buffer-exact painter's order for a static scene (static_order.h). */
#include "static_order.h"

#include <stdlib.h>
#include <string.h>

#define MAX_POLYGONS 255 /* ids are STYLE8 style indices 1..255 */
#define NO_SHADE UINT32_MAX

typedef struct polygon {
    uint32_t at, n;   /* header entry, entries */
    uint32_t shade;   /* the STP_OP_SHADE in force, or NO_SHADE */
} polygon;

/* The polygons of df, or -1 when it holds anything but polygons and SHADEs. */
static int collect(const stp_instr *df, uint32_t used, polygon *p, uint32_t *count)
{
    uint32_t k = 0, shade = NO_SHADE;
    *count = 0;
    while (k < used) {
        if (df[k].op == STP_OP_SHADE) {
            shade = k++;
        } else if (df[k].op >= 3 && (uint32_t)df[k].op <= used - k) {
            if (*count == MAX_POLYGONS)
                return -1;
            p[*count].at = k;
            p[*count].n = (uint32_t)df[k].op;
            p[*count].shade = shade;
            ++*count;
            k += (uint32_t)df[k].op;
        } else {
            return -1;
        }
    }
    return 0;
}

typedef struct picture {
    uint8_t *pixels;
    uint32_t width;
} picture;

static int keep_rows(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                     size_t stride)
{
    picture *pic = port->user;
    uint32_t y;
    for (y = 0; y < rows; y++)
        memcpy(pic->pixels + (size_t)(y0 + y) * pic->width, pixels + (size_t)y * stride, pic->width);
    return 0;
}

/* STYLE8 picture of df[0, used) with 255 levels: each pixel the style index
 * in force for the polygon drawn there, 0 where none is.  Returns 0 or -1. */
static int render_styles(const stp_instr *df, uint32_t used, uint32_t width, uint32_t height,
                         stp_hidden hidden, uint8_t *pixels)
{
    void *mem = malloc(stp_renderer_size());
    uint8_t *band = malloc(width);
    uint16_t *zbuf = malloc(width * sizeof *zbuf);
    stp_renderer *r;
    stp_port port;
    stp_output out;
    stp_frame_memory fm;
    picture pic;
    int status = -1;
    if (!mem || !band || !zbuf)
        goto done;
    r = stp_playback_create(mem, stp_renderer_size(), df, used, width, height, 255, 1);
    if (!r)
        goto done;
    memset(&out, 0, sizeof out);
    out.hidden = hidden;
    memset(&fm, 0, sizeof fm);
    fm.band = band;
    fm.band_size = width;
    fm.band_rows = 1;
    fm.zbuf = zbuf;
    fm.zbuf_count = width;
    pic.pixels = pixels;
    pic.width = width;
    port.width = width;
    port.height = height;
    port.format = STP_PIXEL_STYLE8;
    port.flush = keep_rows;
    port.user = &pic;
    status = stp_renderer_render(r, &port, &out, &fm) == STP_OK ? 0 : -1;
done:
    free(mem);
    free(band);
    free(zbuf);
    return status;
}

/* The polygons listed in which[0, n), polygon which[i] drawn in style i+1. */
static uint32_t id_file(const stp_instr *df, const polygon *p, const uint32_t *which, uint32_t n,
                        stp_instr *out)
{
    uint32_t i, k = 0;
    for (i = 0; i < n; i++) {
        const polygon *q = &p[which[i]];
        memset(&out[k], 0, sizeof out[k]);
        out[k].op = STP_OP_SHADE;
        out[k].x = (int32_t)i + 1;
        k++;
        memcpy(&out[k], &df[q->at], q->n * sizeof *out);
        k += q->n;
    }
    return k;
}

/* Kahn's algorithm over after[a * n + b] (a must follow b) for the
 * polygons with wins[a], the earliest in the display file first among those
 * free: order[0, *placed).  0 on a cycle. */
static int order_polygons(const uint8_t *after, const uint8_t *wins, uint32_t n, uint32_t *order,
                          uint32_t *placed_out)
{
    uint32_t placed, a, b, total = 0;
    uint8_t *done = calloc(n ? n : 1, 1);
    if (!done)
        return -1;
    for (a = 0; a < n; a++) {
        done[a] = !wins[a];
        total += wins[a];
    }
    *placed_out = total;
    for (placed = 0; placed < total; placed++) {
        for (a = 0; a < n; a++) {
            int free_now = !done[a];
            for (b = 0; b < n && free_now; b++)
                if (after[(size_t)a * n + b] && !done[b])
                    free_now = 0;
            if (free_now)
                break;
        }
        if (a == n) {
            free(done);
            return 0;
        }
        done[a] = 1;
        order[placed] = a;
    }
    free(done);
    return 1;
}

int stp_tool_static_order(const stp_instr *df, uint32_t used, uint32_t width, uint32_t height,
                          stp_instr **out, uint32_t *out_used)
{
    size_t area = (size_t)width * height;
    polygon *p = malloc(MAX_POLYGONS * sizeof *p);
    stp_instr *ids = malloc((used + MAX_POLYGONS) * sizeof *ids), *res = 0;
    uint8_t *winner = malloc(area), *cover = malloc(area), *want = malloc(area), *got = malloc(area);
    uint8_t *after = 0, wins[MAX_POLYGONS];
    uint32_t *order = malloc(MAX_POLYGONS * sizeof *order), n, i, k, placed = 0;
    uint32_t last_shade = NO_SHADE;
    size_t px;
    int result = -1, found;

    *out = 0;
    *out_used = 0;
    if (!p || !ids || !winner || !cover || !want || !got || !order)
        goto done;
    result = 0;
    if (collect(df, used, p, &n) != 0 || n == 0)
        goto done;
    result = -1;
    after = calloc((size_t)n * n, 1);
    res = malloc(used * 2 * sizeof *res);
    if (!after || !res)
        goto done;
    /* who wins each pixel under the Z buffer (polygons in display order) */
    for (i = 0; i < n; i++)
        order[i] = i;
    k = id_file(df, p, order, n, ids);
    if (render_styles(ids, k, width, height, STP_HIDDEN_ZBUFFER, winner) != 0)
        goto done;
    /* a polygon that wins no pixel is hidden everywhere: it is left out
     * (it constrains nothing); each other one alone: it must come before the
     * winner of every pixel it covers */
    memset(wins, 0, n);
    for (px = 0; px < area; px++)
        if (winner[px])
            wins[winner[px] - 1u] = 1;
    for (i = 0; i < n; i++) {
        if (!wins[i])
            continue;
        k = id_file(df, p, &i, 1, ids);
        if (render_styles(ids, k, width, height, STP_HIDDEN_NONE, cover) != 0)
            goto done;
        for (px = 0; px < area; px++)
            if (cover[px] && winner[px] && winner[px] - 1u != i)
                after[(size_t)(winner[px] - 1u) * n + i] = 1;
    }
    found = order_polygons(after, wins, n, order, &placed);
    result = found < 0 ? -1 : 0;
    if (found <= 0)
        goto done;
    /* the polygons in that order, each after the SHADE in force for it */
    k = 0;
    for (i = 0; i < placed; i++) {
        const polygon *q = &p[order[i]];
        if (q->shade == NO_SHADE && i > 0)
            goto done; /* its style is the renderer's initial one: only first */
        if (q->shade != NO_SHADE &&
            (last_shade == NO_SHADE || memcmp(&df[q->shade], &df[last_shade], sizeof *df) != 0)) {
            res[k++] = df[q->shade];
            last_shade = q->shade;
        }
        memcpy(&res[k], &df[q->at], q->n * sizeof *res);
        k += q->n;
    }
    /* the proof: the same styles everywhere as the Z buffer's */
    if (render_styles(df, used, width, height, STP_HIDDEN_ZBUFFER, want) != 0 ||
        render_styles(res, k, width, height, STP_HIDDEN_NONE, got) != 0)
        goto done;
    if (memcmp(want, got, area) != 0)
        goto done;
    *out = res;
    *out_used = k;
    res = 0;
    result = 1;
done:
    free(p);
    free(ids);
    free(winner);
    free(cover);
    free(want);
    free(got);
    free(after);
    free(order);
    free(res);
    return result;
}
