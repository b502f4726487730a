/* SPDX-License-Identifier: MIT */
/*
 * A spinning model for the Arduino examples, drawn by direct drawing
 * (stipple/direct.h): the camera, the light and the turn of frame n in one
 * place, so a sketch and the host test that checks its pictures
 * (tests/avr/spin_reference.c) draw the same frames.
 *
 * The model (centred on the origin with radius 1, as `stipple compile
 * --mesh` writes it) is seen from (0, 1, 3.375) looking at the origin,
 * 35 degrees across the 64 rows of a 128x64 panel (focal 101.49 pixels,
 * hither 0.1): the view stp_direct_view_look makes, worked out on the host
 * and kept as data (STIPPLE_SPIN_VIEW; tests/avr/test_u8g2_buffer.c checks
 * it), so the look-at's code (1.5 KB on an AVR) stays off the chip.  One
 * light at (-4, 6, 5), power 9.775, background 0.2, reflectivity 0.7,
 * brightness 1; 16 levels, Bayer 4x4.  The face shader's constants for
 * that view and light (stp_direct_lit) are data too in the Arduino
 * library's configuration (spin_lit in stipple_spin.c;
 * tests/avr/test_spin_lit.c checks them against the prepare), so a
 * sketch links neither the prepare nor its 64-bit arithmetic.  Frame n
 * turns the model by n/64 of a turn about y and by n 410/65536 of a turn
 * about x.
 */
#ifndef STIPPLE_SPIN_H
#define STIPPLE_SPIN_H

#include <stdint.h>

#include "stipple/direct.h"

#ifdef __cplusplus
extern "C" {
#endif

#define STIPPLE_SPIN_WIDTH 128u
#define STIPPLE_SPIN_HEIGHT 64u

typedef struct stipple_spin {
    const stp_mesh *mesh;      /* its arrays readable by the core (RAM on an AVR) */
    stp_direct_point *points;  /* mesh->vertex_count entries */
    uint16_t *faces;           /* mesh->triangle_count entries */
    stp_direct_view view;
    const stp_direct_lit *lit; /* the light prepared for the view, kept as
                                  data in the Arduino configuration; NULL
                                  elsewhere: prepared every frame */
    stp_direct_frame frame;    /* the last frame made by stipple_spin_frame */
} stipple_spin;

/* The view above, as stp_direct_view_look(from (0, 1, 3.375), at the
 * origin, up (0, 1, 0), focal 6651316, hither 6554, 128, 64) returns it. */
#define STIPPLE_SPIN_VIEW                                                                    \
    {{0, 65536, 221184}, {{65536, 0, 0}, {0, 62836, -18620}, {0, -18620, -62836}}, 6651316, 6554, \
     STIPPLE_SPIN_WIDTH, STIPPLE_SPIN_HEIGHT}

/* Set s up for mesh (prepared normals required; centred, radius 1).
 * points and faces: caller memory as above.  Returns STP_OK or
 * STP_ERR_ARG (a pointer NULL). */
int stipple_spin_begin(stipple_spin *s, const stp_mesh *mesh, stp_direct_point *points,
                       uint16_t *faces);

/* The light above into *light (the one stipple_spin_frame prepares where
 * lit is NULL; the tests compare lit with it). */
void stipple_spin_light(stp_direct_light *light);

/* Frame n into s->frame (then drawn band by band by stp_direct_draw_band).
 * Returns STP_OK or the error of stp_direct_frame_project. */
int stipple_spin_frame(stipple_spin *s, uint16_t n);

#ifdef __cplusplus
}
#endif

#endif
