/* SPDX-License-Identifier: MIT */
/*
 * Host counterpart of m0/main.c for valgrind --tool=callgrind: the same 64
 * faces shaded by stp_shade_fast_face and by the accurate path (two
 * stp_unit_from64 and stp_shade_unit), 1000 times each, in functions of
 * their own so callgrind's inclusive counts divide into instructions per
 * face (m0_bench.sh's figures are the Cortex-M0+ ones).  Argument "diffuse":
 * the material's Ks = 0; a second argument "time": the ratio of their
 * wall times over 20 interleaved runs instead.  Prints the sum of
 * the shades so the work cannot be optimised away.
 */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <time.h>

#include "fix_private.h"
#include "shade_fast_private.h"
#include "shade_private.h"

#define FACES 64
#define REPEAT 1000

static int16_t normals[FACES][3];
static stp_vec3 points[FACES];

__attribute__((noinline)) static long bench_fast(const stp_lighting *l, const stp_material *m)
{
    stp_shade_fast s;
    stp_vec3 eye = {0, 0, 0}, back = {0, 0, -STP_FIX_ONE};
    long sum = 0;
    int k, i;
    stp_shade_fast_prepare(&s, l, m, eye, 0, back);
    for (k = 0; k < REPEAT; k++)
        for (i = 0; i < FACES; i++)
            sum += stp_shade_fast_face(&s, normals[i], points[i]);
    return sum;
}

__attribute__((noinline)) static long bench_accurate(const stp_lighting *l, const stp_material *m)
{
    long sum = 0;
    int k, i;
    for (k = 0; k < REPEAT; k++)
        for (i = 0; i < FACES; i++) {
            stp_unit3 n, e;
            (void)stp_unit_from64(normals[i][0], normals[i][1], normals[i][2], &n);
            (void)stp_unit_from64(-(int64_t)points[i].x, -(int64_t)points[i].y, -(int64_t)points[i].z, &e);
            sum += stp_shade_unit(l, m, n, points[i], e, stp_unit_dot(n, e));
        }
    return sum;
}

int main(int argc, char **argv)
{
    stp_lighting lighting;
    stp_material material;
    int i;
    stp_lighting_default(&lighting);
    stp_material_default(&material);
    lighting.lights[0].position.x = -4 * STP_FIX_ONE;
    lighting.lights[0].position.y = 6 * STP_FIX_ONE;
    lighting.lights[0].position.z = -1 * STP_FIX_ONE;
    lighting.background = STP_FIX_ONE / 5;
    lighting.lights[0].power = 8 * STP_FIX_ONE;
    for (i = 0; i < FACES; i++) {
        int32_t a = i % 8 - 4, b = i / 8 - 4;
        stp_unit3 u;
        (void)stp_unit_from64(a * 3 + 1, b * 3 + 2, -20, &u);
        normals[i][0] = (int16_t)((u.x + (1 << 15)) >> 16);
        normals[i][1] = (int16_t)((u.y + (1 << 15)) >> 16);
        normals[i][2] = (int16_t)((u.z + (1 << 15)) >> 16);
        points[i].x = u.x >> 14;
        points[i].y = u.y >> 14;
        points[i].z = 6 * STP_FIX_ONE + (u.z >> 14);
    }
    if (argc > 1 && argv[1][0] == 'd')
        material.specular = 0; /* "diffuse": Ks = 0 */
    if (argc > 2 && argv[2][0] == 't') {
        /* wall time, interleaved: the ratio only (third argument "time") */
        double tf = 0, ta = 0;
        int r;
        for (r = 0; r < 20; r++) {
            struct timespec a, b, c;
            clock_gettime(CLOCK_MONOTONIC, &a);
            (void)bench_fast(&lighting, &material);
            clock_gettime(CLOCK_MONOTONIC, &b);
            (void)bench_accurate(&lighting, &material);
            clock_gettime(CLOCK_MONOTONIC, &c);
            tf += (double)(b.tv_sec - a.tv_sec) + 1e-9 * (double)(b.tv_nsec - a.tv_nsec);
            ta += (double)(c.tv_sec - b.tv_sec) + 1e-9 * (double)(c.tv_nsec - b.tv_nsec);
        }
        printf("wall time fast / accurate: %.2f\n", tf / ta);
        return 0;
    }
    printf("fast %ld accurate %ld\n", bench_fast(&lighting, &material), bench_accurate(&lighting, &material));
    return 0;
}
