/* SPDX-License-Identifier: MIT */
/* An animation of a scene: see animate.h. */
#include "animate.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tone.h"

void stp_tool_animation_defaults(stp_tool_options *opt)
{
    if (!opt->dither_given)
        opt->dither = STP_TOOL_DITHER_BLUE_NOISE;
    if (!opt->levels_given)
        opt->levels = 256;
    if (!opt->exposure_given)
        opt->exposure_auto = 1;
    if (!opt->hold_given)
        opt->hold = STP_TOOL_DEFAULT_HOLD;
}

int stp_tool_animation_gain(const stp_scene *scene, const stp_tool_options *opt,
                            const stp_tool_motion *motion, double *gain, char *err, size_t err_size)
{
    int samples = motion->frames < 16 ? motion->frames : 16, s;
    *gain = 0;
    for (s = 0; s < samples; s++) {
        int frame = (int)((long)s * motion->frames / samples);
        stp_tool_camera_scene moved;
        stp_tool_options still;
        double g;
        int rc;
        if (stp_tool_camera_apply(scene, opt, motion, frame, &moved, &still, err, err_size) != 0)
            return -1;
        rc = stp_tool_exposure_gain(&moved.scene, &still, &g, err, err_size);
        stp_tool_camera_free(&moved);
        if (rc != 0)
            return -1;
        if (s == 0 || g < *gain)
            *gain = g;
    }
    return 0;
}

unsigned long stp_tool_changed_pixels(const stp_posix_frame *a, const stp_posix_frame *b)
{
    unsigned long changed = 0;
    uint32_t x, y;
    for (y = 0; y < a->height; y++) {
        const uint8_t *ra = a->pixels + (size_t)y * a->stride, *rb = b->pixels + (size_t)y * b->stride;
        for (x = 0; x < a->width; x++) {
            int mask = 0x80 >> (x & 7);
            changed += ((ra[x >> 3] ^ rb[x >> 3]) & mask) != 0;
        }
    }
    return changed;
}

int stp_tool_animation_holds(const stp_tool_options *opt)
{
    stp_cell cell;
    return opt->hold > 0 && opt->dither != STP_TOOL_DITHER_DIFFUSE && !opt->edge_aa &&
           stp_tool_cell(opt, &cell) == 0 && cell.kind == STP_CELL_THRESHOLD;
}

void stp_tool_halftone_held(const stp_posix_frame *grey, const stp_cell *cell, int hold,
                            const stp_posix_frame *before, stp_posix_frame *out)
{
    const uint8_t *table = stp_cell_table(cell);
    uint32_t x, y;
    for (y = 0; y < grey->height; y++) {
        const uint8_t *g = grey->pixels + (size_t)y * grey->stride;
        const uint8_t *was = before ? before->pixels + (size_t)y * before->stride : NULL;
        const uint8_t *row = table + (y % cell->height) * cell->width;
        uint8_t *o = out->pixels + (size_t)y * out->stride;
        for (x = 0; x < grey->width; x++) {
            int t = row[x % cell->width], bit = 0x80 >> (x & 7), on = g[x] > t;
            if (was && hold > 0)
                on = (was[x >> 3] & bit) ? g[x] > t - hold : g[x] > t + hold;
            o[x >> 3] = (uint8_t)(on ? o[x >> 3] | bit : o[x >> 3] & ~bit);
        }
    }
}

/* Render frame `index` of the animation into frame (MONO1); with a hold,
 * through grey (GREY8) and the frame before. */
static int draw_frame(const stp_scene *scene, const stp_tool_options *opt, const stp_tool_motion *motion,
                      int index, stp_posix_frame *frame, stp_posix_frame *grey,
                      const stp_posix_frame *before, char *err, size_t err_size)
{
    stp_tool_camera_scene moved;
    stp_tool_options still;
    stp_cell cell;
    char why[400];
    int rc;
    if (stp_tool_camera_apply(scene, opt, motion, index, &moved, &still, err, err_size) != 0)
        return -1;
    rc = stp_tool_render(&moved.scene, &still, stp_posix_frame_port(grey ? grey : frame), 0, why, sizeof why);
    stp_tool_camera_free(&moved);
    if (rc != 0) {
        snprintf(err, err_size, "frame %d: %s", index + 1, why);
        return rc;
    }
    if (grey && stp_tool_cell(opt, &cell) == 0)
        stp_tool_halftone_held(grey, &cell, opt->hold, before, frame);
    return 0;
}

int stp_tool_animate(const stp_scene *scene, const stp_tool_options *opt,
                     const stp_tool_motion *motion, stp_tool_frame_sink sink, void *ctx,
                     stp_tool_animation_stats *stats, char *err, size_t err_size)
{
    stp_tool_options each = *opt;
    stp_tool_animation_stats local;
    stp_posix_frame frames[2], grey;
    int holding = stp_tool_animation_holds(opt);
    double total = 0, pixels = (double)opt->width * opt->height;
    int i, rc = -1;
    if (!stats)
        stats = &local;
    memset(stats, 0, sizeof *stats);
    stats->gain = 1;
    if (opt->exposure_auto) {
        if (stp_tool_animation_gain(scene, opt, motion, &stats->gain, err, err_size) != 0)
            return -1;
        each.exposure_auto = 0;
        each.brightness *= stats->gain;
    }
    if (stp_posix_frame_init(&frames[0], (uint32_t)opt->width, (uint32_t)opt->height, STP_PIXEL_MONO1) != 0)
        goto no_memory;
    if (stp_posix_frame_init(&frames[1], (uint32_t)opt->width, (uint32_t)opt->height, STP_PIXEL_MONO1) != 0) {
        stp_posix_frame_free(&frames[0]);
        goto no_memory;
    }
    if (holding && stp_posix_frame_init(&grey, (uint32_t)opt->width, (uint32_t)opt->height, STP_PIXEL_GREY8) != 0) {
        stp_posix_frame_free(&frames[0]);
        stp_posix_frame_free(&frames[1]);
        goto no_memory;
    }
    for (i = 0; i < motion->frames; i++) {
        stp_posix_frame *now = &frames[i & 1], *before = &frames[!(i & 1)];
        if (draw_frame(scene, &each, motion, i, now, holding ? &grey : NULL, i ? before : NULL, err,
                       err_size) != 0 ||
            sink(now, i, ctx, err, err_size) != 0)
            goto done;
        if (i > 0) {
            double share = (double)stp_tool_changed_pixels(now, before) / pixels;
            total += share;
            if (share > stats->max_changed)
                stats->max_changed = share;
        }
        stats->frames = i + 1;
    }
    stats->mean_changed = motion->frames > 1 ? total / (motion->frames - 1) : 0;
    rc = 0;
done:
    if (holding)
        stp_posix_frame_free(&grey);
    stp_posix_frame_free(&frames[0]);
    stp_posix_frame_free(&frames[1]);
    return rc;
no_memory:
    snprintf(err, err_size, "out of memory for the frames");
    return -1;
}
