/* SPDX-License-Identifier: MIT */
/*
 * stipple quality bench (issue 14): how far a 1-bit picture is from what it
 * stands for, per shared scene x method x size, beside what the method
 * costs and how much of the picture flickers when the model turns.
 *
 * The ideal: stipple's own render at 4x the size with 256 levels to 8-bit
 * grey, box-filtered 4x4 down to the size (values in [0, 1]).
 * The error: mean absolute difference between the 1-bit picture (ON = 1)
 * and the ideal, both blurred by a Gaussian of sigma 1.5 pixels (the eye;
 * taps to 3 sigma, weights renormalised over the taps inside the frame).
 * The flicker: the share of pixels that differ between the picture of the
 * scene and that of the scene turned by one degree about the view's up axis
 * through its look-at point (lights stay put).
 * The cost: counted by tools/bench/quality_cost.sh (callgrind instructions
 * inside stp_renderer_render, one --once render per method, scene and size); with
 * --time, also wall time of one render with the method over that of the
 * first, in rounds that interleave them (the median ratio; a busy machine
 * blurs it).  "Applied to the ideal" methods have no cost figure.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "quality_methods.h"
#include "render_scene.h"
#include "scene.h"
#include "tone.h"
#include "stipple/stipple.h"

#ifndef STP_BENCH_SCENES_DIR
#define STP_BENCH_SCENES_DIR "../shared/scenes"
#endif

static const char *const scene_names[] = {"tetra-s1", "tetra-s2", "mount-s2", "teapot-s1",
                                          "teapot-s2", "gears-s1", "balls-s1", "balls-s2"};
#define SCENE_COUNT (sizeof scene_names / sizeof scene_names[0])

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* ---- a port that keeps the whole frame ---- */

typedef struct frame {
    stp_port port;
    uint8_t *px;
    size_t stride;
} frame;

static int frame_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    frame *f = (frame *)port->user;
    uint32_t r;
    for (r = 0; r < rows; r++)
        memcpy(f->px + (size_t)(y0 + r) * f->stride, pixels + (size_t)r * stride, f->stride);
    return 0;
}

static int frame_init(frame *f, int w, int h, stp_pixel_format format)
{
    memset(f, 0, sizeof *f);
    f->stride = stp_row_bytes(format, (uint32_t)w);
    f->px = calloc(f->stride, (size_t)h);
    f->port.width = (uint32_t)w;
    f->port.height = (uint32_t)h;
    f->port.format = format;
    f->port.flush = frame_flush;
    f->port.user = f;
    return f->px ? 0 : -1;
}

/* ---- the ideal ---- */

/* 256-level grey render at 4x, box-filtered: ideal[w*h] in [0, 1]. */
static int render_ideal(const stp_scene *scene, const qm_method *m, int w, int h, double *ideal)
{
    stp_tool_options opt;
    frame f;
    char err[256];
    int x, y, i, j;
    stp_tool_options_default(&opt);
    /* the method's tone (exposure, grey from colour, background) is part
     * of what its picture stands for */
    if (m && m->setup)
        m->setup(&opt);
    opt.dither = STP_TOOL_DITHER_BAYER4;
    opt.band_rows = 0;
    if (opt.exposure_auto) {
        /* the picture's exposure, found at the picture's size */
        double gain;
        opt.width = w;
        opt.height = h;
        if (stp_tool_exposure_gain(scene, &opt, &gain, err, sizeof err) != 0) {
            fprintf(stderr, "bench_quality: exposure %dx%d: %s\n", w, h, err);
            return -1;
        }
        opt.brightness *= gain;
        opt.exposure_auto = 0;
    }
    opt.width = 4 * w;
    opt.height = 4 * h;
    opt.levels = 256;
    opt.outlines = 0; /* lines are drawn for the eye, not part of the scene (exposure kept) */
    if (frame_init(&f, opt.width, opt.height, STP_PIXEL_GREY8) != 0)
        return -1;
    if (stp_tool_render(scene, &opt, &f.port, 0, err, sizeof err) != 0) {
        fprintf(stderr, "bench_quality: ideal %dx%d: %s\n", w, h, err);
        free(f.px);
        return -1;
    }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            double s = 0;
            for (j = 0; j < 4; j++)
                for (i = 0; i < 4; i++)
                    s += f.px[(size_t)(4 * y + j) * f.stride + (size_t)(4 * x + i)];
            ideal[(size_t)y * (size_t)w + (size_t)x] = s / (16.0 * 255.0);
        }
    free(f.px);
    return 0;
}

