/* SPDX-License-Identifier: MIT */
/*
 * Host side: render a stp_scene through the fixed-point core onto a port.
 * Used by the stipple command, the golden-image tests and the benchmarks.
 */
#ifndef STIPPLE_TOOLS_RENDER_SCENE_H
#define STIPPLE_TOOLS_RENDER_SCENE_H

#include <stddef.h>
#include "scene.h"
#include "stipple/stipple.h"

typedef enum stp_tool_dither {
    STP_TOOL_DITHER_BAYER2,
    STP_TOOL_DITHER_BAYER4,
    STP_TOOL_DITHER_BAYER8,
    STP_TOOL_DITHER_SEED2X2,
    STP_TOOL_DITHER_PATTERN2X2,
    STP_TOOL_DITHER_USER,
    STP_TOOL_DITHER_DIFFUSE, /* error diffusion (MONO1): diffuse_kernel */
    STP_TOOL_DITHER_BAYER16,
    STP_TOOL_DITHER_BLUE_NOISE, /* the core's 64x64 void-and-cluster mask */
    STP_TOOL_DITHER_CLUSTERED   /* clustered dots: clustered_n, clustered_angle */
} stp_tool_dither;

/* Most --eye or --at keys of an animation's camera path. */
#define STP_TOOL_CAMERA_KEYS 16

typedef struct stp_tool_options {
    int width, height;       /* device pixels (default 128 x 64) */
    int levels;              /* INTENSITY levels (16) */
    stp_tool_dither dither;  /* (Bayer 4x4) */
    stp_spacing spacing;     /* threshold spacing of Bayer cells (linear) */
    int diffuse_kernel;      /* STP_TOOL_DITHER_DIFFUSE: stp_diffusion_kernel */
    int diffuse_raster;      /* 1: every row left to right (0: serpentine) */
    int diffuse_noise;       /* 1: thresholds modulated by the blue-noise mask
                                (STP_DIFFUSE_NOISE_AMPLITUDE_OF, _BAND; diffuse.h) */
    int dither_given, levels_given; /* the option parser saw -d / -l */
    int clustered_n, clustered_angle; /* STP_TOOL_DITHER_CLUSTERED: side, 0 or 45 */
    /* tone (tone.h): */
    int exposure_auto;       /* 1: BRIGHT scaled so the brightest drawn pixel
                                reaches the top level (0; 1 for a still PBM) */
    int exposure_given;      /* the option parser saw --exposure */
    int grey_contrast;       /* 1: grey keeps the colours' contrast (0) */
    int background_given;    /* 1: background_rgb replaces the scene's */
    double background_rgb[3];
    int user_cell_w, user_cell_h;
    unsigned char user_cell[STP_CELL_MAX * STP_CELL_MAX];
    double gamma, gamma_k;   /* (10.44): 1, 1 = linear */
    stp_hidden hidden;       /* (Z buffer) */
    int backface_removal;    /* (0) */
    int shading;             /* 1: MAKE-SHADE per polygon (1) */
    int colour;              /* 1: shade per channel (10.45) with NFF colours;
                                RGB888 ports show colour (0) */
    int transparency;        /* 1: NFF's T makes surfaces transparent (0) */
    unsigned shadow_resolution; /* >0: a shadow map of this many texels square
                                   per light (0: no shadows) */
    int smooth;              /* 1: Gouraud from vertex normals: the file's
                                (NFF pp, OBJ vn), else averaged face normals (0);
                                large polygons are split first (subdivide.h) */
    int subdivided;          /* 1: smooth polygons already split (internal) */
    int edge_aa;             /* 1: anti-aliased polygon edges (stp_output.edge_aa) (0) */
    int band_rows;           /* 0: whole frame (page ports: rounded up to 8) */
    double background;       /* BKGRND, the indirect share (0.2) */
    double brightness;       /* BRIGHT (1) */
    double attenuation_c;    /* C of 1/(C+U) (1) */
    int auto_power;          /* 1: light powers cancel attenuation at the
                                scene centre (see render_scene.c) (1) */
    int light_count;         /* >0: these lights replace the scene's */
    stp_scene_vec3 lights[STP_MAX_LIGHTS];
    int perspective;         /* 1 (0: parallel) */
    double fov;              /* degrees; 0: the scene's, else 45 */
    const stp_style_table *styles; /* STYLE8 codes (NULL: index) */
    int raytrace;            /* 1: the ray tracer instead of the polygon
                                renderer (0); NFF spheres and cones stay
                                analytic, T is transmission */
    int rt_depth;            /* ray tracer: maximum recursion depth (4) */
    double rt_min_weight;    /* ray tracer: weight below which a secondary
                                ray is not cast (1/64) */
    int rt_hierarchy;        /* ray tracer: bounding-volume hierarchy (1) */
    /* outlines (outlines.h, docs/outlines.md): lines over the polygons */
    int outlines;            /* mask of STP_OUTLINE_SILHOUETTE, _CREASE (0) */
    int outlines_auto;       /* 1: silhouettes when the objects would not be
                                told from their background (readable.h; 0;
                                1 for a still 1-bit picture without -d or
                                --outlines) */
    int outlines_given;      /* the option parser saw --outlines */
    double crease_angle;     /* degrees between normals that make a crease (40) */
    double outline_level;    /* the lines' shade 0..1 (0, black); < 0: black,
                                or white on a dark background */
    /* camera (camera.h): --eye/--at keys (several for an animation's
     * path), --up; a camera given replaces the scene's view */
    int eye_count, at_count, up_given;
    stp_scene_vec3 eye[STP_TOOL_CAMERA_KEYS], at[STP_TOOL_CAMERA_KEYS], up;
    int hold, hold_given;    /* animation: grey steps a pixel's grey must move
                                past its threshold to flip (animate.h) (0) */
    int keep_units;          /* 1: the scene's coordinates go to the core as
                                they are, not moved and scaled into its range
                                (--no-rescale; polygon renderer only): what a
                                firmware given them draws, or refuses (0) */
} stp_tool_options;

