/* SPDX-License-Identifier: MIT */
/* Progress bar port: see progress.h. */
#define _POSIX_C_SOURCE 200809L
#include "progress.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define BAR_WIDTH 40

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static int progress_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                          size_t stride)
{
    stp_progress *pg = (stp_progress *)port->user;
    int status = pg->inner->flush(pg->inner, y0, rows, pixels, stride);
    double elapsed = now() - pg->start;
    if (pg->enabled && (pg->shown || elapsed > pg->delay)) {
        unsigned done = y0 + rows, total = port->height;
        int filled = (int)((unsigned long)done * BAR_WIDTH / total), k;
        fprintf(stderr, "\r%s [", pg->label);
        for (k = 0; k < BAR_WIDTH; k++)
            fputc(k < filled ? '#' : ' ', stderr);
        fprintf(stderr, "] %3u%%", (unsigned)((unsigned long)done * 100 / total));
        if (done < total)
            fprintf(stderr, " %4.0f s left", elapsed * (total - done) / done);
        else
            fprintf(stderr, " %4.1f s     ", elapsed);
        fflush(stderr);
        pg->shown = 1;
    }
    return status;
}

static int always(void)
{
    const char *v = getenv("STIPPLE_PROGRESS");
    return v && !strcmp(v, "always");
}

int stp_progress_wanted(void)
{
    return isatty(STDERR_FILENO) || always();
}

stp_port *stp_progress_wrap(stp_progress *pg, stp_port *inner, const char *label)
{
    pg->inner = inner;
    pg->label = label;
    pg->start = now();
    pg->enabled = stp_progress_wanted();
    pg->delay = always() ? 0.0 : 1.0;
    pg->shown = 0;
    pg->port = *inner;
    pg->port.flush = progress_flush;
    pg->port.user = pg;
    return &pg->port;
}

void stp_progress_finish(stp_progress *pg)
{
    if (pg->shown)
        fputc('\n', stderr);
    pg->shown = 0;
}
