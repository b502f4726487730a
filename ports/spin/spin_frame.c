/* SPDX-License-Identifier: MIT */
/* Frames of the spinning scene (spin_frame.h). */
#include "spin_frame.h"

/* every part with spins == spinning, each with its material */
static int enter_parts(stp_renderer *r, int spinning)
{
    uint16_t i;
    int status = STP_OK;
    for (i = 0; i < spin_part_count && status == STP_OK; i++) {
        if (spin_parts[i].spins != spinning)
            continue;
        status = stp_renderer_set_object_shade(r, &spin_parts[i].material);
        if (status == STP_OK)
            status = stp_renderer_mesh(r, &spin_parts[i].mesh, spin_scratch, spin_scratch_count);
    }
    return status;
}

int spin_setup(stp_renderer *r)
{
    stp_view view;
    stp_lighting lighting;
    int status;
    spin_scene_view(&view);
    spin_scene_lighting(&lighting);
    status = stp_renderer_set_view(r, &view);
    if (status == STP_OK)
        status = stp_renderer_set_levels(r, spin_levels);
    if (status == STP_OK)
        status = stp_renderer_set_lighting(r, &lighting);
    if (status == STP_OK)
        status = stp_renderer_set_shading(r, 1);
    if (status == STP_OK)
        status = stp_renderer_set_backface_removal(r, spin_backface_removal);
    if (status == STP_OK)
        status = stp_segment_create(r, 1);
    if (status == STP_OK)
        status = enter_parts(r, 0);
    if (status == STP_OK)
        status = stp_segment_close(r);
    return status;
}

int spin_enter(stp_renderer *r, uint32_t frame)
{
    stp_transform t;
    stp_vec3 back = spin_axis_point, to;
    int status;
    /* the axis point's vertical coordinate is 0: only the horizontal move */
    to.x = -back.x;
    to.y = -back.y;
    to.z = -back.z;
    stp_transform_identity(&t);
    stp_transform_translate(&t, to);
    stp_transform_rotate(&t, spin_axis,
                         stp_fix_from_int((int32_t)((frame % (360u / SPIN_DEGREES_PER_FRAME)) *
                                                    SPIN_DEGREES_PER_FRAME)));
    stp_transform_translate(&t, back);
    (void)stp_segment_delete(r, 2); /* absent on the first frame */
    status = stp_segment_create(r, 2);
    if (status == STP_OK)
        status = stp_renderer_set_transform(r, &t);
    if (status == STP_OK)
        status = enter_parts(r, 1);
    if (status == STP_OK)
        status = stp_segment_close(r);
    return status;
}

int spin_render(stp_renderer *r, stp_port *port, const stp_frame_memory *mem)
{
    stp_output out;
    int status = stp_output_default(&out);
    out.hidden = STP_HIDDEN_ZBUFFER;
    out.background = spin_background;
    return status == STP_OK ? stp_renderer_render(r, port, &out, mem) : status;
}
