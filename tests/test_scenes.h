/* SPDX-License-Identifier: MIT */
/*
 * Shared by the cmocka tests that load the shared scenes: where things are
 * (CTest's environment: STP_SCENES_DIR, STP_SOURCE_DIR, STP_BINARY_DIR) and
 * a loader that fails the test on error.  Include after <cmocka.h>.
 */
#ifndef STIPPLE_TESTS_TEST_SCENES_H
#define STIPPLE_TESTS_TEST_SCENES_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"

/* The environment variable's value, or fallback when unset or empty. */
static inline const char *stp_test_env_or(const char *name, const char *fallback)
{
    const char *v = getenv(name);
    return v && *v ? v : fallback;
}

/* The path of a shared scene: name with or without its ".nff". */
static inline void stp_test_scene_path(const char *name, char *path, size_t len)
{
    snprintf(path, len, "%s/%s%s", stp_test_env_or("STP_SCENES_DIR", "../shared/scenes"), name,
             strchr(name, '.') ? "" : ".nff");
}

/* Load a shared scene with the default reader options, or fail the test. */
static inline void stp_test_load_scene(const char *name, stp_scene *scene)
{
    char path[1024], err[512];
    stp_scene_options sopt;
    stp_scene_options_default(&sopt);
    stp_test_scene_path(name, path, sizeof path);
    if (stp_scene_load(path, &sopt, scene, err, sizeof err) != 0)
        fail_msg("cannot load %s: %s", path, err);
}

#endif
