/* SPDX-License-Identifier: MIT */
/*
 * The side-by-side torus bench of issue 21: the torus of torus.h drawn by
 * stipple (the mesh route: torus_bench_use_mesh, torus_frame) or by
 * small3dlib (peer_s3l.h, when built with the peer's source), frame after
 * frame, for tools/bench/peer_bench.sh to count under callgrind
 * (--toggle-collect=torus_frame or peer_s3l_frame: only the frames).
 *
 * usage: peer_bench [--renderer stipple|small3dlib] [--size WxH] [--spin]
 *                   [--fine AROUNDxTUBE] [--frames N] [--pbm FILE] [--keep-slivers]
 *   --renderer    who draws (default stipple)
 *   --size WxH    frame size (default 128x64; small3dlib: at most 640x480)
 *   --spin        a new pose each frame, as torus_bench --spin: tilt 20
 *                 degrees, spin 3 degrees more each frame (the pose is set
 *                 before each measured frame, outside it, for both)
 *   --fine AxT    a finer torus of A x T quads (2 A T triangles), in
 *                 parts of at most 65 535 triangles (torus_bench_use_fine_mesh)
 *   --frames N    frames drawn (default 20)
 *   --pbm FILE    write the last frame (binary PBM)
 *   --keep-slivers  stipple without pixel culling (stp_renderer_set_pixel_cull,
 *                 on by default here: no edge anti-aliasing; the same frame)
 * Prints "RENDERER WxH TRIANGLES N frames".  Exit status 3: small3dlib
 * asked for but not built in.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peer_s3l.h"
#include "torus.h"

typedef struct options {
    int small3dlib, width, height, spin, around, tube, frames, keep_slivers;
    const char *pbm;
} options;

static int usage(void)
{
    fprintf(stderr, "usage: peer_bench [--renderer stipple|small3dlib] [--size WxH] [--spin] "
                    "[--fine AROUNDxTUBE] [--frames N] [--pbm FILE] [--keep-slivers]\n");
    return 2;
}

static int parse(int argc, char **argv, options *o)
{
    int i;
    memset(o, 0, sizeof *o);
    o->width = 128;
    o->height = 64;
    o->frames = 20;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : 0;
        if (!strcmp(a, "--spin")) {
            o->spin = 1;
            continue;
        }
        if (!strcmp(a, "--keep-slivers")) {
            o->keep_slivers = 1;
            continue;
        }
        if (!v)
            return -1;
        i++;
        if (!strcmp(a, "--renderer") && (!strcmp(v, "stipple") || !strcmp(v, "small3dlib")))
            o->small3dlib = !strcmp(v, "small3dlib");
        else if (!strcmp(a, "--size") && sscanf(v, "%dx%d", &o->width, &o->height) == 2 &&
                 o->width >= 2 && o->height >= 2 && o->width <= 4096 && o->height <= 4096)
            continue;
        else if (!strcmp(a, "--fine") && sscanf(v, "%dx%d", &o->around, &o->tube) == 2 &&
                 o->around >= 3 && o->tube >= 3 && o->around <= 2000 && o->tube <= 2000)
            continue;
        else if (!strcmp(a, "--frames") && (o->frames = atoi(v)) >= 1)
            continue;
        else if (!strcmp(a, "--pbm"))
            o->pbm = v;
        else
            return -1;
    }
    return 0;
}

static int write_pbm(const char *path, const uint8_t *bits, size_t stride, int w, int h)
{
    FILE *f = fopen(path, "wb");
    int ok = f != 0 && fprintf(f, "P4\n%d %d\n", w, h) > 0;
    int y;
    size_t x;
    /* 1 = lit in the frame, 1 = black in PBM */
    for (y = 0; ok && y < h; y++)
        for (x = 0; ok && x < stride; x++)
            ok = fputc(~bits[(size_t)y * stride + x] & 0xFF, f) != EOF;
    if (f && fclose(f) != 0)
        ok = 0;
    if (!ok)
        fprintf(stderr, "peer_bench: cannot write %s\n", path);
    return ok ? 0 : -1;
}

static void view_of(const stp_scene *s, peer_view *v)
{
    v->eye[0] = s->from.x, v->eye[1] = s->from.y, v->eye[2] = s->from.z;
    v->at[0] = s->at.x, v->at[1] = s->at.y, v->at[2] = s->at.z;
    v->up[0] = s->up.x, v->up[1] = s->up.y, v->up[2] = s->up.z;
    v->fov_degrees = s->angle;
    v->light[0] = s->lights[0].position.x;
    v->light[1] = s->lights[0].position.y;
    v->light[2] = s->lights[0].position.z;
}

static int run(const options *o, torus_bench *b)
{
    int f;
    size_t stride;
    const uint8_t *bits;
    for (f = 0; f < o->frames; f++) {
        double spin = 3.0 * (f % 120);
        if (o->small3dlib) {
            if (o->spin)
                peer_s3l_pose(20, spin);
            if (peer_s3l_frame() != 0)
                return -1;
        } else {
            if (o->spin)
                torus_bench_pose(b, 20, spin, 0, 0, 0);
            if (torus_frame(b) != 0)
                return -1;
        }
    }
    if (o->small3dlib) {
        bits = peer_s3l_bits(&stride);
    } else {
        bits = b->frame;
        stride = b->stride;
    }
    return o->pbm ? write_pbm(o->pbm, bits, stride, o->width, o->height) : 0;
}

int main(int argc, char **argv)
{
    options o;
    static torus_bench b;
    char err[256];
    size_t triangles;
    int status;
    if (parse(argc, argv, &o) != 0)
        return usage();
    if (o.small3dlib && !peer_s3l_available) {
        fprintf(stderr, "peer_bench: built without small3dlib (STP_PEER_SMALL3DLIB_DIR)\n");
        return 3;
    }
    triangles = o.around ? 2 * (size_t)o.around * (size_t)o.tube : TORUS_TRIANGLES;
    /* the stipple bench also gives small3dlib its meshes and view */
    if (torus_bench_init_for(&b, o.width, o.height, triangles, err, sizeof err) != 0 ||
        (o.around ? torus_bench_use_fine_mesh(&b, o.around, o.tube, 0, err, sizeof err)
                  : torus_bench_use_mesh(&b, err, sizeof err)) != 0) {
        fprintf(stderr, "peer_bench: %dx%d: %s\n", o.width, o.height, err);
        return 1;
    }
    if (!o.keep_slivers)
        (void)stp_renderer_set_pixel_cull(b.r, 1);
    if (o.small3dlib) {
        peer_view v;
        view_of(&b.scene, &v);
        if (peer_s3l_init(o.width, o.height, b.parts, b.part_count, &v, err, sizeof err) != 0) {
            fprintf(stderr, "peer_bench: %s\n", err);
            torus_bench_free(&b);
            return 1;
        }
    }
    status = run(&o, &b);
    if (status != 0)
        fprintf(stderr, "peer_bench: a frame was refused\n");
    else
        printf("%s %dx%d %lu %d frames\n", o.small3dlib ? "small3dlib" : "stipple", o.width,
               o.height, (unsigned long)triangles, o.frames);
    peer_s3l_free();
    torus_bench_free(&b);
    return status == 0 ? 0 : 1;
}
