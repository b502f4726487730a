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

static stp_vec3 point(stp_fix x, stp_fix y, stp_fix z)
{
    stp_vec3 p;
    p.x = x;
    p.y = y;
    p.z = z;
    return p;
}

int stipple_spin_begin(stipple_spin *s, const stp_mesh *mesh, stp_direct_point *points,
                       uint16_t *faces)
{
    if (s == 0 || mesh == 0 || points == 0 || faces == 0)
        return STP_ERR_ARG;
    s->mesh = mesh;
    s->points = points;
    s->faces = faces;
    s->light.position = point(-4 * ONE, 6 * ONE, 5 * ONE);
    s->light.power = 640614; /* 9.775 */
    s->light.brightness = ONE;
    s->light.background = 13107; /* 0.2 */
    s->light.attenuation_c = ONE;
    s->light.reflectivity = 45875; /* 0.7 */
#if defined(__AVR__)
    memcpy_P(&s->view, &spin_view, sizeof s->view);
#else
    s->view = spin_view;
#endif
    return STP_OK;
}

int stipple_spin_frame(stipple_spin *s, uint16_t n)
{
    stp_direct_model pose;
    stp_direct_model_turn(&pose, (uint16_t)(n * 1024u), (uint16_t)(n * 410u), ONE, point(0, 0, 0));
    return stp_direct_frame_project(&s->frame, s->mesh, &pose, &s->view, &s->light, 16, bayer4,
                                    s->points, s->mesh->vertex_count, s->faces,
                                    s->mesh->triangle_count);
}
