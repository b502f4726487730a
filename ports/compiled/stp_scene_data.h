/* SPDX-License-Identifier: MIT */
/*
 * A scene compiled to C data (by `stipple compile`, tools/compile_scene.c),
 * and the one routine that feeds it to the core.
 *
 * Used where there is no file system and no floating point: the host tool
 * does every double-precision step (reading NFF, choosing the view and the
 * light powers, converting to stp_fix) and writes the results as integer
 * literals, so a firmware build makes exactly the core calls the host's
 * stp_tool_render makes and gets the same picture, pixel for pixel.
 *
 * Portable C99, no libc, no heap: the display file and the painter's sort
 * array are arrays in the generated source, sized for the scene.
 */
#ifndef STIPPLE_PORTS_SCENE_DATA_H
#define STIPPLE_PORTS_SCENE_DATA_H

#include <stdint.h>
#include "stipple/stipple.h"

/* Where the generated source keeps its vertex, polygon and material tables
 * (STP_SCENE_ROM after the array's name).  Where const data is read in
 * place, nothing; on an AVR, whose const data is otherwise copied into its
 * few KB of SRAM at start-up, program memory, read a record at a time
 * through STP_SCENE_ROM_COPY(dst, src, bytes). */
#if defined(__AVR__)
#include <avr/pgmspace.h>
#define STP_SCENE_ROM PROGMEM
#define STP_SCENE_ROM_COPY(dst, src, bytes) memcpy_P((dst), (src), (bytes))
#else
#define STP_SCENE_ROM
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* One polygon: count vertices, taken in order from the scene's vertex array
 * (polygon i starts where polygon i-1 ended), and its material's index. */
typedef struct stp_scene_data_polygon {
    uint16_t count;
    uint16_t material;
} stp_scene_data_polygon;

typedef struct stp_scene_data {
    uint32_t width, height;        /* the device size the view was set for */
    int levels;                    /* INTENSITY levels */
    int shading;                   /* 1: MAKE-SHADE; 0: material fill styles */
    int backface_removal;
    stp_view view;
    stp_lighting lighting;         /* world-space light positions */
    const stp_material *materials; /* only the materials polygons use (STP_SCENE_ROM) */
    uint32_t material_count;
    const stp_vec3 *vertices;      /* world space (STP_SCENE_ROM) */
    uint32_t vertex_count;
    const stp_scene_data_polygon *polygons; /* STP_SCENE_ROM */
    uint32_t polygon_count;
    stp_instr *display_file;       /* capacity: what the scene enters */
    uint32_t display_capacity;
    stp_sort_entry *sort;          /* painter only, else NULL */
    uint32_t sort_count;
    stp_hidden hidden;             /* what the output should use */
    const stp_cell *cell;          /* the halftone cell, as a value in ROM */
    const uint8_t *gamma;          /* levels entries, or NULL for linear */
    stp_fix background;            /* shade of the empty frame */
    const stp_diffusion *diffusion; /* MONO1 error diffusion (its error rows
                                       in RAM; the band then holds GREY8
                                       rows), or NULL: the cell */
} stp_scene_data;

/* The generated source defines this one object. */
extern const stp_scene_data stp_compiled_scene;

/* A static scene (`stipple compile --static`): the display file entered on
 * the host, as const data, played back by stp_playback_create's renderer. */
typedef struct stp_scene_static {
    uint32_t width, height;        /* the device size it was entered for */
    int levels;                    /* INTENSITY levels */
    int fill_style;                /* style in force before the first SHADE */
    const stp_instr *display_file; /* used entries */
    uint32_t display_used;
    stp_sort_entry *sort;          /* painter only, else NULL */
    uint32_t sort_count;
    stp_hidden hidden;
    const stp_cell *cell;
    const uint8_t *gamma;
    stp_fix background;
} stp_scene_static;

/* The generated source of a static scene defines this one object. */
extern const stp_scene_static stp_compiled_static;

/* A static scene compiled with --spans: its picture as visible spans
 * (stipple/playback_spans.h), drawn with stp_spans_draw. */
extern const stp_spans stp_compiled_spans;

/* The renderer over the scene's display file in mem (stp_renderer_size()
 * bytes); *out receives it.  Returns STP_OK or STP_ERR_ARG. */
int stp_scene_static_open(const stp_scene_static *scene, void *mem, size_t mem_size,
                          stp_renderer **out);

/* The output settings the static scene was compiled with. */
void stp_scene_static_output(const stp_scene_static *scene, stp_output *out);

/* Create the renderer in mem (stp_renderer_size() bytes) over the scene's
 * display file and enter the scene into segment 1, as stp_tool_render does
 * (degenerate polygons skipped).  *out receives the renderer.  Returns
 * STP_OK or the first core error. */
int stp_scene_data_enter(const stp_scene_data *scene, void *mem, size_t mem_size,
                         stp_renderer **out);

/* The output settings the scene was compiled with. */
void stp_scene_data_output(const stp_scene_data *scene, stp_output *out);

/* The frame memory a firmware lends stp_renderer_render for a compiled scene:
 * band_rows rows in band (band_size bytes), the scene's sort array, no kept
 * per-polygon setups and no Z buffer — a build with STP_WITH_ZBUFFER sets
 * zbuf and zbuf_count afterwards. */
static inline void stp_scene_frame_memory(stp_frame_memory *mem, uint8_t *band, size_t band_size,
                                          uint32_t band_rows, stp_sort_entry *sort,
                                          uint32_t sort_count)
{
    mem->band = band;
    mem->band_size = band_size;
    mem->band_rows = band_rows;
    mem->zbuf = 0;
    mem->zbuf_count = 0;
    mem->sort = sort;
    mem->sort_count = sort_count;
    mem->setup = 0;
    mem->setup_count = 0;
}

#ifdef __cplusplus
}
#endif

#endif
