/* `stp_compile_scene compile SCENE -o OUT.c ...`: stp_tool_compile_main on
 * its own, so the firmware test does not depend on the stipple command
 * having the subcommand wired in; it takes the same arguments as
 * `stipple compile`. */
#include <stdio.h>
#include <string.h>

#include "compile_scene.h"

int main(int argc, char **argv)
{
    if (argc < 2 || strcmp(argv[1], "compile") != 0) {
        fprintf(stderr, "usage: %s compile SCENE -o OUT.c [options]\n", argv[0]);
        return 2;
    }
    return stp_tool_compile_main(argc - 1, argv + 1);
}
