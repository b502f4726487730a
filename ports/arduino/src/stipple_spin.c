/* SPDX-License-Identifier: MIT */
/* The spinning model of the Arduino examples (stipple_spin.h).  It reads
 * the core's private stp_direct_lit (direct_private.h): the release
 * archive puts this file with the core's sources (scripts/
 * arduino_library.sh), the tree's builds give it src/ to include. */
#include "stipple_spin.h"

#include "direct_private.h" /* stp_direct_lit */
#include "stipple/render.h"

#define ONE STP_FIX_ONE

/* The Bayer 4x4 cell's thresholds (stp_cell_bayer(cell, 4)) */
static const uint8_t bayer4[16] = {14, 134, 44, 164, 194, 74, 224, 104,
                                   59, 179, 29, 149, 239, 119, 209, 89};

#if defined(__AVR__)
#include <avr/pgmspace.h>
#define SPIN_ROM PROGMEM
#else
#define SPIN_ROM
#endif

static const stp_direct_view spin_view SPIN_ROM = STIPPLE_SPIN_VIEW;

/* the light at (-4, 6, 5), power 9.775, brightness 1, background 0.2,
 * C = 1, reflectivity 0.7 */
static const stp_direct_light spin_light SPIN_ROM = {
    {-4 * ONE, 6 * ONE, 5 * ONE}, 640614, ONE, 13107, ONE, 45875};

/* The light prepared for spin_view (stp_direct_light_prepare, as
 * stp_direct_frame_project makes it every frame), for the layout of the
 * Arduino library's configuration (stipple_config.h: 16 fractional bits,
 * one light, no highlight; tag ..._f16_..._l1_..._0...) on 32-bit target
 * arithmetic; tests/avr/test_spin_lit.c checks it, field by field, and
 * prints it anew when the prepare changes.  Not in program memory: the
 * face shader reads it where it is (RAM, copied there at start-up). */
#if STP_FIX_FRAC_BITS == 16 && STP_MAX_LIGHTS == 1 && !STP_WITH_SPECULAR && !STP_WIDE_ARITH
#define SPIN_LIT_DATA 1
static const stp_direct_lit spin_lit = {{
    .count = 1,
    .ambient_shade = 9175,              /* 0.2 x 0.7, Q16 */
    .ambient = 9395056,                 /* the same in Q26 */
    .light = {{-262144, 283922, -195209}}, /* the light in view coordinates */
    .power_refl = {{56052, -3}},        /* BRIGHT P R 2^16 per raw unit of C + U */
    .attenuation_c = {32768, -1},       /* C = 1 (65536 raw units) */
}};
#else
#define SPIN_LIT_DATA 0 /* another layout: prepared every frame */
#endif

int stipple_spin_begin(stipple_spin *s, const stp_mesh *mesh, stp_direct_point *points,
                       uint16_t *faces)
{
    if (s == 0 || mesh == 0 || points == 0 || faces == 0)
        return STP_ERR_ARG;
    s->mesh = mesh;
    s->points = points;
    s->faces = faces;
#if SPIN_LIT_DATA
    s->lit = &spin_lit;
#else
    s->lit = 0;
#endif
#if defined(__AVR__)
    memcpy_P(&s->view, &spin_view, sizeof s->view);
#else
    s->view = spin_view;
#endif
    return STP_OK;
}

void stipple_spin_light(stp_direct_light *light)
{
#if defined(__AVR__)
    memcpy_P(light, &spin_light, sizeof *light);
#else
    *light = spin_light;
#endif
}

__attribute__((noinline)) int stipple_spin_frame(stipple_spin *s, uint16_t n)
{
    stp_direct_model pose;
    stp_vec3 origin = {0, 0, 0};
    stp_direct_model_turn(&pose, (uint16_t)(n * 1024u), (uint16_t)(n * 410u), ONE, origin);
#if SPIN_LIT_DATA
    return stp_direct_frame_project_lit(&s->frame, s->mesh, &pose, &s->view, s->lit, 16, bayer4, s->points,
                                        s->mesh->vertex_count, s->faces, s->mesh->triangle_count);
#else
    {
        stp_direct_light light;
        stipple_spin_light(&light);
        return stp_direct_frame_project(&s->frame, s->mesh, &pose, &s->view, &light, 16, bayer4, s->points,
                                        s->mesh->vertex_count, s->faces, s->mesh->triangle_count);
    }
#endif
}
