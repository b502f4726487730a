/* SPDX-License-Identifier: MIT */
/* stipple animate: a scene seen from a moving camera, as an animated GIF or
 * numbered 1-bit PBM/PNG frames (animate_command.c). */
#ifndef STIPPLE_TOOLS_ANIMATE_COMMAND_H
#define STIPPLE_TOOLS_ANIMATE_COMMAND_H

#include <stdio.h>

/* The command's help. */
void stp_tool_animate_usage(FILE *to);

/* stipple animate ARGS (argv[0] is "animate"); returns the exit status. */
int stp_tool_animate_main(int argc, char **argv);

#endif
