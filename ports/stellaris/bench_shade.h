/* SPDX-License-Identifier: MIT */
/* The bench images' per-shade figure (bench_shade.c). */
#ifndef STIPPLE_PORTS_BENCH_SHADE_H
#define STIPPLE_PORTS_BENCH_SHADE_H

#include <stdint.h>

#include "stp_scene_data.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Instructions per stp_shade_point call, counted with SysTick: the inputs are
 * STP_FW_SHADE_INPUTS polygons spread evenly over the scene's polygon list
 * (a scene with fewer polygons repeats them; one with no direction is
 * replaced by the next that has one), with the scene's lighting (its
 * world-space lights), the polygons' materials and the eye of its view; every
 * input is shaded STP_FW_SHADE_REPEAT times.  The count covers the calls and
 * the loop around them (argument passing included, as the host benchmark's
 * ns per shade does) and is rounded to whole instructions; a SysTick tick is
 * per_tick instructions, so the figure is within per_tick / calls of the
 * count.  *calls receives the number of calls timed (0: no usable polygon). */
uint32_t stp_bench_shade(const stp_scene_data *s, uint32_t per_tick, uint32_t *calls);

#ifdef __cplusplus
}
#endif

#endif
