/* SPDX-License-Identifier: MIT */
/* Direct drawing's faces that the picture's edge cuts
 * (direct_clip_private.h): the renderer's clipper (clip.c) and projection
 * (project_private.h) on the frame's view coordinates, so a clipped face
 * gets the vertices, device positions and depth keys the renderer stores
 * for it.  Compiled in the compact form too, which calls none of it (its
 * frames mark no face clipped). */
#include "direct_clip_private.h"

#include "view_private.h" /* stp_view_lens, stp_view_perspective_device */

void stp_direct_clip_volume(const stp_direct_frame *f, stp_clip_volume *v)
{
    v->focal = f->focal;
    v->near = f->hither;
    v->width = f->width;
    v->height = f->height;
    v->parallel = 0;
}

int stp_direct_face_clip(const stp_direct_frame *f, const uint16_t k[3], stp_instr out[STP_DIRECT_CLIP_MAX])
{
    int32_t d[3];
    stp_vec3 a[STP_DIRECT_CLIP_MAX], b[STP_DIRECT_CLIP_MAX], *clipped, *spare;
    stp_fix *values;
    stp_clip_volume volume;
    stp_view_lens lens;
    int i, n;
    for (i = 0; i < 3; i++) {
        a[i].x = f->points[k[i]].x;
        a[i].y = f->points[k[i]].y;
        a[i].z = f->points[k[i]].z;
    }
    stp_direct_clip_volume(f, &volume);
    n = stp_clip_polygon(&volume, a, b, 0, 0, 3, &clipped, &spare, &values);
    /* render.c's project (width, height <= 512) */
    stp_view_lens_make(&lens, f->focal, f->hither, f->width, f->height);
    for (i = 0; i < n; i++) {
        stp_view_perspective_device(&lens, &clipped[i], d);
        out[i].op = 0;
        out[i].x = d[0];
        out[i].y = d[1];
        out[i].z = d[2];
#if STP_WITH_GOURAUD
        out[i].shade = -1; /* flat */
#endif
    }
    return n;
}
