/* SPDX-License-Identifier: MIT */
/* The spinning model of the Arduino examples (stipple_spin.h). */
#include "stipple_spin.h"

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

int stipple_spin_begin(stipple_spin *s, const stp_mesh *mesh, stp_direct_point *points,
                       uint16_t *faces)
{
    if (s == 0 || mesh == 0 || points == 0 || faces == 0)
        return STP_ERR_ARG;
    s->mesh = mesh;
    s->points = points;
    s->faces = faces;
#if defined(__AVR__)
    memcpy_P(&s->view, &spin_view, sizeof s->view);
    memcpy_P(&s->light, &spin_light, sizeof s->light);
#else
    s->view = spin_view;
    s->light = spin_light;
#endif
    return STP_OK;
}

int stipple_spin_frame(stipple_spin *s, uint16_t n)
{
    stp_direct_model pose;
    stp_vec3 origin = {0, 0, 0};
    stp_direct_model_turn(&pose, (uint16_t)(n * 1024u), (uint16_t)(n * 410u), ONE, origin);
    return stp_direct_frame_project(&s->frame, s->mesh, &pose, &s->view, &s->light, 16, bayer4,
                                    s->points, s->mesh->vertex_count, s->faces,
                                    s->mesh->triangle_count);
}
