/* SPDX-License-Identifier: MIT */
/* The methods the quality bench (quality.c) compares: either options of a
 * render (setup) or a dither applied to the ideal picture (on_ideal). */
#ifndef STIPPLE_BENCH_QUALITY_METHODS_H
#define STIPPLE_BENCH_QUALITY_METHODS_H

#include <stddef.h>
#include "render_scene.h"

typedef struct qm_method {
    const char *name;
    void (*setup)(stp_tool_options *opt); /* NULL: the defaults; its tone
                                             (tone.h) shapes the ideal too */
    /* ideal[w*h] in [0, 1] -> bits[w*h] 0/1; NULL for a render */
    void (*on_ideal)(const double *ideal, int w, int h, unsigned char *bits);
} qm_method;

/* Names of the still default (stipple render to PBM: Floyd-Steinberg at
 * 256 levels with automatic exposure) and of Floyd-Steinberg applied to
 * the ideal of the same tone, which the bench compares. */
#define QM_STILL_DEFAULT "still default"
#define QM_IDEAL_FS "still ideal + fs"
/* The still default without its automatic silhouettes (readable.h): the
 * diffusion the ratio "still / ideal+fs" holds to Floyd-Steinberg on the
 * ideal (lines are drawn for the eye and are not in the ideal). */
#define QM_STILL_NO_LINES "still, no auto lines"

/* Method 0 is the default render (the cost ratios' base). */
size_t qm_method_count(void);
const qm_method *qm_method_at(size_t i);

#endif
