/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the OBJ reader (stp_scene_parse with format "obj").
 * The input is the file text; see fuzz_scene.h for what is checked. */
#include "fuzz_scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return fz_scene_one(data, size, "obj");
}