/* ---- the measure ---- */

/* Separable Gaussian blur, sigma 1.5, taps to 3 sigma, renormalised at the
 * frame's edges. */
static void gauss_blur(const double *in, double *out, int w, int h)
{
    enum { RADIUS = 5 };
    double k[2 * RADIUS + 1], *tmp = malloc(sizeof *tmp * (size_t)w * (size_t)h);
    int x, y, d;
    for (d = -RADIUS; d <= RADIUS; d++)
        k[d + RADIUS] = exp(-(double)(d * d) / (2.0 * 1.5 * 1.5));
    if (!tmp)
        exit(2);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            double s = 0, ws = 0;
            for (d = -RADIUS; d <= RADIUS; d++)
                if (x + d >= 0 && x + d < w) {
                    s += k[d + RADIUS] * in[(size_t)y * (size_t)w + (size_t)(x + d)];
                    ws += k[d + RADIUS];
                }
            tmp[(size_t)y * (size_t)w + (size_t)x] = s / ws;
        }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            double s = 0, ws = 0;
            for (d = -RADIUS; d <= RADIUS; d++)
                if (y + d >= 0 && y + d < h) {
                    s += k[d + RADIUS] * tmp[(size_t)(y + d) * (size_t)w + (size_t)x];
                    ws += k[d + RADIUS];
                }
            out[(size_t)y * (size_t)w + (size_t)x] = s / ws;
        }
    free(tmp);
}

/* Mean absolute difference of the blurred 0/1 picture and blurred ideal. */
static double picture_error(const unsigned char *bits, const double *ideal_blurred, int w, int h)
{
    size_t n = (size_t)w * (size_t)h, i;
    double *p = malloc(sizeof *p * n), *pb = malloc(sizeof *pb * n), sum = 0;
    if (!p || !pb)
        exit(2);
    for (i = 0; i < n; i++)
        p[i] = bits[i];
    gauss_blur(p, pb, w, h);
    for (i = 0; i < n; i++)
        sum += fabs(pb[i] - ideal_blurred[i]);
    free(p);
    free(pb);
    return sum / (double)n;
}

/* ---- methods ---- */

/* Render with a method's options to MONO1 and unpack to 0/1. */
static int render_bits(const stp_scene *scene, const qm_method *m, int w, int h, unsigned char *bits)
{
    stp_tool_options opt;
    frame f;
    char err[256];
    int x, y;
    stp_tool_options_default(&opt);
    opt.width = w;
    opt.height = h;
    if (m->setup)
        m->setup(&opt);
    if (frame_init(&f, w, h, STP_PIXEL_MONO1) != 0)
        return -1;
    if (stp_tool_render(scene, &opt, &f.port, 0, err, sizeof err) != 0) {
        fprintf(stderr, "bench_quality: %s %dx%d: %s\n", m->name, w, h, err);
        free(f.px);
        return -1;
    }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            bits[(size_t)y * (size_t)w + (size_t)x] =
                (unsigned char)((f.px[(size_t)y * f.stride + (size_t)(x >> 3)] >> (7 - (x & 7))) & 1);
    free(f.px);
    return 0;
}

static int method_bits(const stp_scene *scene, const qm_method *m, int w, int h, const double *ideal,
                       unsigned char *bits)
{
    if (m->on_ideal) {
        m->on_ideal(ideal, w, h, bits);
        return 0;
    }
    return render_bits(scene, m, w, h, bits);
}

/* ---- turning the model ---- */

static stp_scene_vec3 turn(stp_scene_vec3 p, stp_scene_vec3 c, stp_scene_vec3 axis, double angle)
{
    /* Rodrigues' rotation of p about the unit axis through c */
    double cs = cos(angle), sn = sin(angle), dot;
    stp_scene_vec3 v = {p.x - c.x, p.y - c.y, p.z - c.z}, cr, out;
    dot = v.x * axis.x + v.y * axis.y + v.z * axis.z;
    cr.x = axis.y * v.z - axis.z * v.y;
    cr.y = axis.z * v.x - axis.x * v.z;
    cr.z = axis.x * v.y - axis.y * v.x;
    out.x = c.x + v.x * cs + cr.x * sn + axis.x * dot * (1 - cs);
    out.y = c.y + v.y * cs + cr.y * sn + axis.y * dot * (1 - cs);
    out.z = c.z + v.z * cs + cr.z * sn + axis.z * dot * (1 - cs);
    return out;
}

