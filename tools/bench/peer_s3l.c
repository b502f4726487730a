/* SPDX-License-Identifier: MIT */
/* small3dlib's side of the side-by-side torus bench: see peer_s3l.h.
 * Built with STP_PEER_SMALL3DLIB defined and the peer's directory on the
 * include path (tools/bench/CMakeLists.txt, STP_PEER_SMALL3DLIB_DIR);
 * without it only stubs are compiled. */
#include "peer_s3l.h"

#ifndef STP_PEER_SMALL3DLIB

const int peer_s3l_available = 0;

int peer_s3l_init(int width, int height, const stp_mesh *parts, int part_count,
                  const peer_view *view, char *err, size_t err_size)
{
    (void)width, (void)height, (void)parts, (void)part_count, (void)view;
    if (err_size > 0)
        err[0] = 0;
    return -1;
}

void peer_s3l_pose(double tilt_degrees, double spin_degrees)
{
    (void)tilt_degrees, (void)spin_degrees;
}

int peer_s3l_frame(void)
{
    return -1;
}

const uint8_t *peer_s3l_bits(size_t *stride)
{
    *stride = 0;
    return 0;
}

void peer_s3l_free(void)
{
}

#else

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* small3dlib's configuration: a resolution chosen at run time, its
 * reduced Z buffer of bytes (PEER_S3L_Z_BUFFER 2, the default here: depth
 * in 1/16 world-unit steps up to 16 units; the cheaper of its two, and on
 * this torus the same picture as its full one but for 1 pixel at 640x480)
 * or its full 32-bit one (PEER_S3L_Z_BUFFER 1), no sorting, triangles
 * crossing the near plane dropped (none do), its default 32-bit types and
 * no perspective correction. */
#ifndef PEER_S3L_Z_BUFFER
#define PEER_S3L_Z_BUFFER 2
#endif
#define S3L_MAX_PIXELS (640 * 480)
#define S3L_Z_BUFFER PEER_S3L_Z_BUFFER
#define S3L_SORT 0
#define S3L_NEAR_CROSS_STRATEGY 0
#define S3L_PERSPECTIVE_CORRECTION 0
#define S3L_PIXEL_FUNCTION peer_pixel
#include "small3dlib.h"

#define PEER_MAX_PARTS 8
#define PEER_BACKGROUND_LEVEL 0

static const uint8_t bayer4[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};

static struct peer {
    int width, height;
    size_t stride;
    uint8_t *frame;
    uint8_t pattern[16][4]; /* level, row & 3: 8 pixels, MSB first */
    S3L_Model3D models[PEER_MAX_PARTS];
    S3L_Unit *vertices[PEER_MAX_PARTS];
    S3L_Index *triangles[PEER_MAX_PARTS];
    S3L_Unit *normals[PEER_MAX_PARTS]; /* 3 per triangle, model units of 1/512 */
    int part_count;
    S3L_Scene scene;
    double view[3][4];   /* world -> camera: rows right, up, forward; column 3 the move */
    S3L_Mat4 matrix;     /* the model's custom transform: view x pose */
    S3L_Unit pose[3][3]; /* the pose's rotation, 1/512 */
    S3L_Unit light[3];   /* unit direction towards the light, world, 1/512 */
    /* per frame */
    S3L_Unit light_model[3];
    uint32_t current;           /* triangleID of the shaded triangle */
    const uint8_t *current_pattern;
} g;

/* The level of a face from its model normal n (1/512): 0.2 + 0.8 N.L of
 * 15, rounded; N.L at 2^18 = 1. */
static const uint8_t *face_pattern(const S3L_Unit *n)
{
    S3L_Unit d = n[0] * g.light_model[0] + n[1] * g.light_model[1] + n[2] * g.light_model[2];
    S3L_Unit level;
    if (d < 0)
        d = 0;
    level = (d * 12 + 3 * (1 << 18) + (1 << 17)) >> 18;
    return g.pattern[level > 15 ? 15 : level];
}

