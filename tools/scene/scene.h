/* SPDX-License-Identifier: MIT */
/*
 * Host-side scene model and readers (NFF, Wavefront OBJ, OFF, PLY).
 * Host code: may use libc, the heap and double precision.  The stipple
 * command turns a stp_scene into calls of the fixed-point core.
 */
#ifndef STIPPLE_TOOLS_SCENE_H
#define STIPPLE_TOOLS_SCENE_H

#include <stddef.h>

typedef struct stp_scene_vec3 {
    double x, y, z;
} stp_scene_vec3;

/* NFF "f": colour, Kd, Ks, Shine (Phong exponent), T (transmittance),
 * index of refraction.  OBJ/OFF meshes get one default material. */
typedef struct stp_scene_material {
    double color[3];
    double kd, ks, shine, t, ior;
} stp_scene_material;

typedef struct stp_scene_light {
    stp_scene_vec3 position;
    double color[3]; /* 1,1,1 when the file gives none */
} stp_scene_light;

/* A polygon: count vertices starting at vertices[first]; when has_normals,
 * normals[first..first+count-1] are its vertex normals (NFF pp, OBJ vn,
 * unit length as given by the file, not renormalised). */
typedef struct stp_scene_polygon {
    size_t first;
    int count;
    int material;    /* index into materials */
    int has_normals;
    int source_line; /* line of the file it came from (for messages) */
    int prim;        /* index into prims of the sphere or cone it
                        tessellates, -1 for the file's own polygons */
} stp_scene_polygon;

/* Analytic primitives are kept (for a ray tracer) besides being tessellated
 * into polygons. */
typedef enum stp_scene_prim_kind { STP_SCENE_SPHERE, STP_SCENE_CONE } stp_scene_prim_kind;
typedef struct stp_scene_prim {
    stp_scene_prim_kind kind;
    stp_scene_vec3 base, apex; /* sphere: base = centre */
    double base_radius, apex_radius; /* sphere: base_radius = radius */
    int material;
} stp_scene_prim;

typedef struct stp_scene {
    int has_view;             /* NFF "v" present */
    stp_scene_vec3 from, at, up;
    double angle;             /* degrees */
    double hither;
    int resolution[2];
    int has_background;
    double background[3];

    stp_scene_light *lights;
    size_t light_count;
    stp_scene_material *materials;
    size_t material_count;

    stp_scene_vec3 *vertices; /* all polygons' vertices, in order */
    stp_scene_vec3 *normals;  /* parallel to vertices; zero where none */
    size_t vertex_count;
    stp_scene_polygon *polygons;
    size_t polygon_count;
    stp_scene_prim *prims;
    size_t prim_count;
} stp_scene;

typedef struct stp_scene_options {
    /* Tessellation of NFF spheres and cones for the polygon renderer:
     * slices around (>= 3) and, for spheres, stacks pole to pole (>= 2). */
    int sphere_slices, sphere_stacks;
    int cone_slices;
    /* 1: NFF spheres and cones are kept only as prims, not tessellated
     * (for the ray tracer, which traces them analytically); 0 (default):
     * both. */
    int analytic_only;
} stp_scene_options;

/* Defaults: 16 slices, 8 stacks, 16 cone slices, tessellated. */
void stp_scene_options_default(stp_scene_options *opt);

/* Read a scene; the format is chosen by the extension (.nff, .obj, .off,
 * .ply; case-insensitive).  On error returns -1 and writes "path:line: what is
 * wrong" (or "path: what is wrong" when no line applies) into err; the scene
 * is then empty (freed).  Returns 0 on success. */
int stp_scene_load(const char *path, const stp_scene_options *opt, stp_scene *scene,
                   char *err, size_t err_size);

/* The same with the format given ("nff", "obj", "off", "ply"), or chosen
 * by the extension when format is NULL.  path "-" reads standard input
 * (named "stdin" in messages; it is not closed), which needs a format. */
int stp_scene_load_as(const char *path, const char *format, const stp_scene_options *opt,
                      stp_scene *scene, char *err, size_t err_size);

/* The same from a memory buffer, format given as "nff", "obj", "off" or
 * "ply" (binary PLY bodies give "path: byte N: what" instead of a line);
 * name is used in messages (for fuzzing and tests). */
int stp_scene_parse(const char *text, size_t size, const char *format, const char *name,
                    const stp_scene_options *opt, stp_scene *scene, char *err, size_t err_size);

void stp_scene_free(stp_scene *scene);

#endif
