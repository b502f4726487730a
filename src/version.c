/* SPDX-License-Identifier: MIT */
/* The library's version string, built from the macros of version.h. */
#include "stipple/version.h"

#define STP_STRINGIFY_(x) #x
#define STP_STRINGIFY(x) STP_STRINGIFY_(x)

const char *stp_version(void)
{
    return STP_STRINGIFY(STP_VERSION_MAJOR) "." STP_STRINGIFY(STP_VERSION_MINOR) "." STP_STRINGIFY(
        STP_VERSION_PATCH);
}
