/* SPDX-License-Identifier: MIT */
/*
 * Cortex-M bench of the flat-face shading (src/shade_fast.c) against the
 * accurate path (stp_shade_unit with the stp_unit_from64 calls render.c
 * makes for N and E), for QEMU's mps2-an385 under -icount shift=0
 * (instructions counted with SysTick, ports/stellaris): 64 faces of the
 * issue 11 torus's light and view (one point light at (-4, 6, 5) seen
 * from the eye, the seed's material: full specular), each shaded 4 times.
 * Prints instructions per call and the worst difference between the two
 * paths' shades in LSB, then exits through semihosting.
 */
#include "fix_private.h"
#include "shade_fast_private.h"
#include "shade_private.h"
#include "stellaris.h"

#define FACES 64u
#define REPEAT 4u

static int16_t normals[FACES][3];
static stp_unit3 units[FACES];
static stp_vec3 points[FACES];
static stp_fix shades[FACES];

static void report(const char *what, uint32_t value)
{
    char num[12];
    stp_semihost_write("stipple: ");
    stp_semihost_write(what);
    stp_semihost_write(" ");
    stp_semihost_write(stp_utoa(value, num));
    stp_semihost_write("\n");
}

int main(void)
{
    stp_lighting lighting;
    stp_material material;
    stp_shade_fast fast;
    stp_vec3 eye = {0, 0, 0}, back = {0, 0, -STP_FIX_ONE};
    uint32_t per_tick, i, k, worst = 0, lit = 0;
    uint64_t t0, t1;
    stp_count_start();
    per_tick = stp_count_calibrate();
    stp_lighting_default(&lighting);
    stp_material_default(&material);
    lighting.lights[0].position.x = -4 * STP_FIX_ONE;
    lighting.lights[0].position.y = 6 * STP_FIX_ONE;
    lighting.lights[0].position.z = -1 * STP_FIX_ONE; /* in front of the faces */
    lighting.background = STP_FIX_ONE / 5;
    lighting.lights[0].power = 8 * STP_FIX_ONE;
    /* faces on a sphere of radius 1 around (0, 0, 6), those facing the eye */
    for (i = 0; i < FACES; i++) {
        int32_t a = (int32_t)(i % 8u) - 4, b = (int32_t)(i / 8u) - 4;
        stp_unit3 u;
        (void)stp_unit_from64(a * 3 + 1, b * 3 + 2, -20, &u);
        normals[i][0] = (int16_t)((u.x + (1 << 15)) >> 16);
        normals[i][1] = (int16_t)((u.y + (1 << 15)) >> 16);
        normals[i][2] = (int16_t)((u.z + (1 << 15)) >> 16);
        (void)stp_unit_from64(normals[i][0], normals[i][1], normals[i][2], &units[i]);
        points[i].x = u.x >> 14;
        points[i].y = u.y >> 14;
        points[i].z = 6 * STP_FIX_ONE + (u.z >> 14);
    }
    report("instructions per tick", per_tick);

    t0 = stp_count_now();
    for (k = 0; k < 16u; k++)
        stp_shade_fast_prepare(&fast, &lighting, &material, eye, 0, back);
    t1 = stp_count_now();
    report("instructions per stp_shade_fast_prepare", (uint32_t)((t1 - t0) * per_tick / 16u));

    t0 = stp_count_now();
    for (k = 0; k < REPEAT; k++)
        for (i = 0; i < FACES; i++)
            shades[i] = stp_shade_fast_face(&fast, normals[i], points[i]);
    t1 = stp_count_now();
    report("instructions per stp_shade_fast_face", (uint32_t)((t1 - t0) * per_tick / (FACES * REPEAT)));

    material.gloss = STP_FIX_ONE / 10; /* a sharp highlight: k = 0.1 */
    stp_shade_fast_prepare(&fast, &lighting, &material, eye, 0, back);
    t0 = stp_count_now();
    for (k = 0; k < REPEAT; k++)
        for (i = 0; i < FACES; i++)
            (void)stp_shade_fast_face(&fast, normals[i], points[i]);
    t1 = stp_count_now();
    report("instructions per stp_shade_fast_face with k = 0.1",
           (uint32_t)((t1 - t0) * per_tick / (FACES * REPEAT)));
    t0 = stp_count_now();
    for (k = 0; k < REPEAT; k++)
        for (i = 0; i < FACES; i++) {
            stp_unit3 n, e;
            (void)stp_unit_from64(normals[i][0], normals[i][1], normals[i][2], &n);
            (void)stp_unit_from64(-(int64_t)points[i].x, -(int64_t)points[i].y, -(int64_t)points[i].z, &e);
            (void)stp_shade_unit(&lighting, &material, n, points[i], e, stp_unit_dot(n, e));
        }
    t1 = stp_count_now();
    report("instructions per accurate face with k = 0.1",
           (uint32_t)((t1 - t0) * per_tick / (FACES * REPEAT)));
    material.gloss = 10 * STP_FIX_ONE;

    material.specular = 0; /* diffuse only (Ks = 0) */
    stp_shade_fast_prepare(&fast, &lighting, &material, eye, 0, back);
    t0 = stp_count_now();
    for (k = 0; k < REPEAT; k++)
        for (i = 0; i < FACES; i++)
            (void)stp_shade_fast_face(&fast, normals[i], points[i]);
    t1 = stp_count_now();
    report("instructions per stp_shade_fast_face with Ks = 0",
           (uint32_t)((t1 - t0) * per_tick / (FACES * REPEAT)));
    t0 = stp_count_now();
    for (k = 0; k < REPEAT; k++)
        for (i = 0; i < FACES; i++) {
            stp_unit3 n, e;
            (void)stp_unit_from64(normals[i][0], normals[i][1], normals[i][2], &n);
            (void)stp_unit_from64(-(int64_t)points[i].x, -(int64_t)points[i].y, -(int64_t)points[i].z, &e);
            (void)stp_shade_unit(&lighting, &material, n, points[i], e, stp_unit_dot(n, e));
        }
    t1 = stp_count_now();
    report("instructions per accurate face with Ks = 0",
           (uint32_t)((t1 - t0) * per_tick / (FACES * REPEAT)));
    material.specular = STP_FIX_ONE;
    stp_shade_fast_prepare(&fast, &lighting, &material, eye, 0, back);

    t0 = stp_count_now();
    for (k = 0; k < REPEAT; k++)
        for (i = 0; i < FACES; i++) {
            stp_unit3 n, e;
            (void)stp_unit_from64(normals[i][0], normals[i][1], normals[i][2], &n);
            (void)stp_unit_from64(-(int64_t)points[i].x, -(int64_t)points[i].y, -(int64_t)points[i].z, &e);
            (void)stp_shade_unit(&lighting, &material, n, points[i], e, stp_unit_dot(n, e));
        }
    t1 = stp_count_now();
    report("instructions per accurate face (2 stp_unit_from64 + stp_shade_unit)",
           (uint32_t)((t1 - t0) * per_tick / (FACES * REPEAT)));

    t0 = stp_count_now();
    for (k = 0; k < REPEAT; k++)
        for (i = 0; i < FACES; i++) {
            stp_unit3 e = {0, 0, -STP_UNIT_ONE};
            (void)stp_shade_unit(&lighting, &material, units[i], points[i], e, units[i].z < 0 ? -units[i].z : 0);
        }
    t1 = stp_count_now();
    report("instructions per stp_shade_unit", (uint32_t)((t1 - t0) * per_tick / (FACES * REPEAT)));

    for (i = 0; i < FACES; i++) {
        stp_unit3 e;
        stp_fix a;
        uint32_t d;
        (void)stp_unit_from64(-(int64_t)points[i].x, -(int64_t)points[i].y, -(int64_t)points[i].z, &e);
        a = stp_shade_unit(&lighting, &material, units[i], points[i], e, stp_unit_dot(units[i], e));
        d = (uint32_t)(a > shades[i] ? a - shades[i] : shades[i] - a);
        if (d > worst)
            worst = d;
        if (shades[i] > a / 2 && shades[i] > fast.ambient_shade)
            lit++;
    }
    report("faces lit", lit);
    report("worst |fast - accurate| in LSB", worst);
    return 0;
}