void stp_tool_options_default(stp_tool_options *opt);

/* Statistics of one render. */
typedef struct stp_tool_stats {
    unsigned long polygons_in;     /* polygons given to the core */
    unsigned long polygons_skipped;/* degenerate ones the core refused */
    unsigned long display_entries; /* display-file entries used */
    size_t frame_bytes;            /* renderer + display file + band + z + sort;
                                      ray tracer: its object + objects +
                                      points + hierarchy + band */
    /* ray tracer only */
    unsigned long rt_objects;      /* spheres, cones and polygons */
    unsigned long rt_nodes;        /* hierarchy nodes built (0: none) */
    double rt_build_seconds;       /* building the hierarchy */
    double rt_trace_seconds;       /* tracing and output */
    unsigned long rt_rays, rt_shadow_rays, rt_box_tests, rt_object_tests;
} stp_tool_stats;

/* The output description of a render with these options: the halftone
 * cell (into *cell), the gamma table (allocated into *gamma, NULL when
 * linear; the caller frees it), style table and the scene's background
 * (into background_rgb for colour).  Returns 0, or -1 with a message. */
int stp_tool_output(const stp_scene *scene, const stp_tool_options *opt, stp_output *out,
                    stp_cell *cell, uint8_t **gamma, stp_fix background_rgb[3], char *err,
                    size_t err_size);

/* A scene point as stp_vec3 (stp_tool_fix of each coordinate). */
stp_vec3 stp_tool_vec3(stp_scene_vec3 v);

/* A scene loaded into the core's ray tracer (raytrace_scene.c): the ray
 * tracer and the memory it was lent, the view, lighting and materials it
 * was given.  The hierarchy is built when opt->rt_hierarchy is set (the
 * memory for it is always there, so stp_rt_build can be called later). */
typedef struct stp_tool_rt {
    stp_raytracer *rt;
    void *storage;
    stp_rt_memory mem;
    stp_rt_material *materials;
    size_t material_count, points_used;
    stp_view view;
    stp_lighting lighting;
} stp_tool_rt;

/* Build it from the scene as stp_tool_prepare makes it (stats: rt_objects,
 * rt_nodes, rt_build_seconds, polygons_in, polygons_skipped).  Returns 0,
 * or -1 with a message (nothing to free). */
int stp_tool_rt_build(const stp_scene *scene, const stp_tool_options *opt, stp_tool_rt *t,
                      stp_tool_stats *stats, char *err, size_t err_size);
void stp_tool_rt_free(stp_tool_rt *t);

/* The ray tracer's material slot of a scene material index: the index
 * itself when it names one of the scene's materials, else the default
 * material that follows them (scene->material_count). */
uint32_t stp_tool_rt_material(const stp_scene *scene, int material);

/* Ray-trace scene onto port (raytrace_scene.c; opt->raytrace is implied).
 * Returns 0, or -1 with a message in err. */
int stp_tool_raytrace(const stp_scene *scene, const stp_tool_options *opt, stp_port *port,
                      stp_tool_stats *stats, char *err, size_t err_size);

