/* SPDX-License-Identifier: MIT */
/*
 * Host side of `stipple compile --spans`: a static scene's display file
 * played back through the host core, once as GREY8 (each pixel's 8-bit
 * level) and once as MONO1 (the picture the firmware must show), turned into
 * rows of runs of one level (include/stipple/playback_spans.h) and checked:
 * the spans played back by stp_spans_draw must give the MONO1 picture pixel
 * for pixel, or the compile fails.
 */
#ifndef STIPPLE_TOOLS_STATIC_SPANS_H
#define STIPPLE_TOOLS_STATIC_SPANS_H

#include <stddef.h>
#include <stdint.h>
#include "stipple/stipple.h"
#include "stipple/playback_spans.h"

typedef struct stp_tool_spans {
    uint8_t *runs;           /* malloc'ed, run_bytes */
    size_t run_bytes;
    uint8_t patterns[256 * 8]; /* shade_count * cell_rows used */
    int shade_count, cell_rows;
    uint8_t levels[256];     /* shade index -> 8-bit level (for comments) */
} stp_tool_spans;

/* The spans of display file df[0, used) (a width x height picture of
 * `levels` levels, first fill style fill_style) drawn with output (its
 * hidden-surface method, cell, gamma, background; no diffusion).  Returns 0
 * (free s->runs), or -1 with a message in err: the picture wider than 256
 * or higher than 32767, a cell that is not 1, 2, 4 or 8 pixels each way (or
 * a mask cell), a core error, or spans that do not give the core's
 * picture. */
int stp_tool_static_spans(const stp_instr *df, uint32_t used, uint32_t width, uint32_t height,
                          int levels, int fill_style, const stp_output *output,
                          stp_tool_spans *s, char *err, size_t errlen);

#endif
