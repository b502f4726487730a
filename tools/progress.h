/* SPDX-License-Identifier: MIT */
/*
 * A progress bar on stderr for long renders: a port that passes every band
 * on to another port and, once a frame has taken more than a second, draws
 * "label [#####     ]  42%  3 s left" over itself; the time left is the
 * time so far times the rows to go over the rows done.  Quiet when stderr is not a
 * terminal (logs and CI stay clean).  Host code.
 */
#ifndef STIPPLE_TOOLS_PROGRESS_H
#define STIPPLE_TOOLS_PROGRESS_H

#include "stipple/port.h"

typedef struct stp_progress {
    stp_port port;        /* give this one to the renderer */
    stp_port *inner;      /* where the bands go */
    const char *label;
    double start;         /* seconds, CLOCK_MONOTONIC */
    double delay;         /* seconds before the bar appears (1; 0 always) */
    int enabled;          /* stderr is a terminal */
    int shown;            /* the bar has been drawn */
} stp_progress;

/* 1 when a bar would be drawn: stderr is a terminal, or the environment
 * variable STIPPLE_PROGRESS is "always" (then drawn from the first band,
 * wherever stderr goes: for tests and logs). */
int stp_progress_wanted(void);

/* Wrap inner (same size and format).  Returns the port to render into. */
stp_port *stp_progress_wrap(stp_progress *pg, stp_port *inner, const char *label);

/* End the bar's line if one was drawn (call after the render). */
void stp_progress_finish(stp_progress *pg);

#endif
