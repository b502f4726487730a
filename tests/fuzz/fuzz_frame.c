/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer target: from the bytes of a scene file to a finished frame, as
 * `stipple render` goes: stp_scene_parse (NFF, OBJ, OFF or PLY), then
 * stp_tool_render (scene preparation: rescaling, light merging, polygon
 * splitting; the polygon renderer) and stp_tool_raytrace (the ray tracer),
 * at a small size.  The first byte picks the format (bits 0-1) and the
 * options (hidden-surface method, smooth shading, colour, shadow maps,
 * edge anti-aliasing, outlines, parallel projection, lights given on the
 * command line, --no-rescale); the rest is the file.  Beyond the
 * sanitizers: every call returns 0 or -1, a failure comes with a message,
 * and a finished frame has every row delivered.  The scene budget is
 * lowered (256 KiB) and spheres and cones tessellated coarsely, so an input
 * of a few KB cannot take the fuzzer's memory or time.
 */
#include <string.h>

#include "fuzz_common.h"
#include "render_scene.h"
#include "scene.h"
#include "scene_private.h"
#include "stp_posix.h"

#define FZ_W 24
#define FZ_H 16

static const char *const formats[4] = {"nff", "obj", "off", "ply"};

static void options(uint8_t a, uint8_t b, stp_tool_options *opt)
{
    stp_tool_options_default(opt);
    opt->width = FZ_W;
    opt->height = FZ_H;
    opt->hidden = (stp_hidden)((a >> 2) % 3);
    opt->smooth = (a >> 4) & 1;
    opt->colour = (a >> 5) & 1;
    opt->shadow_resolution = (a >> 6) & 1 ? 16u : 0u;
    opt->edge_aa = (a >> 7) & 1;
    opt->outlines = b & 3;
    opt->perspective = !((b >> 2) & 1);
    opt->keep_units = (b >> 3) & 1;
    opt->band_rows = (b >> 4) & 1 ? 5 : 0;
    opt->backface_removal = (b >> 5) & 1;
    if ((b >> 6) & 1) {
        int k;
        opt->light_count = 1 + b % STP_MAX_LIGHTS;
        for (k = 0; k < opt->light_count; k++) {
            opt->lights[k].x = k - 2;
            opt->lights[k].y = 3 + k;
            opt->lights[k].z = 4 - k;
        }
    }
}

/* One render (raytrace: the ray tracer) of scene into a fresh frame. */
static void one_frame(const stp_scene *scene, const stp_tool_options *opt, int raytrace)
{
    stp_posix_frame f;
    stp_tool_options o = *opt;
    char err[512];
    int rc;

    FZ_CHECK(stp_posix_frame_init(&f, FZ_W, FZ_H, o.colour ? STP_PIXEL_RGB888 : STP_PIXEL_GREY8) == 0,
             "frame");
    err[0] = 0;
    if (raytrace) {
        o.raytrace = 1;
        o.outlines = 0;
        o.keep_units = 0;
        o.shadow_resolution = 0;
        o.rt_depth = 2;
        rc = stp_tool_raytrace(scene, &o, stp_posix_frame_port(&f), NULL, err, sizeof err);
    } else {
        rc = stp_tool_render(scene, &o, stp_posix_frame_port(&f), NULL, err, sizeof err);
    }
    FZ_CHECK(rc == 0 || rc == -1, "returned %d", rc);
    if (rc == 0)
        FZ_CHECK(f.rows_filled == FZ_H, "a finished frame of %u rows", (unsigned)f.rows_filled);
    else
        FZ_CHECK(err[0] != 0 && strnlen(err, sizeof err) < sizeof err, "a failure without a message");
    stp_posix_frame_free(&f);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    stp_scene_options sopt;
    stp_tool_options opt;
    stp_scene scene;
    char err[256];
    uint8_t a, b;

    if (size < 2)
        return 0;
    a = data[0];
    b = data[1];
    stp_scene_byte_limit = (size_t)1 << 18;
    stp_scene_options_default(&sopt);
    sopt.sphere_slices = 6;
    sopt.sphere_stacks = 4;
    sopt.cone_slices = 6;
    if (stp_scene_parse((const char *)data + 2, size - 2, formats[a & 3], "fuzz", &sopt, &scene, err,
                        sizeof err) != 0)
        return 0;
    options(a, b, &opt);
    one_frame(&scene, &opt, 0);
    one_frame(&scene, &opt, 1);
    stp_scene_free(&scene);
    return 0;
}
