# SPDX-License-Identifier: MIT
# Issue 12: one naming rule, module first (stp_<module>_<action>).  The
# polygon renderer's calls take the module name of their handle,
# stp_renderer_, as the ray tracer's take stp_rt_.  Applied to every tracked
# file by scripts/rename-api.sh; running it again changes nothing (the new
# names do not contain the old ones as whole words).  The old names stay as
# deprecated macros for one release (include/stipple/deprecated.h).
s/\bstp_set_view\b/stp_renderer_set_view/g
s/\bstp_set_light\b/stp_renderer_set_light/g
s/\bstp_set_lighting\b/stp_renderer_set_lighting/g
s/\bstp_set_object_shade\b/stp_renderer_set_object_shade/g
s/\bstp_set_shading\b/stp_renderer_set_shading/g
s/\bstp_set_fill_style\b/stp_renderer_set_fill_style/g
s/\bstp_set_colour\b/stp_renderer_set_colour/g
s/\bstp_set_transparency\b/stp_renderer_set_transparency/g
s/\bstp_set_levels\b/stp_renderer_set_levels/g
s/\bstp_set_backface_removal\b/stp_renderer_set_backface_removal/g
s/\bstp_set_shadow_map\b/stp_renderer_set_shadow_map/g
s/\bstp_remove_shadow_map\b/stp_renderer_remove_shadow_map/g
s/\bstp_move\b/stp_renderer_move/g
# stp_line is also the scene readers' line type (tools/scene): calls only
s/\bstp_line(/stp_renderer_line(/g
s/\bstp_polygon\b/stp_renderer_polygon/g
s/\bstp_polygon_smooth\b/stp_renderer_polygon_smooth/g
s/\bstp_polygon_vertex_shades\b/stp_renderer_polygon_vertex_shades/g
s/\bstp_display_file_used\b/stp_renderer_display_file_used/g
s/\bstp_polygon_count\b/stp_renderer_polygon_count/g
s/\bstp_last_shade\b/stp_renderer_last_shade/g
s/\bstp_render\b/stp_renderer_render/g
s/\bstp_set_transform\b/stp_renderer_set_transform/g
