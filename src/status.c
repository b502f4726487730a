/* SPDX-License-Identifier: MIT */
/* Status texts: see stp_status_text in include/stipple/render.h. */
#include "stipple/render.h"

const char *stp_status_text(int status)
{
    switch (status) {
    case STP_OK: return "ok";
    case STP_ERR_ARG: return "invalid argument";
    case STP_ERR_FULL: return "display file or segment table full";
    case STP_ERR_NO_SEGMENT: return "no open segment";
    case STP_ERR_SEGMENT: return "no such segment, or a segment is already open";
    case STP_ERR_TOO_MANY_VERTICES: return "polygon has more vertices than STP_MAX_POLYGON_VERTICES";
    case STP_ERR_DEGENERATE: return "degenerate polygon (no area)";
    case STP_ERR_MEMORY: return "buffer too small";
    case STP_ERR_PORT: return "the port reported an error";
    case STP_ERR_VIEW: return "invalid view";
    case STP_ERR_UNSUPPORTED: return "feature not compiled into this build";
    case STP_ERR_RANGE: return "coordinate beyond the range of view coordinates";
    default: return "unknown status";
    }
}
