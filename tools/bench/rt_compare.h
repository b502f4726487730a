/* SPDX-License-Identifier: MIT */
/*
 * The ray tracer against its double-precision reference, and its speed
 * (host only).  Used by tests/raytrace, by the error-against-run-time
 * bench (one row per numeric configuration) and by `stipple bench`.
 *
 * Error: every pixel of a scene is traced by the core (stp_rt_trace_pixel,
 * through stp_tool_rt_build) and by tools/bench/raytrace_ref.c given the
 * very inputs the core got (its stp_fix view, lighting, materials and
 * object coordinates converted to double), so what differs is the core's
 * arithmetic.  Grey only.  Shadow rays leaving a patch pass its
 * neighbouring facets in both (ref_rt_set_smooth_shadows).
 */
#ifndef STIPPLE_TOOLS_BENCH_RT_COMPARE_H
#define STIPPLE_TOOLS_BENCH_RT_COMPARE_H

#include <stdio.h>

#include "render_scene.h"
#include "scene.h"

typedef struct stp_rt_error {
    long pixels;          /* traced */
    double max, mean;     /* |core - reference| shade, over all pixels */
    int max_x, max_y;     /* where the largest one is */
    long above_step;      /* pixels off by more than 1/30 (half a step of 16
                             levels): a different object seen, mostly at
                             silhouettes and shadow edges */
    long style_differs;   /* pixels whose INTENSITY index (opt->levels)
                             differs */
} stp_rt_error;

/* Compare core and reference over the whole opt->width x opt->height frame
 * of scene (opt->raytrace settings: depth, min weight, hierarchy).  When
 * shades is not NULL it receives the core's and the reference's grey
 * shades (2 * width * height doubles: core first).  Returns 0, or -1 with a
 * message in err. */
int stp_rt_compare(const stp_scene *scene, const stp_tool_options *opt, stp_rt_error *e,
                   double *shades, char *err, size_t err_size);

/* Speed of one scene: the hierarchy's build time, and the best frame time
 * over repeated renders (GREY8, whole frame, no output) within about
 * budget seconds, with rays (primary + secondary) and shadow rays per
 * frame. */
typedef struct stp_rt_speed {
    double build_us, frame_us;
    unsigned long rays, shadow_rays, box_tests, object_tests, objects;
} stp_rt_speed;
int stp_rt_time(const stp_scene *scene, const stp_tool_options *opt, double budget,
                stp_rt_speed *s, char *err, size_t err_size);

/* `stipple bench`: the table of rays per second and us per frame, with and
 * without the hierarchy, and the error against the reference, for the
 * named scenes (files in scenes_dir) at the options' size.  Returns 0, or
 * -1 with a message on stderr. */
int stp_rt_bench(FILE *out, const char *scenes_dir, const char *const *names, int count,
                 const stp_tool_options *opt, double budget);

#endif
