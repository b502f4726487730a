/* SPDX-License-Identifier: MIT */
/*
 * stipple POSIX port: host-side output and input of pictures.
 *
 *  - A frame port (stp_posix_frame): an stp_port that gathers the bands a
 *    renderer flushes into one whole-frame buffer, so the picture can be
 *    inspected or written when the frame is done.
 *  - Writers: PBM (P4 raw, P1 plain), PGM (P5), PPM (P6) and an ASCII dump
 *    of STYLE8 frames (one text line per row).  Files are replaced
 *    atomically: a temporary file beside the target is written, fsync'ed and
 *    renamed over it, so a failed write never leaves a half-written target.
 *  - Readers: PBM/PGM/PPM (P1..P6, maxval 1..65535) into 8-bit samples, for
 *    golden-image comparisons and for grey input images.
 *
 * Host code: uses libc, the heap and POSIX.  Every function that can fail
 * returns 0 on success and -1 on failure; those taking err/errlen then write
 * a one-line message "<path>: <what is wrong>" there (truncated to errlen,
 * always NUL-terminated; err may be NULL or errlen 0 to ignore it).
 * Not thread-safe where noted (the umask lookup of the writers).
 */
#ifndef STP_POSIX_H
#define STP_POSIX_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "stipple/port.h"
#include "stipple/shade.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- frames */

/* A whole frame gathered from a renderer's bands.  Fields are for reading;
 * change them only through the functions below.  The embedded port points
 * back at the frame (port.user), so a frame must not be copied or moved
 * after stp_posix_frame_init. */
typedef struct stp_posix_frame {
    stp_port port;          /* hand &port (stp_posix_frame_port) to the core */
    uint8_t *pixels;        /* height rows, stride bytes apart, top row first */
    size_t stride;          /* bytes per row: exactly the packed row size */
    uint32_t width, height; /* pixels, 1..32767 each */
    stp_pixel_format format;
    uint32_t bands;         /* flush calls accepted since init/clear */
    uint32_t rows_filled;   /* one past the bottom-most row received so far */
} stp_posix_frame;

/* Allocates a zeroed frame of width x height pixels (each 1..32767) in
 * format fmt and sets up its port.  Zero means OFF (MONO1), black (GREY8,
 * RGB888) or "nothing drawn" (STYLE8).  Returns 0, or -1 with errno EINVAL
 * (bad size or format; f untouched) or ENOMEM (f zeroed). */
int stp_posix_frame_init(stp_posix_frame *f, uint32_t width, uint32_t height,
                         stp_pixel_format fmt);

/* The frame's port, to pass to the renderer.  Its flush copies rows
 * [y0, y0 + rows) into the frame (row r read at pixels + r * stride, the
 * stride being at least the packed row size unless rows == 1) and returns 0;
 * it returns -1, copying nothing, when the band falls outside the frame,
 * pixels is NULL or the stride is too small.  MONO1 padding bits past the
 * last pixel of a row are cleared, so written files do not depend on them.
 * Bands may come in any order and may repeat (the last one wins). */
stp_port *stp_posix_frame_port(stp_posix_frame *f);

/* Zeroes the pixels and the band counters, for rendering the frame again. */
void stp_posix_frame_clear(stp_posix_frame *f);

/* Frees the pixels and zeroes f.  f may be zeroed or already freed. */
void stp_posix_frame_free(stp_posix_frame *f);

/* ---------------------------------------------------------------- writing */

typedef enum stp_posix_file_kind {
    STP_POSIX_FILE_UNKNOWN = -1,
    STP_POSIX_FILE_P4 = 0, /* PBM raw:   from MONO1 */
    STP_POSIX_FILE_P1,     /* PBM plain: from MONO1 (lines <= 70 chars) */
    STP_POSIX_FILE_P5,     /* PGM raw, maxval 255: from GREY8; MONO1 as 0/255 */
    STP_POSIX_FILE_P6,     /* PPM raw, maxval 255: from RGB888; GREY8 and
                              MONO1 (0/255) with R = G = B */
    STP_POSIX_FILE_ASCII   /* text: from STYLE8, each pixel's byte written as
                              is (a character code from a style table such as
                              stp_posix_lineprinter_styles), '\n' per row */
} stp_posix_file_kind;

/* PBM stores 1 = black while MONO1 has 1 = ON = light: the PBM writers
 * invert, so an ON pixel is written as 0 (white). */

/* The kind an output path asks for, from its extension (case-insensitive):
 * .pbm -> P4, .pgm -> P5, .ppm -> P6, .txt -> ASCII.  Anything else,
 * including "-" (stdout) and NULL, gives STP_POSIX_FILE_UNKNOWN: the caller
 * then picks one, e.g. with stp_posix_kind_for_format. */
stp_posix_file_kind stp_posix_kind_from_path(const char *path);

/* The natural kind for a pixel format: MONO1 -> P4, GREY8 -> P5,
 * RGB888 -> P6, STYLE8 -> ASCII; unknown formats -> STP_POSIX_FILE_UNKNOWN. */
stp_posix_file_kind stp_posix_kind_for_format(stp_pixel_format fmt);

