/* SPDX-License-Identifier: MIT */
/*
 * stipple POSIX port: animated GIF output of 1-bit frames through giflib
 * (Debian's libgif-dev).  A library of its own (stipple_posix_gif), built
 * when giflib is found, so that other users of the port do not need it.
 *
 * Conventions as in stp_posix.h: 0 on success, -1 on failure with a
 * one-line message "<path>: <what is wrong>" in err.
 */
#ifndef STP_POSIX_GIF_H
#define STP_POSIX_GIF_H

#include <stddef.h>
#include <stdint.h>

#include "stp_posix.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The frames of an animation, gathered before the file is written (a
 * 128x64 frame takes 1 KiB). */
typedef struct stp_posix_gif {
    uint32_t width, height; /* of every frame */
    size_t stride;          /* bytes per packed MONO1 row */
    size_t count, capacity; /* frames held, room for */
    uint8_t *bits;          /* count frames of height * stride bytes */
    unsigned delay_cs;      /* each frame's time on screen, 1/100 s (5) */
    uint32_t off_rgb, on_rgb; /* 0xRRGGBB of an unlit (0x000000) and a lit
                                 (0xFFFFFF) pixel */
} stp_posix_gif;

/* An empty animation of width x height frames (1..32767 each).  Returns 0,
 * or -1 (bad size). */
int stp_posix_gif_init(stp_posix_gif *g, uint32_t width, uint32_t height);

/* Append a copy of frame f (MONO1, g's size).  Returns 0, or -1 with a
 * message (another format or size, out of memory). */
int stp_posix_gif_add(stp_posix_gif *g, const stp_posix_frame *f, char *err, size_t errlen);

/* Write the frames as a GIF89a file that loops for ever: a two-colour
 * table (index 0 unlit, 1 lit), the first frame whole, each later one as
 * the rectangle that holds its changes over the frame before (drawn over
 * it: disposal "do not dispose"), so a viewer shows exactly the frames
 * added.  path "-" writes to stdout; any other path is replaced
 * atomically (stp_posix_write_file).  Returns 0, or -1 with a message (no
 * frames, giflib's error, I/O). */
int stp_posix_gif_write(const stp_posix_gif *g, const char *path, char *err, size_t errlen);

void stp_posix_gif_free(stp_posix_gif *g);

/* 1 if path ends in ".gif" (case-insensitive), else 0 (also for NULL). */
int stp_posix_gif_path(const char *path);

#ifdef __cplusplus
}
#endif

#endif
