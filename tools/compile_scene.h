/* SPDX-License-Identifier: MIT */
/*
 * Host side: compile a scene into C for a firmware build (`stipple compile`).
 *
 * Output 1, a C source: the scene as world-space polygon vertex arrays of
 * stp_fix integer literals, the view, the lighting (light powers already
 * worked out as stp_tool_render works them out), the materials, the
 * halftone cell and gamma table, and the display file and sort array sized
 * exactly for the scene.  It defines `stp_compiled_scene`
 * (ports/compiled/stp_scene_data.h), which stp_scene_data_enter feeds to the
 * core with the same calls stp_tool_render makes, so the firmware's picture
 * equals `stipple render` with the same options.
 *
 * Output 2, a configuration header for STP_CONFIG_HEADER: every switch of
 * include/stipple/config.h at the least the scene needs.
 */
#ifndef STIPPLE_TOOLS_COMPILE_SCENE_H
#define STIPPLE_TOOLS_COMPILE_SCENE_H

#include <stddef.h>
#include <stdio.h>
#include "render_scene.h"
#include "scene.h"

/* Write the scene's C source to c_out and its configuration header to h_out
 * (either may be NULL to skip it) for the options opt (size, levels, cell,
 * gamma, hidden-surface method, lights... as for stp_tool_render; band_rows
 * and styles are ignored: the firmware picks its band, and the output is
 * MONO1).  Returns 0, or -1 with a message in err. */
int stp_tool_compile(const stp_scene *scene, const stp_tool_options *opt, FILE *c_out,
                     FILE *h_out, char *err, size_t errlen);

/* The `stipple compile` subcommand: argv[0] is "compile".  Returns the exit
 * status (0 done, 1 failure, 2 usage). */
/* As stp_tool_compile, but c_out gets the static scene: the display file the
 * host core entered, as const data (stp_scene_static, stp_compiled_static). */
int stp_tool_compile_static(const stp_scene *scene, const stp_tool_options *opt, FILE *c_out,
                            FILE *h_out, char *err, size_t errlen);

/* As stp_tool_compile_static, but c_out gets the host's picture as visible
 * spans (stp_spans, stp_compiled_spans; tools/static_spans.h): no error
 * diffusion, cells of 1, 2, 4 or 8 pixels each way, at most 256 wide. */
int stp_tool_compile_spans(const stp_scene *scene, const stp_tool_options *opt, FILE *c_out,
                           FILE *h_out, char *err, size_t errlen);

int stp_tool_compile_main(int argc, char **argv);

/* Its help text. */
void stp_tool_compile_usage(FILE *to);

#endif
