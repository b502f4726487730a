/* SPDX-License-Identifier: MIT */
/* A renderer over a ready display file, for playback only (playback.h):
 * only the fields stp_renderer_render reads are set. */
#include "stipple/playback.h"
#include "render_private.h"

stp_renderer *stp_playback_create(void *mem, size_t mem_size, const stp_instr *display_file,
                                  uint32_t used, uint32_t width, uint32_t height, int levels,
                                  int fill_style)
{
    stp_renderer *r = (stp_renderer *)mem;
    int i;
    if (mem == 0 || mem_size < sizeof(stp_renderer) || display_file == 0 || used == 0 ||
        width < 1 || height < 1 || width > 32767 || height > 32767 || levels < 2 ||
        levels > 256 || fill_style < 1 || fill_style > levels)
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
    r->segments[0].id = 1;
    r->segments[0].start = 0;
    r->segments[0].end = used;
    r->open_segment = -1;
    r->levels = levels;
    r->fill_style = fill_style;
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