/* Turn every vertex, normal and primitive of scene by `degrees` about the
 * view's up through its look-at point (the tool's view when the file has
 * none). */
static void turn_scene(stp_scene *scene, double degrees)
{
    stp_tool_options opt;
    stp_view view;
    stp_lighting lighting;
    char err[128];
    stp_scene_vec3 c, axis, zero = {0, 0, 0};
    double a = degrees * 3.14159265358979323846 / 180.0, len;
    size_t i;
    stp_tool_options_default(&opt);
    if (stp_tool_setup(scene, &opt, &view, &lighting, err, sizeof err) != 0)
        return;
    c.x = (double)view.at.x / STP_FIX_ONE;
    c.y = (double)view.at.y / STP_FIX_ONE;
    c.z = (double)view.at.z / STP_FIX_ONE;
    axis.x = (double)view.up.x;
    axis.y = (double)view.up.y;
    axis.z = (double)view.up.z;
    len = sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
    axis.x /= len;
    axis.y /= len;
    axis.z /= len;
    for (i = 0; i < scene->vertex_count; i++) {
        scene->vertices[i] = turn(scene->vertices[i], c, axis, a);
        if (scene->normals)
            scene->normals[i] = turn(scene->normals[i], zero, axis, a);
    }
    for (i = 0; i < scene->prim_count; i++) {
        scene->prims[i].base = turn(scene->prims[i].base, c, axis, a);
        scene->prims[i].apex = turn(scene->prims[i].apex, c, axis, a);
    }
}

/* One render of a method (for an instruction count under callgrind). */
static int render_once(const char *dir, const char *method, const char *scene_name, int w, int h)
{
    size_t i, nm = qm_method_count();
    stp_scene scene;
    stp_scene_options sopt;
    char path[1024], err[256];
    unsigned char *bits = malloc((size_t)w * (size_t)h);
    int rc = 1;
    if (!scene_name || !bits)
        return 2;
    snprintf(path, sizeof path, "%s/%s.nff", dir, scene_name);
    stp_scene_options_default(&sopt);
    if (stp_scene_load(path, &sopt, &scene, err, sizeof err) != 0) {
        fprintf(stderr, "bench_quality: %s\n", err);
        free(bits);
        return 1;
    }
    for (i = 0; i < nm; i++)
        if (!strcmp(qm_method_at(i)->name, method) && !qm_method_at(i)->on_ideal)
            rc = render_bits(&scene, qm_method_at(i), w, h, bits) == 0 ? 0 : 1;
    if (i == nm && rc)
        fprintf(stderr, "bench_quality: no render method '%s' (--list)\n", method);
    stp_scene_free(&scene);
    free(bits);
    return rc;
}

/* ---- main ---- */

typedef struct result {
    double error[2], flicker[2], cost[2];
    int ok;
} result;

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : (x > y);
}

/* Median over `rounds` interleaved rounds of (time of m) / (time of the
 * default method), each time the best of a few renders. */
static double cost_ratio(const stp_scene *scene, const qm_method *m, const qm_method *base, int w,
                         int h, int rounds, unsigned char *bits)
{
    double ratios[16];
    int r, k;
    if (rounds > 16)
        rounds = 16;
    for (r = 0; r < rounds; r++) {
        double tm = 1e30, tb = 1e30;
        for (k = 0; k < 3; k++) {
            double t0 = now();
            (void)render_bits(scene, base, w, h, bits);
            double t1 = now();
            (void)render_bits(scene, m, w, h, bits);
            double t2 = now();
            if (t1 - t0 < tb)
                tb = t1 - t0;
            if (t2 - t1 < tm)
                tm = t2 - t1;
        }
        ratios[r] = tm / tb;
    }
    qsort(ratios, (size_t)rounds, sizeof ratios[0], compare_double);
    return ratios[rounds / 2];
}

