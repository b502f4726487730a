/* SPDX-License-Identifier: MIT */
/* Compiled with a core configuration for the target: its one object is as
 * large as the renderer object, and the build reads that size back
 * (renderer_bytes.cmake) as the exact STP_RENDERER_BYTES of the images. */
#include "render_private.h"

extern const unsigned char stp_renderer_probe[sizeof(stp_renderer)];
const unsigned char stp_renderer_probe[sizeof(stp_renderer)] = {0};
