/* SPDX-License-Identifier: MIT */
/* Playing back a static scene (stp_scene_data.h, stp_scene_static). */
#include "stp_scene_data.h"

int stp_scene_static_open(const stp_scene_static *s, void *mem, size_t mem_size,
                          stp_renderer **out)
{
    *out = stp_playback_create(mem, mem_size, s->display_file, s->display_used, s->width,
                               s->height, s->levels, s->fill_style);
    return *out ? STP_OK : STP_ERR_ARG;
}

void stp_scene_static_output(const stp_scene_static *s, stp_output *out)
{
    out->hidden = s->hidden;
    out->cell = s->cell;
    out->gamma = s->gamma;
    out->styles = 0;
    out->background = s->background;
    out->background_colour = 0;
    out->diffusion = 0; /* a static scene is not diffused */
    out->edge_aa = 0;   /* compiled scenes: STP_WITH_EDGE_AA 0 */
}
