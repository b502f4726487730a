/* SPDX-License-Identifier: MIT */
/*
 * What the board-independent firmware main (main.c) asks of a board: its
 * panel's size, the pixel format its bands go in, how to start the panel,
 * how a band reaches it, and how the picture is held for a test harness
 * before the program ends.
 */
#ifndef STIPPLE_PORTS_BOARD_H
#define STIPPLE_PORTS_BOARD_H

#include <stdint.h>

#include "stipple/port.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct stp_board {
    const char *name;
    uint32_t width, height;        /* the panel, in pixels */
    /* the bands flush takes: STP_PIXEL_MONO1 rows, or STP_PIXEL_MONO1_PAGES
     * (the panel's own 8-row pages, sent as they are: bands of whole pages
     * starting on a page, or the whole height; the build's STP_FW_PAGES) */
    stp_pixel_format format;
    const char *size_hint;         /* how to compile a scene for it: "-s WxH" */
    int (*panel_start)(void);      /* bus and controller set up: 0, or -1 */
    stp_flush_fn flush;            /* bands top to bottom, after panel_start */
    void (*hold)(void);            /* keep the picture until the harness lets go */
} stp_board;

/* The board the image is linked for (board_<name>.c). */
extern const stp_board stp_board_this;

#ifdef __cplusplus
}
#endif

#endif
