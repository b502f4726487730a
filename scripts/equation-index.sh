#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Writes docs/equations.md: for each equation and algorithm of the seed
# (numbered as in docs/model.md), the functions that compute it and the
# tests that check it, with file:line found by looking the names up in the
# sources now, so the line numbers follow edits.
# Usage: scripts/equation-index.sh           rewrite docs/equations.md
#        scripts/equation-index.sh --check   exit 1 (and show the diff) when
#                                            the committed file is stale or a
#                                            name is no longer found
# A name may be qualified by its file (src/render.c:newell) where it is
# defined in more than one place.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"

# seed | what it says, in our words | computed by | checked by
# (a line "## ..." starts a section)
table() {
    cat <<'TABLE'
## 1. Vectors and conventions
UNITY (Algorithm 10.2) | a vector divided by its length, the length returned; a zero vector reported, never divided by | stp_vec3_unity | test_vec3_unity_random test_vec3_unity_tiny_and_huge
(10.5) | the half-way vector H = (L+E)/\|L+E\| between the light and the eye | shade_parts | test_specular_terms_against_reference test_shade_highlight_sweep
eye direction | E from the point to the centre of projection, or the fixed direction of a parallel projection | enter_polygon shade_parts | test_shade_grid_against_reference test_backface_removal_keeps_faces_towards_viewer
Newell's normal (Algorithm 10.4) | the polygon's normal from the sums over its edges of (y'-y)(z'+z) and its cyclic companions, and the vertex average as the point to shade | src/render.c:newell | tests/stiff/test_stiff.c:test_case test_pictures_of_clipped_polygons
SHADE-CHECK | Newell's sums collected while a polygon is entered, its shade computed at the last vertex and entered before it as a fill style | enter_polygon src/render.c:newell | tests/stiff/test_stiff.c:test_case tests/golden/test_golden.c:test_golden_128x64
## 2. The shading equation
(10.1) | ambient light alone: v = B R | shade_parts | test_shade_back_face_is_ambient_only
(10.3) | one diffuse point light: v = B R + P R (L.N) | shade_parts | test_shade_grid_against_reference
(10.4) | facet distribution D = (k/(k+1-N.H))^2 | stp_specular | test_specular_terms_against_reference test_specular_terms_known_values
(10.6)-(10.8) | Fresnel reflection F from c = E.H and the index of refraction n | src/shade.c:fresnel stp_fresnel fresnel_xf | test_specular_terms_against_reference test_property_specular_terms tests/shade_accuracy/test_shade_accuracy.c:test_host
(10.9)-(10.11) | blocking and shadowing of facets: G = min(1, 2(N.H)(N.E)/(E.H), 2(N.H)(N.L)/(E.H)) | stp_specular | test_specular_terms_against_reference test_specular_terms_zero_for_nonpositive_cosines
(10.12) | the specular share D G F/(E.N) | specular_xf | test_shade_highlight_sweep test_property_shade_point tests/shade_accuracy/test_shade_accuracy.c:test_host
(10.14) | attenuation with distance 1/(C+U) | shade_parts | test_shade_light_at_point_is_head_on test_shade_grid_against_reference
(10.16) | the whole model: background share plus each light's diffuse and specular terms over C+U | stp_shade_point shade_parts stp_shade_combine | test_shade_grid_against_reference test_property_shade_point tests/stiff/test_stiff.c:test_case
MAKE-SHADE (Algorithm 10.5) | the shade of a face: background only when the light is behind it, capped at 1 and scaled by the brightness | shade_parts | test_shade_no_lights_and_caps test_shade_back_face_is_ambient_only
(10.45) | colour: the same equation per channel, the highlight colourless | stp_shade_point_colour | test_colour_shading_per_channel
INITIALIZE-10 | defaults: light at (0,0,1), brightness 1, no background; reflectivity 1, refraction 10, gloss 10; shading off | stp_lighting_default stp_material_default | test_seed_defaults
SET-LIGHT (Algorithms 10.7-10.11) | the light's position, brightness and background share, kept in [0,1] | stp_renderer_set_light stp_renderer_set_lighting | test_copy_light_per_segment tests/stiff/test_stiff.c:test_case
SET-OBJECT-SHADE | reflectivity, index of refraction and gloss of the polygons entered next | stp_renderer_set_object_shade | tests/stiff/test_stiff.c:test_case
SET-SHADING | shading on, or off with polygons in the current fill style | stp_renderer_set_shading stp_renderer_set_fill_style | test_set_shading
COPY-LIGHT | a segment keeps the lighting current when it was created, its lights turned into view coordinates | stp_segment_create | test_copy_light_per_segment
## 3. From shade to pixels
INTENSITY (Algorithm 10.6) | a shade in [0,1] to one of N styles, INT(s(N-1)+1) | stp_intensity_index | test_intensity_index_at_step_boundaries test_intensity_index_random_shades test_property_intensity
SHADE-STYLES | a table from style number to the device's own code (a line printer's character) | stp_style_lookup stp_style_inverse | test_style_table_lookup_and_inverse
(10.44) | gamma: drive V = (I/k)^(1/gamma), as a table | stp_gamma_table | test_gamma_table_against_reference test_gamma_table_identity_and_bad_arguments
halftone cells | ordered-dither threshold matrices: the seed's 2x2, Bayer cells, pattern cells, linear, exponential or cubic spacing | stp_cell_seed2x2 stp_cell_bayer_spaced stp_cell_pattern2x2 stp_cell_user | test_seed_2x2_cell_values test_spacings_for_2x2_equal_documented_numbers test_bayer_thresholds_match_imagemagick_ranks test_pattern2x2_levels
HALFTONE-FILLIN (Algorithm 10.12) | one span of a polygon: a pixel is on when the intensity exceeds the cell's threshold at (x mod w, y mod h) | stp_halftone_fillin | test_halftone_fillin_exact_bits test_halftone_fillin_single_pixel test_halftone_fillin_uses_x_mod_cell
ordered dither of a picture | every pixel of a grey row against the tiled cell | stp_halftone_row | test_halftone_row test_bayer4_equals_imagemagick_o4x4
## 4. Smooth shading (Gouraud)
Gouraud shading | a shade per vertex, stepped along edges and spans, each pixel through INTENSITY and its own threshold | stp_renderer_polygon_vertex_shades stp_renderer_polygon_smooth put_span_smooth | test_horizontal_ramp test_triangle_barycentric test_golden_smooth_teapot
## 5. Transparency, reflections, shadows, ray tracing
(10.18) | transmission through material t e^(-a d) | enter_polygon src/raytrace.c:absorb | test_blend_over_opaque_and_background tests/raytrace/test_raytrace.c:test_scenes_against_reference
(10.19) | Snell's law for the refracted ray | shade_hit | tests/raytrace/test_raytrace.c:test_scenes_against_reference tests/raytrace/test_raytrace.c:test_stiff_cases
(10.20) | painter's transparency v = v_r + t v_t, v_t read back through the inverse of INTENSITY | blend index_of_level stp_intensity_shade | test_blend_over_opaque_and_background test_intensity_shade_is_inverse
(10.21) | transparency by angle t = (t_max - t_min)(N.E)^a + t_min | enter_polygon | test_blend_over_opaque_and_background test_opaque_and_fully_transparent
(10.22), (10.23) | light reflected from another surface, weighted by F with c = E.N | shade_hit secondary | tests/raytrace/test_raytrace.c:test_scenes_against_reference
shadows | a shadow Z buffer per light; a point hidden from a light keeps only the background share | stp_shadow_enter stp_shadow_records stp_shadow_polygon | test_square_over_floor test_two_lights test_no_acne_at_grazing_light
ray tracing | a ray per pixel, the nearest hit shaded by (10.16), shadow rays, reflected and refracted rays until they miss or weigh too little | stp_rt_render src/raytrace.c:trace shade_hit nearest_hit | tests/raytrace/test_raytrace.c:test_scenes_against_reference test_hierarchy_equals_every_object tests/raytrace/test_raytrace.c:test_stiff_cases
## 6. Colour
(10.25)-(10.27) | chromaticity x, y, z from X, Y, Z and back | stp_colour_rgb_to_xyz_matrix | test_seed_monitor_matrix_and_inverse
(10.28)-(10.36) | the RGB to XYZ matrix from the primaries and the white point, and its inverse | stp_colour_rgb_to_xyz_matrix_xyz stp_mat3_inverse | test_seed_monitor_matrix_and_inverse test_singular_and_bad_input
(10.37) | CMY = 1 - RGB, and CMYK | stp_rgb_to_cmy stp_rgb_to_cmyk | test_round_trips_over_the_cube
(10.38) | YIQ; Y the luminance a monochrome display shows | stp_rgb_to_iqy stp_rgb_luminance | test_yiq_luminance
(10.39)-(10.42) | HSI: RGB turned so the grey axis is the third, hue and saturation from the other two | stp_rgb_to_hsi stp_hsi_to_rgb | test_hsv_hls_hsi_known_values test_round_trips_over_the_cube
HSV (Algorithms 10.13, 10.14) | the hexcone | stp_rgb_to_hsv stp_hsv_to_rgb | test_hsv_hls_hsi_known_values test_round_trips_over_the_cube
HLS | the double hexcone | stp_rgb_to_hls stp_hls_to_rgb | test_hsv_hls_hsi_known_values test_round_trips_over_the_cube
colour tables | 256 entries of 24-bit colour indexed by the frame's values: grey, pseudocolour, gamma per primary | stp_colour_table_grey stp_colour_table_pseudocolour stp_colour_table_apply_gamma | test_colour_tables
## 7. The display file
DISPLAY-FILE-ENTER (Algorithm 10.3) | each point to view coordinates, shaded, clipped, projected and stored as an instruction | enter_polygon stp_renderer_move stp_renderer_line | test_display_file_full_leaves_it_unchanged tests/golden/test_golden.c:test_golden_128x64
segments | created, closed, deleted, shown or hidden | stp_segment_create stp_segment_close stp_segment_delete stp_segment_visibility | test_segment_errors test_segment_delete_compacts_and_visibility test_segment_table_full
clipping and projection | against the hither plane and the window, then perspective or parallel | clip_polygon project | test_hither_clipping test_polygon_behind_the_eye_enters_nothing test_pictures_of_clipped_polygons
back-face removal | faces with N.E <= 0 dropped | enter_polygon | test_backface_removal_keeps_faces_towards_viewer test_backface_removal_single_polygon
painter's algorithm | polygons drawn far to near | stp_sort_far_to_near | test_hidden_surfaces_nearer_square_wins
Z buffer | the nearest surface per pixel | put_span_z | test_zbuffer_interpenetrating_polygons
direct drawing | no display file: a mesh through the renderer's geometry and face stages (the model composed with the view once a frame, exact in 32 bits; the mesh route's back-face test and shading), projected once per frame, painted in mesh order or far to near (the renderer's painter's sort) straight into bands with the same fill rule, a face the picture's edge or the near plane cuts clipped by the renderer's clipper and projection: the mesh route's pixels | stp_direct_frame_project stp_view_compose_small project_point stp_direct_frame_sort stp_direct_draw_band stp_direct_face_clip | tests/direct/test_direct_equal.c:test_torus_128x64 tests/direct/test_direct_equal.c:test_edges_128x64 tests/direct/test_direct_equal.c:test_near_128x64 tests/direct/test_direct_equal.c:test_tetra_s2_400x240 tests/mesh/test_view_small.c:test_compose_is_the_renderers tests/direct/test_direct.c:test_torus tests/direct/test_direct.c:test_bands
TABLE
}

