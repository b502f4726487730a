/* SPDX-License-Identifier: MIT */
/* The table of procedural scenes and the `stipple scene` command. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scenegen_private.h"
#include "stp_posix.h"

static const stp_scenegen scenes[] = {
    {"teapot", "Newell's teapot on a checkered floor; size S: SxS squares per patch", 64,
     stp_sg_write_teapot},
    {"tetra", "Sierpinski tetrahedron; size S: 4^S triangles", 8, stp_sg_write_tetra},
    {"sphereflake", "sphereflake on a floor; size S: 1+9+...+9^S spheres", 5,
     stp_sg_write_sphereflake},
    {"torus", "torus on a floor; size S: 96*S^2 quadrilaterals", 64, stp_sg_write_torus},
    {"rings", "interlocked rings of cylinders and spheres; size S: S+1 rings", 64,
     stp_sg_write_rings},
    {"mountain", "fractal mountain; size S: 2*4^S triangles", 9, stp_sg_write_mountain},
};

const stp_scenegen *stp_scenegen_all(size_t *count)
{
    *count = sizeof scenes / sizeof scenes[0];
    return scenes;
}

const stp_scenegen *stp_scenegen_find(const char *name)
{
    size_t i;
    for (i = 0; i < sizeof scenes / sizeof scenes[0]; i++)
        if (!strcmp(scenes[i].name, name))
            return &scenes[i];
    return NULL;
}

static void usage(FILE *to)
{
    size_t i;
    fprintf(to,
            "usage: stipple scene NAME [--size N] [-o OUT.nff]\n"
            "\n"
            "Writes a procedural scene as NFF (to stdout without -o), ready for\n"
            "'stipple render'.  Scenes (--size like the Standard Procedural Databases'\n"
            "size factor, default 1):\n");
    for (i = 0; i < sizeof scenes / sizeof scenes[0]; i++)
        fprintf(to, "  %-12s %s (1..%d)\n", scenes[i].name, scenes[i].what, scenes[i].max_size);
    fprintf(to,
            "\n"
            "  -s, --size N          size factor (default 1)\n"
            "  -o, --output FILE     where to write ('-' or none: stdout); the file is\n"
            "                        replaced only once the whole scene is written\n"
            "      --list            print the scenes' names, one a line\n"
            "  -h, --help            this help\n");
}

typedef struct emit_job {
    const stp_scenegen *scene;
    int size;
} emit_job;

static int emit(FILE *out, void *ctx)
{
    const emit_job *job = ctx;
    errno = 0;
    return job->scene->write(out, job->size);
}

int stp_scenegen_main(int argc, char **argv)
{
    enum { OPT_LIST = 256 };
    static const struct option longs[] = {{"size", required_argument, 0, 's'},
                                          {"output", required_argument, 0, 'o'},
                                          {"list", no_argument, 0, OPT_LIST},
                                          {"help", no_argument, 0, 'h'},
                                          {0, 0, 0, 0}};
    const char *out_path = "-", *size_text = "1";
    emit_job job;
    char err[512], *end;
    long size;
    size_t i;
    int c;
    optind = 1;
    while ((c = getopt_long(argc, argv, "s:o:h", longs, 0)) != -1) {
        switch (c) {
        case 's': size_text = optarg; break;
        case 'o': out_path = optarg; break;
        case OPT_LIST:
            for (i = 0; i < sizeof scenes / sizeof scenes[0]; i++)
                printf("%s\n", scenes[i].name);
            return 0;
        case 'h': usage(stdout); return 0;
        default: usage(stderr); return 2;
        }
    }
    if (optind != argc - 1) {
        fprintf(stderr, "stipple: scene: give one scene NAME (try 'stipple scene --help')\n");
        return 2;
    }
    job.scene = stp_scenegen_find(argv[optind]);
    if (!job.scene) {
        fprintf(stderr, "stipple: scene: unknown scene '%s' (", argv[optind]);
        for (i = 0; i < sizeof scenes / sizeof scenes[0]; i++)
            fprintf(stderr, "%s%s", i ? ", " : "", scenes[i].name);
        fprintf(stderr, ")\n");
        return 2;
    }
    errno = 0;
    size = strtol(size_text, &end, 10);
    if (errno || end == size_text || *end || size < 1 || size > job.scene->max_size) {
        fprintf(stderr, "stipple: scene: bad --size '%s' (%s: 1..%d)\n", size_text, job.scene->name,
                job.scene->max_size);
        return 2;
    }
    job.size = (int)size;
    if (stp_posix_write_file(out_path, emit, &job, err, sizeof err) != 0) {
        fprintf(stderr, "stipple: scene: %s\n", err);
        return 1;
    }
    return 0;
}