int main(int argc, char **argv)
{
    const char *dir = getenv("STP_SCENES_DIR");
    const char *only = 0;
    int quick = 0, timed = 0, a, s, z, mi, rounds = 5;
    static const int sizes[2][2] = {{128, 64}, {400, 240}};
    int nsizes = 2;
    size_t nm = qm_method_count();
    result *res;
    const char *once = 0;
    int once_w = 128, once_h = 64;
    for (a = 1; a < argc; a++) {
        if (strcmp(argv[a], "--list") == 0) {
            /* the render methods, for quality_cost.sh */
            for (mi = 0; mi < (int)nm; mi++)
                if (!qm_method_at((size_t)mi)->on_ideal)
                    printf("%s\n", qm_method_at((size_t)mi)->name);
            return 0;
        } else if (strcmp(argv[a], "--once") == 0 && a + 1 < argc) {
            once = argv[++a];
        } else if (strcmp(argv[a], "--size") == 0 && a + 1 < argc) {
            if (sscanf(argv[++a], "%dx%d", &once_w, &once_h) != 2 || once_w < 1 || once_h < 1)
                return 2;
        } else if (strcmp(argv[a], "--time") == 0) {
            timed = 1;
        } else if (strcmp(argv[a], "--quick") == 0) {
            quick = 1;
        } else if (strcmp(argv[a], "--small") == 0) {
            nsizes = 1;
        } else if (strcmp(argv[a], "--scenes") == 0 && a + 1 < argc) {
            dir = argv[++a];
        } else if (strcmp(argv[a], "--scene") == 0 && a + 1 < argc) {
            only = argv[++a];
        } else {
            fprintf(stderr,
                    "usage: bench_quality [--scenes DIR] [--scene NAME] [--small] [--time [--quick]]\n"
                    "       bench_quality --list | --once METHOD --scene NAME [--size WxH]\n"
                    "  --small  128x64 only; --time  wall-time ratios (interleaved rounds;\n"
                    "  --quick: one round); --list  the render methods; --once  one render\n"
                    "  (for valgrind --tool=callgrind --toggle-collect=stp_renderer_render:\n"
                    "  tools/bench/quality_cost.sh)\n");
            return 2;
        }
    }
    if (!dir)
        dir = STP_BENCH_SCENES_DIR;
    if (once)
        return render_once(dir, once, only, once_w, once_h);
    if (quick)
        rounds = 1;
    res = calloc(nm * SCENE_COUNT, sizeof *res);
    if (!res)
        return 2;
    printf("quality: mean |blur(1-bit) - blur(ideal)|, Gaussian sigma 1.5 px; flicker: share of\n"
           "pixels flipping when the model turns 1 degree%s\n\n",
           timed ? "; cost: render time / the first method's" : "");
    for (s = 0; s < (int)SCENE_COUNT; s++) {
        stp_scene scene, turned;
        stp_scene_options sopt;
        char path[1024], err[256];
        if (only && strcmp(only, scene_names[s]) != 0)
            continue;
        snprintf(path, sizeof path, "%s/%s.nff", dir, scene_names[s]);
        stp_scene_options_default(&sopt);
        if (stp_scene_load(path, &sopt, &scene, err, sizeof err) != 0 ||
            stp_scene_load(path, &sopt, &turned, err, sizeof err) != 0) {
            fprintf(stderr, "bench_quality: %s\n", err);
            return 1;
        }
        turn_scene(&turned, 1.0);
        for (z = 0; z < nsizes; z++) {
            int w = sizes[z][0], h = sizes[z][1];
            size_t n = (size_t)w * (size_t)h, i;
            double *ideal = malloc(sizeof *ideal * n), *ideal2 = malloc(sizeof *ideal2 * n),
                   *blurred = malloc(sizeof *blurred * n);
            unsigned char *bits = malloc(n), *bits2 = malloc(n);
            if (!ideal || !ideal2 || !blurred || !bits || !bits2)
                return 2;
            double *toned = malloc(sizeof *toned * n), *toned2 = malloc(sizeof *toned2 * n),
                   *toned_blurred = malloc(sizeof *toned_blurred * n);
            if (!toned || !toned2 || !toned_blurred)
                return 2;
            if (render_ideal(&scene, 0, w, h, ideal) != 0 || render_ideal(&turned, 0, w, h, ideal2) != 0)
                return 1;
            gauss_blur(ideal, blurred, w, h);
            for (mi = 0; mi < (int)nm; mi++) {
                const qm_method *m = qm_method_at((size_t)mi);
                result *rr = &res[(size_t)mi * SCENE_COUNT + (size_t)s];
                long flips = 0;
                const double *mi_ideal = ideal, *mi_ideal2 = ideal2, *mi_blurred = blurred;
                stp_tool_options probe;
                stp_tool_options_default(&probe);
                if (m->setup)
                    m->setup(&probe);
                if (stp_tool_tone_wanted(&probe)) {
                    if (render_ideal(&scene, m, w, h, toned) != 0 ||
                        render_ideal(&turned, m, w, h, toned2) != 0)
                        return 1;
                    gauss_blur(toned, toned_blurred, w, h);
                    mi_ideal = toned;
                    mi_ideal2 = toned2;
                    mi_blurred = toned_blurred;
                }
                if (method_bits(&turned, m, w, h, mi_ideal2, bits2) != 0 ||
                    method_bits(&scene, m, w, h, mi_ideal, bits) != 0)
                    return 1;
                rr->error[z] = picture_error(bits, mi_blurred, w, h);
                for (i = 0; i < n; i++)
                    flips += bits[i] != bits2[i];
                rr->flicker[z] = (double)flips / (double)n;
                rr->cost[z] = (m->on_ideal || !timed) ? -1
                              : cost_ratio(&scene, m, qm_method_at(0), w, h, rounds, bits);
                rr->ok = 1;
            }
            free(ideal);
            free(ideal2);
            free(blurred);
            free(toned);
            free(toned2);
            free(toned_blurred);
            free(bits);
            free(bits2);
        }
        stp_scene_free(&scene);
        stp_scene_free(&turned);
    }
    for (z = 0; z < nsizes; z++) {
        printf("%dx%d\n%-22s", sizes[z][0], sizes[z][1], "error");
        for (s = 0; s < (int)SCENE_COUNT; s++)
            printf(" %9s", scene_names[s]);
        printf("   %7s %7s %6s\n", "min", "max", timed ? "cost" : "");
        for (mi = 0; mi < (int)nm; mi++) {
            const qm_method *m = qm_method_at((size_t)mi);
            double lo = 1e9, hi = -1, cost = -1;
            printf("%-22s", m->name);
            for (s = 0; s < (int)SCENE_COUNT; s++) {
                const result *rr = &res[(size_t)mi * SCENE_COUNT + (size_t)s];
                if (!rr->ok) {
                    printf(" %9s", "-");
                    continue;
                }
                printf(" %9.4f", rr->error[z]);
                if (rr->error[z] < lo)
                    lo = rr->error[z];
                if (rr->error[z] > hi)
                    hi = rr->error[z];
                if (rr->cost[z] > cost)
                    cost = rr->cost[z];
            }
            printf("   %7.4f %7.4f", lo, hi);
            if (cost > 0)
                printf(" %5.2fx", cost);
            printf("\n");
        }
        {
            /* the target: the still default within 1.2x of
             * Floyd-Steinberg applied to the ideal, scene by scene */
            int still = -1, ideal_fs = -1;
            double worst = 0;
            for (mi = 0; mi < (int)nm; mi++) {
                if (!strcmp(qm_method_at((size_t)mi)->name, QM_STILL_DEFAULT))
                    still = mi;
                if (!strcmp(qm_method_at((size_t)mi)->name, QM_IDEAL_FS))
                    ideal_fs = mi;
            }
            if (still >= 0 && ideal_fs >= 0) {
                printf("%-22s", "still / ideal+fs");
                for (s = 0; s < (int)SCENE_COUNT; s++) {
                    const result *rs = &res[(size_t)still * SCENE_COUNT + (size_t)s],
                                 *rf = &res[(size_t)ideal_fs * SCENE_COUNT + (size_t)s];
                    if (!rs->ok || !rf->ok || rf->error[z] <= 0) {
                        printf(" %9s", "-");
                        continue;
                    }
                    printf(" %8.3fx", rs->error[z] / rf->error[z]);
                    if (rs->error[z] / rf->error[z] > worst)
                        worst = rs->error[z] / rf->error[z];
                }
                printf("   worst %.3fx\n", worst);
            }
        }
        printf("%-22s", "flicker (1 degree)");
        for (s = 0; s < (int)SCENE_COUNT; s++)
            printf(" %9s", scene_names[s]);
        printf("   %7s %7s\n", "min", "max");
        for (mi = 0; mi < (int)nm; mi++) {
            const qm_method *m = qm_method_at((size_t)mi);
            double lo = 1e9, hi = -1;
            printf("%-22s", m->name);
            for (s = 0; s < (int)SCENE_COUNT; s++) {
                const result *rr = &res[(size_t)mi * SCENE_COUNT + (size_t)s];
                if (!rr->ok) {
                    printf(" %9s", "-");
                    continue;
                }
                printf(" %9.4f", rr->flicker[z]);
                if (rr->flicker[z] < lo)
                    lo = rr->flicker[z];
                if (rr->flicker[z] > hi)
                    hi = rr->flicker[z];
            }
            printf("   %7.4f %7.4f\n", lo, hi);
        }
        printf("\n");
    }
    free(res);
    return 0;
}