/* 1 if a frame of format fmt can be written as kind (see the table in
 * stp_posix_file_kind), else 0. */
int stp_posix_kind_accepts(stp_posix_file_kind kind, stp_pixel_format fmt);

/* Writes frame f to path as kind.  path "-" writes to stdout (flushed, not
 * closed, not atomic); any other path is replaced atomically (see
 * stp_posix_write_file).  Errors: -1 with a message when f is not an
 * initialised frame, kind cannot hold f's format, or on any I/O failure;
 * an existing target is then left untouched. */
int stp_posix_write(const stp_posix_frame *f, const char *path,
                    stp_posix_file_kind kind, char *err, size_t errlen);

/* Encodes f as kind onto an open stream (no flush, no close).  Returns 0,
 * or -1 with errno set: EINVAL for a bad frame or kind/format pair, else the
 * stream's write error. */
int stp_posix_encode(const stp_posix_frame *f, stp_posix_file_kind kind, FILE *out);

/* Writes a file's bytes through emit, which returns 0, or -1 with errno set
 * (errno 0 is reported as EIO).  For path "-" emit writes to stdout, which is
 * then flushed.  Otherwise the bytes go to a temporary file created with
 * mkstemp in the target's directory, named ".<target name>.XXXXXX"; it gets
 * the existing target's permission bits, or 0666 less the umask for a new
 * file (the umask is read by setting it, which is not thread-safe); it is
 * flushed, fsync'ed and renamed over the target, and the directory is
 * fsync'ed (failure of that last step is ignored: some file systems refuse
 * it).  A symbolic link is followed and the file it ends at is replaced
 * (the link stays a link); a link through /proc (such as /dev/stdout
 * redirected to a file: appended to, as the shell's descriptor would) and
 * a character device or FIFO are written in
 * place; a directory or any other kind of file is refused.  While the
 * temporary file exists, SIGINT, SIGTERM and SIGHUP (unless ignored)
 * remove it and then take their default action; the handlers are the
 * caller's again once the call returns.  On any error the temporary file
 * is removed, the target is untouched and the message names the path, the
 * failed step and strerror. */
typedef int (*stp_posix_emit_fn)(FILE *out, void *ctx);
int stp_posix_write_file(const char *path, stp_posix_emit_fn emit, void *ctx,
                         char *err, size_t errlen);

/* ------------------------------------------------------------ line printer */

/* Sixteen printable characters from dense ink to blank paper, for STYLE8
 * frames printed as text: "@M&B%$#kao=+-:. ".  The order is by ink
 * coverage, measured as lit pixels of each glyph in netpbm's built-in
 * pbmtext font (42 for '@' down to 0 for ' '), so index 1 (darkest style)
 * is '@' and index 16 (lightest) is ' '. */
extern const uint8_t stp_posix_lineprinter_styles[16];

/* Fills table with levels = 16 and codes = stp_posix_lineprinter_styles
 * (static storage: the table stays valid for the whole program). */
void stp_posix_lineprinter_table(stp_style_table *table);

/* ---------------------------------------------------------------- reading */

/* A picture read from a PNM file: 8-bit samples, 0 = black, 255 = white
 * (or full intensity of a colour channel). */
typedef struct stp_posix_image {
    uint32_t width, height; /* pixels, 1..32767 each */
    int channels;           /* 1 (grey) or 3 (R, G, B) */
    uint8_t *samples;       /* height * width * channels bytes, rows top
                               first, no padding */
    int pnm_type;           /* the file's magic number: 1..6 for P1..P6 */
    uint32_t maxval;        /* the file's maxval (1 for PBM) */
} stp_posix_image;

/* Reads a PBM (P1, P4), PGM (P2, P5) or PPM (P3, P6) file; path "-" reads
 * stdin.  Headers may hold '#' comments (to end of line) anywhere between
 * fields; plain rasters may too.  maxval 1..65535 (raw samples above 255
 * are two bytes, most significant first); samples are scaled to 0..255 as
 * round(v * 255 / maxval).  PBM gives 0 for black (bit 1) and 255 for
 * white.  PBM and PGM give channels 1, PPM channels 3.  Only the first
 * image of a multi-image file is read.
 * Errors (-1, img zeroed, message "<path>: ..."): cannot open or read;
 * not a PNM file; bad header (missing or non-numeric field, width or height
 * 0 or over 32767, maxval 0 or over 65535); a sample over maxval or a
 * stray character in a plain raster; truncated raster; out of memory. */
int stp_posix_read_pnm(const char *path, stp_posix_image *img, char *err, size_t errlen);

/* Like stp_posix_read_pnm, but always gives channels 1: a PPM is turned
 * into grey with luminance weights 0.299 R + 0.587 G + 0.114 B (ITU-R
 * BT.601), computed exactly on the file's samples and then scaled to 0..255
 * with rounding. */
int stp_posix_read_grey(const char *path, stp_posix_image *img, char *err, size_t errlen);

/* Frees img's samples and zeroes it.  img may be zeroed or already freed. */
void stp_posix_image_free(stp_posix_image *img);

#ifdef __cplusplus
}
#endif

#endif
