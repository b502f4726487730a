/* SPDX-License-Identifier: MIT */
/*
 * libgpiod v2 loaded on first use (stp_gpiod_load.c), so a program built
 * with the GPIO control lines runs where libgpiod 2 is not installed until a
 * line is asked for.  Host code (libc, POSIX dlopen).
 */
#ifndef STP_GPIOD_LOAD_H
#define STP_GPIOD_LOAD_H

#include <stddef.h>

/* Loads libgpiod.so.3 once (thread-safe).  Returns 0 when it is loaded;
 * -1 with a one-line message in err (errlen bytes, err may be NULL) naming
 * the library and the package to install. */
int stp_gpiod_load(char *err, size_t errlen);

#endif
