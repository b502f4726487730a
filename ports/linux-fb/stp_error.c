/* SPDX-License-Identifier: MIT */
/* Error messages into caller buffers (stp_error.h). */
#include <stdio.h>

#include "stp_error.h"

void stp_error_vset(char *err, size_t errlen, const char *prefix, const char *fmt, va_list ap)
{
    int n = 0;
    if (!err || errlen == 0)
        return;
    if (prefix) {
        n = snprintf(err, errlen, "%s", prefix);
        if (n < 0 || (size_t)n >= errlen)
            return;
    }
    vsnprintf(err + n, errlen - (size_t)n, fmt, ap);
}

void stp_error_set(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    stp_error_vset(err, errlen, NULL, fmt, ap);
    va_end(ap);
}
