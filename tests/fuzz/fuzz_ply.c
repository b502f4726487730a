/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the PLY reader (stp_scene_parse with format "ply"), in
 * its ASCII and both binary encodings.  The input is the file's bytes; see
 * fuzz_scene.h for what is checked. */
#include "fuzz_scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return fz_scene_one(data, size, "ply");
}