static inline void peer_pixel(S3L_PixelInfo *p)
{
    uint8_t *byte, mask;
    if (p->triangleID != g.current) {
        g.current = p->triangleID;
        g.current_pattern = face_pattern(g.normals[p->modelIndex] + 3 * (size_t)p->triangleIndex);
    }
    byte = g.frame + (size_t)p->y * g.stride + (size_t)(p->x >> 3);
    mask = (uint8_t)(0x80u >> (p->x & 7));
    *byte = (uint8_t)(*byte ^ ((*byte ^ g.current_pattern[p->y & 3]) & mask));
}

int peer_s3l_frame(void)
{
    int y, i;
    for (y = 0; y < g.height; y++)
        memset(g.frame + (size_t)y * g.stride, g.pattern[PEER_BACKGROUND_LEVEL][y & 3], g.stride);
    /* the light into model coordinates: L_model = R^T L_world */
    for (i = 0; i < 3; i++)
        g.light_model[i] = (g.pose[0][i] * g.light[0] + g.pose[1][i] * g.light[1] +
                            g.pose[2][i] * g.light[2]) / S3L_F;
    g.current = 0xFFFFFFFFu;
    S3L_newFrame();
    S3L_drawScene(g.scene);
    return 0;
}

static S3L_Unit to_unit(double v)
{
    return (S3L_Unit)lround(v * S3L_F);
}

void peer_s3l_pose(double tilt_degrees, double spin_degrees)
{
    const double pi = 3.14159265358979323846;
    double a = tilt_degrees * pi / 180, b = spin_degrees * pi / 180;
    /* R = Ry(spin) Rx(tilt), right-handed as stp_transform_rotate turns */
    double rx[3][3] = {{1, 0, 0}, {0, cos(a), -sin(a)}, {0, sin(a), cos(a)}};
    double ry[3][3] = {{cos(b), 0, sin(b)}, {0, 1, 0}, {-sin(b), 0, cos(b)}};
    double r[3][3];
    int i, j, k;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            r[i][j] = 0;
            for (k = 0; k < 3; k++)
                r[i][j] += ry[i][k] * rx[k][j];
            g.pose[i][j] = to_unit(r[i][j]);
        }
    /* the custom matrix, matrix[column][row] for small3dlib's row vectors:
     * camera_i = sum_k (V R)_ik model_k + V_i3 */
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            double s = 0;
            for (k = 0; k < 3; k++)
                s += g.view[i][k] * r[k][j];
            g.matrix[i][j] = to_unit(s);
        }
        g.matrix[i][3] = to_unit(g.view[i][3]);
    }
    g.matrix[3][0] = g.matrix[3][1] = g.matrix[3][2] = 0;
    g.matrix[3][3] = S3L_F;
}

static void unit3(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] /= l, v[1] /= l, v[2] /= l;
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* The camera: rows right, up, forward (a left-handed frame, as small3dlib
 * has it: x right, y up, z into the picture) and the move -row . eye. */
static void set_view(const peer_view *v)
{
    double f[3], r[3], u[3];
    const double *rows[3];
    int i, k;
    for (i = 0; i < 3; i++)
        f[i] = v->at[i] - v->eye[i];
    unit3(f);
    cross3(f, v->up, r);
    unit3(r);
    cross3(r, f, u);
    rows[0] = r, rows[1] = u, rows[2] = f;
    for (i = 0; i < 3; i++) {
        g.view[i][3] = 0;
        for (k = 0; k < 3; k++) {
            g.view[i][k] = rows[i][k];
            g.view[i][3] -= rows[i][k] * v->eye[k];
        }
    }
    for (i = 0; i < 3; i++)
        f[i] = v->light[i] - v->at[i];
    unit3(f);
    for (i = 0; i < 3; i++)
        g.light[i] = to_unit(f[i]);
}

