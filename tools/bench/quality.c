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

#include "quality_measure.h"
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

static int method_bits(const stp_scene *scene, const qm_method *m, int w, int h, const double *ideal,
                       unsigned char *bits)
{
    if (m->on_ideal) {
        m->on_ideal(ideal, w, h, bits);
        return 0;
    }
    return qm_render_bits(scene, m, w, h, bits);
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
            rc = qm_render_bits(&scene, qm_method_at(i), w, h, bits) == 0 ? 0 : 1;
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
            (void)qm_render_bits(scene, base, w, h, bits);
            double t1 = now();
            (void)qm_render_bits(scene, m, w, h, bits);
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
            if (qm_render_ideal(&scene, 0, w, h, ideal) != 0 || qm_render_ideal(&turned, 0, w, h, ideal2) != 0)
                return 1;
            qm_gauss_blur(ideal, blurred, w, h);
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
                    if (qm_render_ideal(&scene, m, w, h, toned) != 0 ||
                        qm_render_ideal(&turned, m, w, h, toned2) != 0)
                        return 1;
                    qm_gauss_blur(toned, toned_blurred, w, h);
                    mi_ideal = toned;
                    mi_ideal2 = toned2;
                    mi_blurred = toned_blurred;
                }
                if (method_bits(&turned, m, w, h, mi_ideal2, bits2) != 0 ||
                    method_bits(&scene, m, w, h, mi_ideal, bits) != 0)
                    return 1;
                rr->error[z] = qm_picture_error(bits, mi_blurred, w, h);
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
            /* the target: the still default's diffusion (without
             * its automatic lines, which the ideal does not have) within
             * 1.1x of Floyd-Steinberg applied to the ideal, scene by scene */
            int still = -1, ideal_fs = -1;
            double worst = 0;
            for (mi = 0; mi < (int)nm; mi++) {
                if (!strcmp(qm_method_at((size_t)mi)->name, QM_STILL_NO_LINES))
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
