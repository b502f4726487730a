// SPDX-License-Identifier: MIT
// The public headers from C++: every one compiles in a C++ translation unit,
// and the core's functions link with C names (without extern "C" the linker
// looks for mangled names and this program does not build).
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <csetjmp>
#include <cstdio>
#include <cstring>

#include "stipple/stipple.h"
#include "stipple/version.h"
#include "stp_posix.h"

extern "C" {
#include <cmocka.h>
}

static void version_matches_macros(void **state)
{
    (void)state;
    char expected[32];
    std::snprintf(expected, sizeof expected, "%d.%d.%d", STP_VERSION_MAJOR, STP_VERSION_MINOR,
                  STP_VERSION_PATCH);
    assert_string_equal(stp_version(), expected);
    assert_int_equal(STP_VERSION_NUMBER,
                     STP_VERSION_MAJOR * 10000L + STP_VERSION_MINOR * 100L + STP_VERSION_PATCH);
}

// A renderer created from C++ in static storage, and a status text: the C
// functions resolve under their C names.
static void renderer_links(void **state)
{
    (void)state;
    static stp_renderer_storage storage;
    static stp_instr display_file[64];
    stp_renderer *r = stp_renderer_create(&storage, sizeof storage, display_file, 64, 8, 8);
    assert_non_null(r);
    assert_int_equal(stp_status_text(STP_OK) != NULL, 1);
    assert_true(stp_renderer_size() <= sizeof storage);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(version_matches_macros),
        cmocka_unit_test(renderer_links),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
