/* SPDX-License-Identifier: MIT */
/* The ports' one way of writing an error message into a caller's buffer. */
#ifndef STIPPLE_PORTS_ERROR_H
#define STIPPLE_PORTS_ERROR_H

#include <stdarg.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__)
#define STP_ERROR_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define STP_ERROR_PRINTF(f, a)
#endif

/* Write prefix (when not NULL) and then fmt's message into err, errlen
 * bytes, cut short and always terminated.  Does nothing when err is NULL or
 * errlen 0. */
void stp_error_vset(char *err, size_t errlen, const char *prefix, const char *fmt, va_list ap)
    STP_ERROR_PRINTF(4, 0);

/* stp_error_vset without a prefix. */
void stp_error_set(char *err, size_t errlen, const char *fmt, ...) STP_ERROR_PRINTF(3, 4);

#ifdef __cplusplus
}
#endif

#endif
