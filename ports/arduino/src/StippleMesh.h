/* SPDX-License-Identifier: MIT */
/*
 * A mesh written by `stipple compile MODEL --mesh` (its arrays and its
 * stp_mesh record in STP_MESH_ROM: program memory on an AVR, plain const
 * elsewhere) made readable by the core.  On an AVR the core reads RAM
 * only, so load() copies the arrays into this object (12 bytes a vertex,
 * 12 a triangle); elsewhere const data is readable in place and load()
 * copies nothing.  VERTICES and TRIANGLES: at least the mesh's counts
 * (NAME_VERTEX_COUNT, NAME_TRIANGLE_COUNT of the generated header).
 */
#ifndef STIPPLE_ARDUINO_MESH_H
#define STIPPLE_ARDUINO_MESH_H

#include <stdint.h>
#include <string.h>
#ifdef __AVR__
#include <avr/pgmspace.h>
#endif

#include "stipple/mesh.h"

template <uint16_t VERTICES, uint16_t TRIANGLES> class StippleMesh {
public:
    /* The mesh at rom (a generated NAME_mesh), readable by the core; NULL
     * when its counts exceed VERTICES or TRIANGLES. */
    const stp_mesh *load(const stp_mesh *rom)
    {
#ifdef __AVR__
        size_t corners;
        memcpy_P(&mesh_, rom, sizeof mesh_);
        if (mesh_.vertex_count > VERTICES || mesh_.triangle_count > TRIANGLES)
            return 0;
        static_assert(sizeof triangles_[0] == sizeof normals_[0], "one size for both arrays");
        corners = 3u * sizeof triangles_[0] * mesh_.triangle_count; /* triangles' and normals' bytes */
        memcpy_P(vertices_, mesh_.vertices, mesh_.vertex_count * sizeof vertices_[0]);
        memcpy_P(triangles_, mesh_.triangles, corners);
        memcpy_P(normals_, mesh_.normals, corners);
        mesh_.vertices = vertices_;
        mesh_.triangles = triangles_;
        mesh_.normals = normals_;
        mesh_.bounds = 0; /* a flash pointer on AVR: the core finds them per call */
#else
        mesh_ = *rom;
        if (mesh_.vertex_count > VERTICES || mesh_.triangle_count > TRIANGLES)
            return 0;
#endif
        return &mesh_;
    }

private:
    stp_mesh mesh_;
#ifdef __AVR__
    stp_vec3 vertices_[VERTICES];
    uint16_t triangles_[3 * TRIANGLES];
    int16_t normals_[3 * TRIANGLES];
#endif
};

#endif