/* Render scene onto port (its width/height/format must match opt).  The
 * scene is first prepared for the core (scene_prepare.h: rescaled when out
 * of range, lights beyond STP_MAX_LIGHTS merged, long polygons split).
 * Returns 0, or -1 with a message in err; a message about one line of the
 * scene's file starts with that line's number and a colon ("12: coordinate
 * (0, 0, 40000) of polygon 3 beyond the core's range ..."), for
 * stp_tool_scene_message to put the file's name before. */
int stp_tool_render(const stp_scene *scene, const stp_tool_options *opt, stp_port *port,
                    stp_tool_stats *stats, char *err, size_t err_size);

/* A message of stp_tool_render (err) about the scene file name as the
 * tools print it: "name:12: what" when err starts with a line number
 * ("12: what"), else "name: what".  Truncated to size bytes. */
void stp_tool_scene_message(char *out, size_t size, const char *name, const char *err);

/* The view and lighting stp_tool_render uses for a scene: the scene's view
 * (else one that frames its bounds at 45 degrees), the options' lights, else
 * the scene's, else one above and left of the eye, with powers and colours
 * as the README's "How NFF materials and lights map" says.  Returns 0, or -1
 * with a message (an empty scene). */
int stp_tool_setup(const stp_scene *scene, const stp_tool_options *opt, stp_view *view,
                   stp_lighting *lighting, char *err, size_t err_size);

/* A view in the scene's units (doubles): eye, look-at point, up, the
 * field of view in degrees and the hither distance. */
typedef struct stp_tool_view {
    stp_scene_vec3 from, at, up;
    double fov_degrees, hither;
} stp_tool_view;

/* The view stp_tool_setup starts from, in the scene's units: the scene's
 * own (its fov unless opt->fov > 0), else one that frames its bounds from
 * the +x+y+z octant with y up.  Returns 0, or -1 for a scene with nothing
 * in it. */
int stp_tool_view_of(const stp_scene *scene, const stp_tool_options *opt, stp_tool_view *v);

/* The seed's material parameters for an NFF material (README). */
void stp_tool_material(const stp_scene_material *m, int colour, stp_material *out);

/* Double to stp_fix, saturating. */
stp_fix stp_tool_fix(double v);

/* The rows of a band the options ask for on port: band_rows, or the whole
 * frame for 0 or more; on a page port (STP_PIXEL_MONO1_PAGES) rounded up
 * to whole pages of 8 rows, which it takes (port.h). */
int stp_tool_band_rows(const stp_tool_options *opt, const stp_port *port);

/* Bytes of a band of rows rows of width pixels in format: rows rows, or
 * (rows + 7) / 8 pages of width bytes (STP_PIXEL_MONO1_PAGES). */
size_t stp_tool_band_bytes(stp_pixel_format format, uint32_t width, int rows);

/* The error diffusion the options ask for, for rows of width pixels:
 * 1 with d filled and d->errors allocated (the caller frees it), 0 when the
 * options dither with a cell (d->errors NULL), -1 out of memory. */
int stp_tool_diffusion(const stp_tool_options *opt, uint32_t width, stp_diffusion *d);

/* The visible pieces of the scene's edges of the kinds asked for (a mask of
 * STP_OUTLINE_*, outlines.h) as the options draw the scene, in device
 * pixels (x right, y down, (0, 0) the picture's top left corner): *xy holds
 * x0 y0 x1 y1 per piece, malloc'ed (the caller frees it).  Returns 0, or -1
 * with a message. */
int stp_tool_outline_pixels(const stp_scene *scene, const stp_tool_options *opt, int kinds, double **xy,
                            size_t *count, char *err, size_t err_size);

/* The defaults for a still 1-bit picture (stipple render to a PBM file),
 * where options did not say otherwise: Floyd-Steinberg diffusion, rows
 * left to right, with its band weights and thresholds modulated by the
 * blue-noise mask for mid-greys (-d fs:blue: no worms on flat mid-greys,
 * diffuse.h, docs/dither.md), 256 levels,
 * automatic exposure, and silhouettes where the objects would not be told
 * from their background (readable.h; not with -d, --outlines or --raytrace)
 * (moving pictures keep an ordered cell, which does not flicker). */
void stp_tool_still_defaults(stp_tool_options *opt);

/* Build the halftone cell the options name (Bayer 4x4 for diffusion, whose
 * cell only other formats' fallbacks would use). */
int stp_tool_cell(const stp_tool_options *opt, stp_cell *cell);

#endif
