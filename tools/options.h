/* SPDX-License-Identifier: MIT */
/*
 * Command-line options shared by the commands that render a scene (stipple
 * render, stipple compile): one parser and one help text, so the two cannot
 * drift apart.
 */
#ifndef STIPPLE_TOOLS_OPTIONS_H
#define STIPPLE_TOOLS_OPTIONS_H

#include <getopt.h>
#include <stddef.h>
#include <stdio.h>

#include "render_scene.h"
#include "scene.h"

/* Codes of the long-only shared options; a command's own options use codes
 * from STP_TOOL_OPT_COMMAND on. */
enum {
    STP_TOOL_OPT_SPACING = 256,
    STP_TOOL_OPT_GAMMA_K,
    STP_TOOL_OPT_HIDDEN,
    STP_TOOL_OPT_BACKFACE,
    STP_TOOL_OPT_NO_SHADING,
    STP_TOOL_OPT_SMOOTH,
    STP_TOOL_OPT_COLOUR,
    STP_TOOL_OPT_TRANSPARENT,
    STP_TOOL_OPT_LIGHT,
    STP_TOOL_OPT_BRIGHT,
    STP_TOOL_OPT_AMBIENT,
    STP_TOOL_OPT_ATTEN,
    STP_TOOL_OPT_RAW_POWER,
    STP_TOOL_OPT_PARALLEL,
    STP_TOOL_OPT_FOV,
    STP_TOOL_OPT_SLICES,
    STP_TOOL_OPT_STACKS,
    STP_TOOL_OPT_SHADOWS,
    STP_TOOL_OPT_RAYTRACE,
    STP_TOOL_OPT_DEPTH,
    STP_TOOL_OPT_MIN_WEIGHT,
    STP_TOOL_OPT_NO_HIERARCHY,
    STP_TOOL_OPT_EXPOSURE,
    STP_TOOL_OPT_GREY,
    STP_TOOL_OPT_BACKGROUND,
    STP_TOOL_OPT_EDGE_AA,
    STP_TOOL_OPT_EYE, /* the camera options: in the tables of render and */
    STP_TOOL_OPT_AT,  /* animate only (stp_tool_camera_options) */
    STP_TOOL_OPT_UP,
    STP_TOOL_OPT_COMMAND = 512
};

/* Short options of the shared set, for getopt_long's optstring. */
#define STP_TOOL_SHORT_OPTIONS "s:l:d:g:"

/* Fill out[] with the shared long options followed by extra (both ending in
 * a zero entry); returns 0, or -1 when cap is too small. */
int stp_tool_long_options(struct option *out, size_t cap, const struct option *extra);

/* Apply option `code` with argument arg.  Returns 1 when it is a shared
 * option and was applied, 0 when it is not a shared option, -1 when its
 * argument is bad (message in err). */
int stp_tool_apply_option(int code, const char *arg, stp_tool_options *opt,
                          stp_scene_options *sopt, char *err, size_t err_size);

/* Which options a command line gave, indexed by option code (short
 * options by their character, long-only ones by STP_TOOL_OPT_*). */
typedef struct stp_tool_given {
    unsigned char code[STP_TOOL_OPT_COMMAND];
} stp_tool_given;

/* The long name of a shared option code, without "--" ("?" if unknown). */
const char *stp_tool_option_name(int code);

/* Refuses options the chosen renderer does not read: the polygon
 * renderer's (--hidden, --backface, --no-shading, --smooth, --transparent,
 * --shadows, --slices, --stacks) with raytrace set, the ray tracer's
 * (--depth, --min-weight, --no-hierarchy) without.  Returns 0, or -1 with a
 * message naming every such option given. */
int stp_tool_check_renderer(const stp_tool_given *given, int raytrace, char *err,
                            size_t err_size);

/* A usage error of `stipple COMMAND` (COMMAND NULL: of `stipple` itself):
 * prints "stipple COMMAND: <message>" and "Try 'stipple COMMAND --help'" on
 * stderr; returns the exit status 2. */
int stp_tool_usage_error(const char *command, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* The usage error for getopt_long's return c ('?' unknown option, ':' a
 * missing value; the optstring must start with ':' and opterr be 0). */
int stp_tool_getopt_error(const char *command, int c, char *const argv[]);

/* The camera options --eye, --at, --up as getopt_long entries (zero
 * entry last), for the commands that take them (render, animate). */
extern const struct option stp_tool_camera_options[4];

/* Apply camera option `code` (STP_TOOL_OPT_EYE, _AT, _UP) with argument
 * arg: --eye and --at add a key (at most max_keys each: 1 for a still, up
 * to STP_TOOL_CAMERA_KEYS for an animation's path), --up sets up.  Returns
 * 1 when applied, 0 when code is not a camera option, -1 with a message. */
int stp_tool_apply_camera_option(int code, const char *arg, int max_keys, stp_tool_options *opt,
                                 char *err, size_t err_size);

/* The camera options' help lines. */
void stp_tool_camera_help(FILE *to, int animation);

/* The shared options' help lines. */
void stp_tool_options_help(FILE *to);

/* Parsers used by the shared options and by `stipple dither`; each returns 0,
 * or -1 for a bad value (output untouched). */
int stp_tool_parse_int(const char *s, int lo, int hi, int *out);
int stp_tool_parse_double(const char *s, double *out);
int stp_tool_parse_dither(const char *s, stp_tool_options *opt);
int stp_tool_parse_spacing(const char *s, stp_spacing *out);

/* --scene-format: the reader's name ("nff", "obj", "off", "ply", static
 * storage) for s, or NULL when s names none. */
const char *stp_tool_parse_scene_format(const char *s);

#endif
