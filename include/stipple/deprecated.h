/* SPDX-License-Identifier: MIT */
/*
 * The renderer's names before 0.3 (issue 12: module first, stp_renderer_*),
 * kept as macros for one release; define STP_NO_DEPRECATED to hide them.
 * scripts/rename-api.sh rewrites a source tree to the new names.
 */
#ifndef STIPPLE_DEPRECATED_H
#define STIPPLE_DEPRECATED_H

#ifdef __cplusplus
extern "C" {
#endif

#ifndef STP_NO_DEPRECATED
#define stp_set_view(r, view) stp_renderer_set_view(r, view)
#define stp_set_light(r, position, brightness, background)                                         \
    stp_renderer_set_light(r, position, brightness, background)
#define stp_set_lighting(r, lighting) stp_renderer_set_lighting(r, lighting)
#define stp_set_object_shade(r, material) stp_renderer_set_object_shade(r, material)
#define stp_set_shading(r, on) stp_renderer_set_shading(r, on)
#define stp_set_fill_style(r, index) stp_renderer_set_fill_style(r, index)
#define stp_set_colour(r, on) stp_renderer_set_colour(r, on)
#define stp_set_transparency(r, t_min, t_max, power, absorption, thickness)                        \
    stp_renderer_set_transparency(r, t_min, t_max, power, absorption, thickness)
#define stp_set_levels(r, levels) stp_renderer_set_levels(r, levels)
#define stp_set_backface_removal(r, on) stp_renderer_set_backface_removal(r, on)
#define stp_set_shadow_map(r, light, depth, count, width, height, view)                            \
    stp_renderer_set_shadow_map(r, light, depth, count, width, height, view)
#define stp_remove_shadow_map(r, light) stp_renderer_remove_shadow_map(r, light)
#define stp_move(r, p) stp_renderer_move(r, p)
#define stp_line(r, p) stp_renderer_line(r, p)
#define stp_polygon(r, vertices, n) stp_renderer_polygon(r, vertices, n)
#define stp_polygon_smooth(r, vertices, normals, n) stp_renderer_polygon_smooth(r, vertices, normals, n)
#define stp_polygon_vertex_shades(r, vertices, shades, n)                                          \
    stp_renderer_polygon_vertex_shades(r, vertices, shades, n)
#define stp_display_file_used(r) stp_renderer_display_file_used(r)
#define stp_polygon_count(r) stp_renderer_polygon_count(r)
#define stp_last_shade(r) stp_renderer_last_shade(r)
#define stp_render(r, port, output, memory) stp_renderer_render(r, port, output, memory)
#endif

#ifdef __cplusplus
}
#endif

#endif
