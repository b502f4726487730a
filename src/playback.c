/* SPDX-License-Identifier: MIT */
/* A renderer over a ready display file, for playback only (playback.h):
 * the data checked once, then only the fields stp_renderer_render reads
 * are set. */
#include "stipple/playback.h"
#include "renderer_state.h"

/* A point of a MOVE, LINE or polygon entry: x, y on the device (Q27.4,
 * 0..side << 4, as the entry side's projection clamps them, or up to gx
 * and gy beyond either end: a polygon's with the guard band of compact
 * builds, project_private.h, which the raster clamps; 0 for a line's,
 * which the renderer clips to the picture), z a depth key (perspective
 * (0, 2^30], parallel -z_view, below 0). */
static int point_ok(const stp_instr *in, uint32_t width, uint32_t height, int32_t gx, int32_t gy)
{
    return in->x >= -gx && in->x <= (int32_t)(width << STP_SUBPIXEL_BITS) + gx && in->y >= -gy &&
           in->y <= (int32_t)(height << STP_SUBPIXEL_BITS) + gy && in->z > INT32_MIN &&
           in->z <= ((int32_t)1 << 30);
}

/* A style index of SHADE or LINE_STYLE: 1..256 (indices above the
 * renderer's levels show as its top style). */
static int style_ok(int32_t x)
{
    return x >= 1 && x <= 256;
}

#if STP_WITH_GOURAUD
/* The vertex shades of a polygon: all -1 (flat) or all in [0, 1] (smooth). */
static int shades_ok(const stp_instr *v, int32_t n)
{
    int32_t i;
    for (i = 0; i < n; i++)
        if (v[0].shade < 0 ? v[i].shade != -1 : (v[i].shade < 0 || v[i].shade > STP_FIX_ONE))
            return 0;
    return 1;
}
#endif

/* The polygon whose header is df[k]: its size (clipping may add up to 5
 * vertices to an entered polygon: STP_CLIP_VERTICES, what the scan
 * converter's arrays hold), its vertices inside the data and on the
 * device. */
static int polygon_ok(const stp_instr *df, uint32_t k, uint32_t used, uint32_t width,
                      uint32_t height)
{
    int32_t n = df[k].op, i;
    if (n > STP_CLIP_VERTICES || (uint32_t)n > used - k)
        return 0;
    for (i = 0; i < n; i++)
        if ((i > 0 && df[k + (uint32_t)i].op != STP_OP_LINE) ||
            !point_ok(&df[k + (uint32_t)i], width, height, stp_guard_subpixels(width), stp_guard_subpixels(height)))
            return 0;
#if STP_WITH_GOURAUD
    return shades_ok(&df[k], n);
#else
    return 1;
#endif
}

/* One entry other than a polygon. */
static int entry_ok(const stp_instr *in, uint32_t width, uint32_t height)
{
    switch (in->op) {
    case STP_OP_MOVE:
    case STP_OP_LINE: return point_ok(in, width, height, 0, 0);
    case STP_OP_SHADE:
        return style_ok(in->x) && in->y >= 0 && in->y <= STP_FIX_ONE &&
               (in->z == 0 || (in->z & ~(int32_t)0x00FFFFFF) == STP_COLOUR_FLAG);
    case STP_OP_LINE_STYLE: return style_ok(in->x);
    case STP_OP_TRANSPARENCY: return in->x >= 0 && in->x <= STP_FIX_ONE;
    case STP_OP_LIGHT_TERM: return 1; /* read only with a shadow map, never here */
    default: return 0;
    }
}

int stp_playback_check(const stp_instr *display_file, uint32_t used, uint32_t width,
                       uint32_t height, uint32_t *bad)
{
    uint32_t k;
    if (display_file == 0 || used == 0 || width < 1 || height < 1 || width > 32767 ||
        height > 32767)
        return STP_ERR_ARG;
    for (k = 0; k < used; k++) {
        const stp_instr *in = &display_file[k];
        int ok = in->op >= 3 ? polygon_ok(display_file, k, used, width, height)
                             : entry_ok(in, width, height);
        if (!ok) {
            if (bad)
                *bad = k;
            return STP_ERR_ARG;
        }
        if (in->op >= 3)
            k += (uint32_t)in->op - 1;
    }
    return STP_OK;
}

stp_renderer *stp_playback_create(void *mem, size_t mem_size, const stp_instr *display_file,
                                  uint32_t used, uint32_t width, uint32_t height, int levels,
                                  int fill_style)
{
    stp_renderer *r = (stp_renderer *)mem;
    int i;
    if (mem == 0 || mem_size < sizeof(stp_renderer) || levels < 2 || levels > 256 ||
        fill_style < 1 || fill_style > levels ||
        stp_playback_check(display_file, used, width, height, 0) != STP_OK)
        return 0;
    /* stp_renderer_render never writes through df: the const data stays unwritten */
    r->df = (stp_instr *)(uintptr_t)display_file;
    r->capacity = r->used = used;
    r->width = width;
    r->height = height;
    for (i = 0; i < STP_MAX_SEGMENTS; i++)
        r->segments[i].used = 0;
    r->segments[0].used = 1;
    r->segments[0].open = 0;
    r->segments[0].visible = 1;
    r->segments[0].pixel_culled = 0; /* unknown here (render.h) */
    r->segments[0].id = 1;
    r->segments[0].start = 0;
    r->segments[0].end = used;
    r->open_segment = -1;
    r->levels = levels;
    r->fill_style = fill_style;
    stp_pattern_keep_forget(r);
#if STP_WITH_SHADOWS
    for (i = 0; i < STP_MAX_LIGHTS; i++)
        r->shadow[i].depth = 0;
#endif
    return r;
}

#if STP_PLAYBACK_ONLY
/* render.c is not built in a playback-only core: its two queries a
 * playback program may still ask (render.h) */
typedef char stp_playback_renderer_bound[sizeof(stp_renderer) <= STP_RENDERER_BYTES ? 1 : -1];

size_t stp_renderer_size(void)
{
    return sizeof(stp_renderer);
}

uint32_t stp_renderer_display_file_used(const stp_renderer *r)
{
    return r->used;
}
#endif