static int load_part(int p, const stp_mesh *m)
{
    size_t i, nv = m->vertex_count, nt = m->triangle_count;
    g.vertices[p] = malloc(sizeof(S3L_Unit) * 3 * nv);
    g.triangles[p] = malloc(sizeof(S3L_Index) * 3 * nt);
    g.normals[p] = malloc(sizeof(S3L_Unit) * 3 * nt);
    if (!g.vertices[p] || !g.triangles[p] || !g.normals[p])
        return -1;
    for (i = 0; i < nv; i++) {
        g.vertices[p][3 * i] = to_unit((double)m->vertices[i].x / STP_FIX_ONE);
        g.vertices[p][3 * i + 1] = to_unit((double)m->vertices[i].y / STP_FIX_ONE);
        g.vertices[p][3 * i + 2] = to_unit((double)m->vertices[i].z / STP_FIX_ONE);
    }
    for (i = 0; i < 3 * nt; i++) {
        g.triangles[p][i] = m->triangles[i];
        g.normals[p][i] = to_unit((double)m->normals[i] / STP_MESH_NORMAL_ONE);
    }
    S3L_model3DInit(g.vertices[p], (S3L_Index)nv, g.triangles[p], (S3L_Index)nt, &g.models[p]);
    g.models[p].customTransformMatrix = &g.matrix;
    /* stipple's triangles turn counter-clockwise seen from outside with y
     * up; small3dlib's screen y runs down, so a front face winds clockwise
     * there and the counter-clockwise ones (2) are culled */
    g.models[p].config.backfaceCulling = 2;
    return 0;
}

int peer_s3l_init(int width, int height, const stp_mesh *parts, int part_count,
                  const peer_view *view, char *err, size_t err_size)
{
    const double pi = 3.14159265358979323846;
    int p, level, row, x;
    double focal_px;
    peer_s3l_free();
    if (width < 2 || height < 2 || (long)width * height > S3L_MAX_PIXELS || part_count < 1 ||
        part_count > PEER_MAX_PARTS) {
        snprintf(err, err_size, "small3dlib bench: %dx%d or %d parts not supported", width, height,
                 part_count);
        return -1;
    }
    g.width = width;
    g.height = height;
    g.stride = ((size_t)width + 7) / 8;
    g.frame = calloc(g.stride, (size_t)height);
    for (level = 0; level < 16; level++)
        for (row = 0; row < 4; row++) {
            uint8_t bits = 0;
            for (x = 0; x < 8; x++)
                if (bayer4[row][x & 3] < level)
                    bits = (uint8_t)(bits | (0x80u >> x));
            g.pattern[level][row] = bits;
        }
    g.part_count = part_count;
    for (p = 0; p < part_count; p++)
        if (!g.frame || load_part(p, &parts[p]) != 0) {
            snprintf(err, err_size, "out of memory");
            peer_s3l_free();
            return -1;
        }
    S3L_resolutionX = (uint16_t)width;
    S3L_resolutionY = (uint16_t)height;
    S3L_sceneInit(g.models, (S3L_Index)part_count, &g.scene);
    /* stipple's focal length in pixels, (shorter side / 2) / tan(fov / 2);
     * small3dlib maps x / z = 1 at focalLength S3L_F to half the width */
    focal_px = (width < height ? width : height) / 2.0 / tan(view->fov_degrees / 2 * pi / 180);
    g.scene.camera.focalLength = to_unit(focal_px / (width >> 1));
    set_view(view);
    peer_s3l_pose(0, 0);
    return 0;
}

const uint8_t *peer_s3l_bits(size_t *stride)
{
    *stride = g.stride;
    return g.frame;
}

void peer_s3l_free(void)
{
    int p;
    for (p = 0; p < PEER_MAX_PARTS; p++) {
        free(g.vertices[p]);
        free(g.triangles[p]);
        free(g.normals[p]);
    }
    free(g.frame);
    memset(&g, 0, sizeof g);
}

const int peer_s3l_available = 1;

#endif
