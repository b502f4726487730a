/* SPDX-License-Identifier: MIT */
/*
 * Internals shared by the scene readers: a line/token scanner over a memory
 * buffer, strict number parsing, error formatting and the growable scene
 * arrays with a total memory budget.  Not part of the public API.
 */
#ifndef STIPPLE_TOOLS_SCENE_PRIVATE_H
#define STIPPLE_TOOLS_SCENE_PRIVATE_H

#include <stddef.h>

#include "scene.h"

/* Upper bound on the vertices of one polygon, checked before anything is
 * read so that "p 1000000000" fails at once instead of after a long scan. */
#define STP_SCENE_MAX_POLYGON_VERTICES 1048576

/* Tessellation options outside 3..1024 (2..1024 for stacks) are refused. */
#define STP_SCENE_MAX_TESSELLATION 1024

#define STP_SCENE_MAX_RESOLUTION 65536

#define STP_SCENE_DEFAULT_BYTE_LIMIT ((size_t)512 << 20)

/* Heap bytes one load may hold (scene arrays, reader scratch arrays and the
 * file text itself for stp_scene_load).  A variable rather than a constant
 * only so that tests can exercise the limit without allocating 512 MiB. */
extern size_t stp_scene_byte_limit;

#if defined(__GNUC__)
#define STP_SCENE_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define STP_SCENE_PRINTF(f, a)
#endif

typedef struct stp_token {
    const char *s;
    size_t n;
} stp_token;

/* The unread rest of one line. */
typedef struct stp_line {
    const char *p, *end;
    long number; /* 1-based */
} stp_line;

typedef struct stp_parser {
    const char *text;
    size_t size, pos;
    long line; /* number of the line that starts at pos */
    const char *name;
    char *err;
    size_t err_size;
    stp_scene *scene;
    const stp_scene_options *opt;
    size_t bytes; /* heap bytes currently held against stp_scene_byte_limit */
    size_t vertex_cap, polygon_cap, prim_cap, light_cap, material_cap;
} stp_parser;

/* Writes "name:line: message" (or "name: message" when line is 0) into the
 * error buffer and returns -1. */
int stp_fail(stp_parser *ps, long line, const char *fmt, ...) STP_SCENE_PRINTF(3, 4);

/* Next line holding a token (blank and '#' comment lines are skipped).
 * Returns 1, 0 at the end of the text, -1 on error (NUL byte). */
int stp_next_line(stp_parser *ps, stp_line *ln);

/* Next whitespace-separated token of the line; a token starting with '#'
 * ends the line.  Returns 1, or 0 at the end of the line. */
int stp_next_token(stp_line *ln, stp_token *tok);

int stp_token_is(const stp_token *tok, const char *word);

/* Tokens left on the line (capped at INT_MAX), without consuming them. */
int stp_count_tokens(const stp_line *ln);

/* The token made printable and shortened for a message. */
const char *stp_token_show(const stp_token *tok, char *buf, size_t size);

/* Whole-token decimal number, finite.  Returns 0 or -1 (error set). */
int stp_parse_double(stp_parser *ps, long line, const stp_token *tok, double *out);

/* Whole-token decimal integer with |value| <= 1e15.  Returns 0 or -1. */
int stp_parse_integer(stp_parser *ps, long line, const stp_token *tok, long long *out);

/* Reads the rest of the line as between min and max numbers (max <= 16).
 * Returns how many were read, or -1. what names the entity for messages. */
int stp_read_numbers(stp_parser *ps, stp_line *ln, double *out, int min, int max,
                     const char *what);

/* Fails unless the rest of the line is empty. */
int stp_expect_end(stp_parser *ps, stp_line *ln, const char *what);

/* Makes room for need elements in *arr (capacity *cap, elements of elem
 * bytes), charging the budget.  Returns 0 or -1. */
int stp_grow(stp_parser *ps, long line, void **arr, size_t *cap, size_t need, size_t elem);

/* Frees an array obtained with stp_grow and returns its bytes to the budget. */
void stp_release(stp_parser *ps, void *arr, size_t cap, size_t elem);

/* Appends to the scene.  Each returns 0 or -1 (error set).  A NULL normal
 * stores zero. */
int stp_add_vertex(stp_parser *ps, long line, const stp_scene_vec3 *v, const stp_scene_vec3 *n);
int stp_add_polygon(stp_parser *ps, long line, size_t first, int count, int material,
                    int has_normals);
int stp_add_prim(stp_parser *ps, long line, const stp_scene_prim *prim);
int stp_add_light(stp_parser *ps, long line, const stp_scene_light *light);
/* Returns the new material's index, or -1. */
int stp_add_material(stp_parser *ps, long line, const stp_scene_material *m);
int stp_add_default_material(stp_parser *ps, long line);

int stp_parse_nff(stp_parser *ps);
int stp_parse_obj(stp_parser *ps);
int stp_parse_off(stp_parser *ps);
int stp_parse_ply(stp_parser *ps);

#endif
