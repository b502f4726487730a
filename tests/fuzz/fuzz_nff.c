/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the NFF reader (stp_scene_parse with format "nff").
 * The input is the file text; see fuzz_scene.h for what is checked. */
#include "fuzz_scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return fz_scene_one(data, size, "nff");
}