# Every function definition in the core (its .c files and private headers)
# as "name file:line": a line starting
# with its return type or its name whose parameter list ends in '{' (not in
# ';', as a declaration's does).
list_functions() {
    # shellcheck disable=SC2016
    find src \( -name '*.c' -o -name '*.h' \) -type f | sort | xargs awk '
        FNR == 1 { open = 0 }
        open == 0 && match($0, /^([A-Za-z_][A-Za-z0-9_ *]*[ *])?[A-Za-z_][A-Za-z0-9_]*[(]/) {
            head = substr($0, 1, RLENGTH - 1); sub(/.*[ *]/, "", head)
            open = 1; at = FNR; name = head
        }
        open == 1 && /;[[:space:]]*$/ { open = 0 }
        open == 1 && /[{][[:space:]]*$/ { print name, FILENAME ":" at; open = 0 }'
}

# Every cmocka test function as "name file:line".
list_tests() {
    grep -rHn --include='*.c' -E '^static void [A-Za-z0-9_]+\(void \*\*' tests |
        sed -E 's/^([^:]*):([0-9]*):static void ([A-Za-z0-9_]*).*/\3 \1:\2/'
}

# file:line of NAME (or PATH:NAME, PATH a prefix of the file) in a list.
find_in() {
    local list=$1 name=${2##*:} path="" hits
    [ "$name" != "$2" ] && path=${2%:*}
    hits=$(printf '%s\n' "$list" | awk -v n="$name" -v p="$path" \
        '$1 == n && index($2, p) == 1 { print $2 }')
    report_one "$2" "$hits"
}
find_function() { find_in "$functions_list" "$1"; }
find_test() { find_in "$tests_list" "$1"; }

report_one() {
    local count
    count=$(printf '%s' "$2" | grep -c . || true)
    if [ "$count" -ne 1 ]; then
        echo "equation-index: '$1' is defined $count times${2:+: $(printf '%s' "$2" | tr '\n' ' ')}" >&2
        echo "  (qualify it as path:name, or update the table in scripts/equation-index.sh)" >&2
        return 1
    fi
    printf '%s\n' "$2"
}

# "`name` [file:line](../file#Lline)" for each name, joined by "<br>".
cells() {
    local kind=$1 out="" name at
    shift
    for name in "$@"; do
        at=$("find_$kind" "$name") || return 1
        out="$out${out:+<br>}\`${name##*:}\` [${at}](../${at%%:*}#L${at##*:})"
    done
    printf '%s' "$out"
}

generate() {
    local status=0 seed what functions tests f t
    echo "<!-- SPDX-License-Identifier: MIT -->"
    echo "# Where the seed's equations are computed and tested"
    echo
    echo "Generated by \`scripts/equation-index.sh\` from the names in its table;"
    echo "do not edit by hand (the test \`equation_index\` fails when this file is"
    echo "stale).  Equation numbers (10.x) and algorithm names are the seed"
    echo "chapter's; [model.md](model.md) restates what each one says.  Tests are"
    echo "cmocka functions: \`ctest -R PROGRAM\` runs the file's program."
    while IFS= read -r line; do
        case "$line" in
        '## '*)
            printf '\n%s\n\n| seed | what it says | computed by | checked by |\n|---|---|---|---|\n' "$line"
            continue
            ;;
        esac
        IFS='|' read -r seed what functions tests <<<"${line//\\|/$'\1'}"
        # shellcheck disable=SC2086
        f=$(cells function $functions) || status=1
        # shellcheck disable=SC2086
        t=$(cells test $tests) || status=1
        seed=$(echo "$seed" | sed 's/ *$//')
        what=$(echo "$what" | sed 's/^ *//; s/ *$//' | tr '\1' '|' | sed 's/|/\\|/g')
        printf '| %s | %s | %s | %s |\n' "$seed" "$what" "$f" "$t"
    done < <(table)
    return $status
}

target=docs/equations.md
functions_list=$(list_functions)
tests_list=$(list_tests)
if [ "${1:-}" = --check ]; then
    fresh=$(mktemp)
    trap 'rm -f "$fresh"' EXIT
    generate >"$fresh" || { echo "equation-index: a name in the table is not found (above)" >&2; exit 1; }
    if ! diff -u "$target" "$fresh"; then
        echo "equation-index: $target is stale: run scripts/equation-index.sh and commit it" >&2
        exit 1
    fi
    echo "$target is current"
else
    tmp=$(mktemp "$target.XXXXXX")
    trap 'rm -f "$tmp"' EXIT
    generate >"$tmp"
    mv "$tmp" "$target"
    trap - EXIT
    echo "wrote $target"
fi
