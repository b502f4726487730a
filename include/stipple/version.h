/* SPDX-License-Identifier: MIT */
/*
 * stipple's version.  The top-level CMakeLists.txt reads its project version
 * from the three macros below, so this header is the one place it is written
 * (builds without CMake, such as the Arduino IDE's, see the same numbers).
 */
#ifndef STIPPLE_VERSION_H
#define STIPPLE_VERSION_H

#define STP_VERSION_MAJOR 0
#define STP_VERSION_MINOR 3
#define STP_VERSION_PATCH 0

/* The version as one integer, major * 10000 + minor * 100 + patch, for
 * compile-time comparisons (#if STP_VERSION_NUMBER >= 200). */
#define STP_VERSION_NUMBER (STP_VERSION_MAJOR * 10000L + STP_VERSION_MINOR * 100L + STP_VERSION_PATCH)

#ifdef __cplusplus
extern "C" {
#endif

/* The version of the library linked in, as "MAJOR.MINOR.PATCH" (a static
 * string; never NULL).  Compare it with the macros to catch an application
 * compiled against other headers than the library it links. */
const char *stp_version(void);

#ifdef __cplusplus
}
#endif

#endif
