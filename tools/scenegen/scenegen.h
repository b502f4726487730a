/* SPDX-License-Identifier: MIT */
/*
 * Procedural scenes written as NFF (`stipple scene NAME`): the Utah teapot,
 * the Sierpinski tetrahedron, the sphereflake, a torus, interlocked rings and
 * a fractal mountain.  Host code (libc, double precision).  The size factor
 * plays the role of the Standard Procedural Databases' one: 1 is the
 * smallest scene, each step refines it (see each scene's `what`).
 */
#ifndef STIPPLE_TOOLS_SCENEGEN_H
#define STIPPLE_TOOLS_SCENEGEN_H

#include <stddef.h>
#include <stdio.h>

typedef struct stp_scenegen {
    const char *name;  /* the command's NAME */
    const char *what;  /* one line: what it is and what --size does */
    int max_size;      /* sizes 1..max_size are accepted */
    /* Writes the scene at size (1..max_size) to out.  Returns 0, or -1
     * when the stream reports a write error (errno as the stream left it). */
    int (*write)(FILE *out, int size);
} stp_scenegen;

/* The scenes, in the order `stipple scene --list` prints them; *count gets
 * their number. */
const stp_scenegen *stp_scenegen_all(size_t *count);

/* The scene called name, or NULL. */
const stp_scenegen *stp_scenegen_find(const char *name);

/* `stipple scene NAME [--size N] [-o OUT.nff]`: argv[0] is "scene".
 * Returns the exit status (0, 1 on error, 2 on a usage error); the output
 * file is replaced atomically, so a failed run leaves none behind. */
int stp_scenegen_main(int argc, char **argv);

#endif
