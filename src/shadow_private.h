/* SPDX-License-Identifier: MIT */
/* Private: the shadow maps (shadow.c) for polygon entry (render.c) and the
 * raster (raster.c). */
#ifndef STIPPLE_SHADOW_PRIVATE_H
#define STIPPLE_SHADOW_PRIVATE_H

#include "renderer_state.h"

#if STP_WITH_SHADOWS
/* What the raster needs to re-light the pixels of one polygon, gathered
 * from its STP_OP_LIGHT_TERM records (shadow.c). */
typedef struct stp_shadow_poly {
    int count;                    /* lights tested; 0: the polygon has no record */
    int light[STP_MAX_LIGHTS];    /* their indices */
    int32_t bias[STP_MAX_LIGHTS]; /* their b (map depth units) */
    uint32_t tested;              /* bit j: light j is tested */
    int grey;                     /* STP_LIGHT_TERM_GREY record */
    stp_fix ambient, brightness;
    stp_fix terms[STP_MAX_LIGHTS]; /* by light index; 0 for untested ones */
    stp_fix full;                 /* the shade with every light */
    /* depth key plane: key(xq, yq) = (k0 + gx (xq - x0) + gy (yq - y0))
     * 2^shift / 2^16 raw key units, xq, yq device Q27.4 */
    int64_t k0, gx, gy;
    int32_t x0, y0;
    int shift;
} stp_shadow_poly;

/* shadow.c, at entry: the STP_OP_LIGHT_TERM records of a polygon shaded
 * with this normal at this centre (view coordinates; colour: a colour
 * polygon), in record[] (1 + STP_MAX_LIGHTS entries, op unset): returns
 * how many, 0 when no map can darken it.  Biases are 1 until
 * stp_shadow_enter sets them through r->shadow_record. */
int stp_shadow_records(const stp_renderer *r, stp_vec3 normal, stp_vec3 centre, stp_vec3 eye_dir,
                       int colour, stp_instr *record);
/* shadow.c, at entry, once the polygon (world vertices, n validated) is in
 * the display file or was dropped from it with STP_OK: draw its depth into
 * every map and patch its records' biases. */
void stp_shadow_enter(stp_renderer *r, const stp_vec3 *vertices, int n);

/* shadow.c, at output: gather the records of the polygon whose header is
 * df[at] (sp->count = 0 when it has none); the lights that do not reach
 * device pixel (x, y) of it (bit j: light j); the polygon's shade with
 * only the lights in `lit`. */
void stp_shadow_polygon(const stp_renderer *r, uint32_t at, stp_shadow_poly *sp);
uint32_t stp_shadow_hidden(const stp_renderer *r, const stp_shadow_poly *sp, uint32_t x, uint32_t y);
stp_fix stp_shadow_shade(const stp_shadow_poly *sp, uint32_t lit);
/* 1 when some light has a map set */
int stp_shadow_any(const stp_renderer *r);
#endif

#endif
