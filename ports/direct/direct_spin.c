/* SPDX-License-Identifier: MIT */
/* The spinning torus (direct_spin.h). */
#include "direct_spin.h"

#define ONE STP_FIX_ONE

/* The Bayer 4x4 cell's thresholds (stp_cell_bayer(cell, 4)), as const data */
static const uint8_t bayer4[16] = {14, 134, 44, 164, 194, 74, 224, 104, 59, 179, 29, 149, 239, 119, 209, 89};

/* i / n of a turn in 1/65536 turns, within one unit, as i (2^32 / n)
 * 2^-16 rounded, for i < n (the product stays below 2^32): no division
 * (ARMv6-M has none; the library's would be linked in) */
static uint16_t turn(uint32_t i, uint32_t two32_over_n)
{
    return (uint16_t)((i * two32_over_n + 32768u) >> 16);
}
#define OVER_AROUND 171798692u /* 2^32 / 25 */
#define OVER_TUBE 214748365u   /* 2^32 / 20 */

/* STP_SPIN_PLACE 1's place of the torus's centre */
#ifndef SPIN_PLACE_X
#define SPIN_PLACE_X 40000 /* 0.61 */
#endif
#ifndef SPIN_PLACE_Y
#define SPIN_PLACE_Y 158000 /* 2.41 */
#endif
#ifndef SPIN_PLACE_Z
#define SPIN_PLACE_Z 282000 /* 4.30, 0.9 units from the eye */
#endif

static stp_vec3 point(stp_fix x, stp_fix y, stp_fix z)
{
    stp_vec3 p;
    p.x = x;
    p.y = y;
    p.z = z;
    return p;
}

int direct_spin_init(direct_spin *s)
{
    const int32_t major = ONE, minor = 26214; /* 1 and 0.4 */
    uint32_t i, j, t = 0;
    int status;
    for (i = 0; i < SPIN_AROUND; i++)
        for (j = 0; j < SPIN_TUBE; j++) {
            uint16_t u = turn(i, OVER_AROUND), v = turn(j, OVER_TUBE);
            int32_t cu = stp_direct_sin((uint16_t)(u + 0x4000u)), su = stp_direct_sin(u);
            int32_t cv = stp_direct_sin((uint16_t)(v + 0x4000u)), sv = stp_direct_sin(v);
            int32_t ring = major + ((minor * cv) >> 14); /* below 2^17: times Q14 below 2^31 */
            s->vertices[i * SPIN_TUBE + j] = point((ring * cu) >> 14, (minor * sv) >> 14, (ring * su) >> 14);
        }
    for (i = 0; i < SPIN_AROUND; i++)
        for (j = 0; j < SPIN_TUBE; j++) {
            /* the next ring and tube step, wrapping (no % on the chip) */
            uint32_t i1 = i + 1u == SPIN_AROUND ? 0u : i + 1u, j1 = j + 1u == SPIN_TUBE ? 0u : j + 1u;
            uint16_t a = (uint16_t)(i * SPIN_TUBE + j), b = (uint16_t)(i1 * SPIN_TUBE + j);
            uint16_t c = (uint16_t)(i1 * SPIN_TUBE + j1), d = (uint16_t)(i * SPIN_TUBE + j1);
            /* counter-clockwise seen from outside: (a, d, c), (a, c, b) */
            s->triangles[t++] = a;
            s->triangles[t++] = d;
            s->triangles[t++] = c;
            s->triangles[t++] = a;
            s->triangles[t++] = c;
            s->triangles[t++] = b;
        }
    s->mesh.vertices = s->vertices;
    s->mesh.triangles = s->triangles;
    s->mesh.normals = s->normals;
    s->mesh.bounds = 0;
    s->mesh.vertex_count = (uint16_t)SPIN_VERTICES;
    s->mesh.triangle_count = (uint16_t)SPIN_TRIANGLES;
    status = stp_mesh_prepare_normals(&s->mesh, s->normals, 0);
    if (status != STP_OK)
        return status;
    s->light.position = point(-4 * ONE, 6 * ONE, 5 * ONE);
    s->light.power = 640614; /* 9.775 */
    s->light.brightness = ONE;
    s->light.background = 13107; /* 0.2 */
    s->light.attenuation_c = ONE;
    s->light.reflectivity = 45875; /* 0.7 */
    /* focal: 32 / tan(17.5 degrees) pixels */
    return stp_direct_view_look(&s->view, point(0, 3 * ONE, 340787 /* 5.2 */), point(0, 0, 0), point(0, ONE, 0),
                                6651316, 6554, (uint16_t)SPIN_WIDTH, (uint16_t)SPIN_HEIGHT);
}

int direct_spin_frame(direct_spin *s, uint16_t n, stp_direct_frame *f)
{
    stp_direct_model pose;
    int status;
    stp_direct_model_turn(&pose, (uint16_t)(n * 1024u), (uint16_t)(n * 410u), ONE,
                          STP_SPIN_PLACE ? point(SPIN_PLACE_X, SPIN_PLACE_Y, SPIN_PLACE_Z) : point(0, 0, 0));
    status = stp_direct_frame_project(f, &s->mesh, &pose, &s->view, &s->light, 16, bayer4, s->points,
                                      SPIN_VERTICES, s->faces, SPIN_TRIANGLES);
#if SPIN_SORTED
    if (status == STP_OK)
        status = stp_direct_frame_sort(f, s->order, SPIN_TRIANGLES);
#endif
#if SPIN_DEPTH
    if (status == STP_OK) {
        s->depth.depths = s->depths;
        s->depth.depth_count = SPIN_VERTICES;
        s->depth.zband = s->zband;
        s->depth.zband_count = SPIN_WIDTH * SPIN_DEPTH_ROWS;
        status = stp_direct_frame_depth(f, &s->depth);
    }
#endif
    return status;
}
