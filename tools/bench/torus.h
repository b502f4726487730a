/* SPDX-License-Identifier: MIT */
/*
 * The torus workload of issue 11 (host): one frame of a real-time firmware
 * user, re-entering every polygon of a lit model and producing a finished
 * 1-bit frame.
 *
 * Scene: a torus of major radius 1 and minor radius 0.4 about the y axis,
 * 25 x 20 quads split into 1000 triangles wound counter-clockwise seen from
 * outside; eye at distance 6 along (0, 3, 5.2) looking at the centre, y up,
 * 35 degrees across the shorter side; one point light at (-4, 6, 5); NFF
 * material Kd 0.7, Ks 0.4, Shine 20, white.  The view, lights and material
 * go through the stipple command's mapping (stp_tool_setup,
 * stp_tool_material: background 0.2, C 1, the light's power cancelling its
 * attenuation at the centre), so tools/bench/render_ref.c renders the same
 * scene for the tests.
 *
 * Frame (torus_frame): delete and re-create the segment, set the model
 * transform when the bench is posed (torus_bench_pose), stp_renderer_polygon for
 * each of the 1000 triangles from the caller's stp_vec3 array (shading on:
 * full seed shading D.G.F and attenuation; back-face removal on), then
 * stp_renderer_render to MONO1 (MSB-first rows) with the Z buffer, 16 levels and the
 * Bayer 4x4 cell in one band; the port's flush copies the band into
 * frame[].
 */
#ifndef STIPPLE_TOOLS_BENCH_TORUS_H
#define STIPPLE_TOOLS_BENCH_TORUS_H

#include <stddef.h>
#include <stdint.h>

#include "scene.h"
#include "stipple/stipple.h"

#define TORUS_AROUND 25
#define TORUS_TUBE 20
#define TORUS_TRIANGLES (2 * TORUS_AROUND * TORUS_TUBE)

/* The torus as a host scene (three vertices per triangle, in order).
 * Returns 0, or -1 out of memory; free with stp_scene_free. */
int torus_scene_build(stp_scene *s);

typedef struct torus_bench {
    int width, height;
    stp_scene scene;
    stp_renderer *r;
    void *renderer_mem;
    stp_instr *df;
    uint32_t capacity;
    stp_vec3 *vertices; /* 3 per triangle, world units */
    stp_material material;
    stp_cell cell;
    stp_output output;
    stp_frame_memory memory;
    stp_port port;
    uint8_t *band;
    uint16_t *zbuf;
    uint8_t *frame;     /* the finished frame: height rows of stride bytes */
    size_t stride;
    stp_fix shade[TORUS_TRIANGLES]; /* stp_renderer_last_shade of each triangle's entry,
                                       -1 when nothing was shaded (back face) */
    int keep_shades;                /* 1: fill shade[] during torus_frame */
    int posed;                      /* 1: enter through `pose` (stp_renderer_set_transform) */
    stp_transform pose;
    int use_mesh;                   /* 1: enter through stp_renderer_mesh (torus_bench_use_mesh) */
    stp_mesh mesh;                  /* vertices[] with exact duplicates merged */
    stp_vec3 *mesh_vertices;
    uint16_t *mesh_triangles;
    int16_t *mesh_normals;
    stp_mesh_bounds *mesh_bounds;   /* each mesh's (stp_mesh_prepare_bounds): one, or one a part */
    stp_mesh_vertex *mesh_scratch;
    /* the meshes torus_frame enters, in order (torus_bench_use_mesh: the
     * one above; torus_bench_use_fine_mesh: a finer torus in parts) */
    const stp_mesh *parts;
    int part_count;
    size_t scratch_count;           /* entries of mesh_scratch */
    stp_mesh *fine_parts;
} torus_bench;

/* The most triangles (and vertices) one stp_mesh holds: a finer torus is
 * entered in parts of at most this many. */
#define TORUS_PART_MAX 65535u

/* Pose the model for the next frames: tilt about x, then spin about y (the
 * torus's axis), then move by (dx, dy, dz), through the core's model
 * transform; the vertex array is not touched. */
void torus_bench_pose(torus_bench *b, double tilt_degrees, double spin_degrees, double dx,
                      double dy, double dz);

/* Set up a width x height bench (the scene, renderer, memory).  Returns 0,
 * or -1 with a message in err. */
int torus_bench_init(torus_bench *b, int width, int height, char *err, size_t err_size);
/* The same with a display file for `triangles` triangles (>= 1; the
 * default above is TORUS_TRIANGLES), for torus_bench_use_fine_mesh. */
int torus_bench_init_for(torus_bench *b, int width, int height, size_t triangles, char *err,
                         size_t err_size);
void torus_bench_free(torus_bench *b);

/* Enter the next frames through stp_renderer_mesh instead of one
 * stp_renderer_polygon per triangle: the triangles' vertices as an indexed
 * mesh (exactly equal vertices merged, so every vertex is the one the
 * polygon path enters), normals prepared here.  Returns 0, or -1 with a
 * message in err. */
int torus_bench_use_mesh(torus_bench *b, char *err, size_t err_size);

/* Enter the next frames through stp_renderer_mesh as a finer torus of the
 * same shape: around x tube quads (2 x around x tube triangles in
 * torus_scene_build's order and winding, each vertex computed once), in
 * parts of whole rings of at most part_max triangles and vertices (0 or
 * above TORUS_PART_MAX: TORUS_PART_MAX, as an stp_mesh counts them in 16
 * bits; at least 2 x tube), the rings shared out evenly, normals prepared
 * here, one stp_renderer_mesh call per part.  The bench must come from
 * torus_bench_init_for with at least that many triangles.  Returns 0, or
 * -1 with a message in err. */
int torus_bench_use_fine_mesh(torus_bench *b, int around, int tube, unsigned part_max, char *err,
                              size_t err_size);

/* One frame, as described above.  Returns 0, or -1 when the core refused
 * something (a bug: the workload fits by construction). */
int torus_frame(torus_bench *b);

#endif
