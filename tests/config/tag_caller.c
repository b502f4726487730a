/* SPDX-License-Identifier: MIT */
/* An application that links every constructor of the library (the calls
 * that carry the compatibility tag, stipple/config_guard.h): against a
 * library of its own configuration it links, runs and prints the tag;
 * against one of another configuration it must not link
 * (tests/config/check_config_tag.sh). */
#include <stdio.h>

#include "stipple/stipple.h"

int main(int argc, char **argv)
{
    (void)argv;
    if (argc > 99) { /* never at run time: the calls are linked, not made */
        stp_spans_cursor cursor;
        stp_renderer_create(NULL, 0, NULL, 0, 0, 0);
        stp_playback_create(NULL, 0, NULL, 0, 0, 0, 0, 0);
        stp_rt_create(NULL, 0, NULL, 0, 0);
        stp_direct_frame_project(NULL, NULL, NULL, NULL, NULL, 0, NULL, NULL, 0, NULL, 0);
        stp_spans_start(NULL, &cursor);
    }
    printf("%s\n", STP_CONFIG_TAG);
    return 0;
}
