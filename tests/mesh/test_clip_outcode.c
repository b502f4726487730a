/* SPDX-License-Identifier: MIT */
/*
 * stp_clip_outcode (clip.c; where 64-bit products are library calls it
 * first shows a point clearly inside the side planes in 32-bit products)
 * against the outcode formed here in 64-bit integers from
 * clip_private.h's definition: bit 0 for z below the near plane, bits
 * 1..4 for floor(f x / 2^16) or floor(f y / 2^16) beyond +-trunc(W z / 2)
 * or +-trunc(H z / 2) (perspective) or +-W 2^15, +-H 2^15 (parallel);
 * and against the signs of stp_clip_distance.  Random volumes (device
 * sizes up to 32767, focal lengths from 2^-4 to 2^9 units) and points at
 * every scale, many put within a few raw units of a side plane (where the
 * 32-bit test must leave the decision to the exact one).  Built against
 * the host core and the 32-bit target arithmetic (_narrow).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "clip_private.h"

#define TEST_RANDOM_SEED 0xD1B54A32D192ED03u
#include "test_random.h" /* next_random */

/* uniform in [-2^bits, 2^bits) for 0 <= bits <= 31 */
static int64_t random_signed(int bits)
{
    return (int64_t)(next_random() >> (32 - bits - 1 > 0 ? 32 - bits - 1 : 0)) - ((int64_t)1 << bits);
}

static int64_t floor_div(int64_t a, int64_t b) /* b > 0 */
{
    int64_t q = a / b;
    return q * b > a ? q - 1 : q;
}

static unsigned reference(const stp_clip_volume *v, stp_vec3 p)
{
    int64_t fx = floor_div((int64_t)v->focal * p.x, 65536), fy = floor_div((int64_t)v->focal * p.y, 65536);
    int64_t hw = v->parallel ? (int64_t)v->width * 65536 / 2 : (int64_t)v->width * p.z / 2;
    int64_t hh = v->parallel ? (int64_t)v->height * 65536 / 2 : (int64_t)v->height * p.z / 2;
    unsigned code = 0;
    if (p.z < v->near)
        code |= 1u;
    if (fx < -hw)
        code |= 2u;
    if (fx > hw)
        code |= 4u;
    if (fy > hh)
        code |= 8u;
    if (fy < -hh)
        code |= 16u;
    return code;
}

static stp_fix clamp_fix(int64_t v)
{
    return (stp_fix)(v > INT32_MAX ? INT32_MAX : (v < INT32_MIN ? INT32_MIN : v));
}

static void test_outcodes(void **state)
{
    long round, inside = 0, boundary = 0;
    (void)state;
    for (round = 0; round < 2000000; round++) {
        stp_clip_volume v;
        stp_vec3 p;
        unsigned code;
        int plane;
        v.width = 1 + next_random() % 32767u;
        v.height = 1 + next_random() % 32767u;
        v.focal = (stp_fix)(((int64_t)1 << 12) + (next_random() % ((1u << 25) - (1u << 12))));
        v.near = (stp_fix)(next_random() % (1u << 16));
        v.parallel = next_random() % 16u == 0;
        p.z = clamp_fix(random_signed(4 + (int)(next_random() % 27u)));
        if (next_random() % 4u != 0 && p.z < 0)
            p.z = -p.z - 1;
        p.x = clamp_fix(random_signed(2 + (int)(next_random() % 30u)));
        p.y = clamp_fix(random_signed(2 + (int)(next_random() % 30u)));
        if (next_random() % 2u == 0 && !v.parallel && p.z > 0) {
            /* x or y a few raw units from where a side plane crosses z */
            int64_t edge_x = (int64_t)v.width * p.z / 2 * 65536 / v.focal;
            int64_t edge_y = (int64_t)v.height * p.z / 2 * 65536 / v.focal;
            int64_t wobble = random_signed(3);
            if (next_random() % 2u)
                p.x = clamp_fix((next_random() % 2u ? edge_x : -edge_x) + wobble);
            else
                p.y = clamp_fix((next_random() % 2u ? edge_y : -edge_y) + wobble);
            boundary++;
        }
        code = stp_clip_outcode(&v, p);
        if (code != reference(&v, p))
            fprintf(stderr, "outcode %u, reference %u: W %u H %u f %d near %d par %d p (%d %d %d)\n", code,
                    reference(&v, p), (unsigned)v.width, (unsigned)v.height, (int)v.focal, (int)v.near,
                    v.parallel, (int)p.x, (int)p.y, (int)p.z);
        assert_int_equal(code, reference(&v, p));
        for (plane = 0; plane < 5; plane++)
            assert_int_equal((code >> plane) & 1u, stp_clip_distance(&v, plane, p) < 0 ? 1u : 0u);
        inside += (code & 30u) == 0;
    }
    fprintf(stderr, "  %ld points, %ld inside the side planes, %ld put at one\n", round, inside, boundary);
    assert_true(inside > 200000 && boundary > 200000);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_outcodes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
