/* SPDX-License-Identifier: MIT */
/*
 * The accuracy cases (../cases.h) shaded on the Cortex-M0+ (QEMU
 * mps2-an385): for each case one line "stipple: case I DIGEST FACE
 * CLASSIC" (the face shader's and stp_shade_point's shades in raw
 * stp_fix), checked on the host by test_shade_accuracy against the double
 * reference (../m0_run.sh).
 */
#include "cases.h"
#include "shade_fast_private.h"
#include "stellaris.h"

#ifndef ACC_M0_CASES
#define ACC_M0_CASES 30000u
#endif

static char *append(char *out, const char *text)
{
    while (*text)
        *out++ = *text++;
    return out;
}

static char *append_u(char *out, uint32_t v)
{
    char num[12];
    out = append(out, stp_utoa(v, num));
    *out++ = ' ';
    return out;
}

int main(void)
{
    static acc_case c;
    static stp_shade_fast fast;
    char line[96], *p;
    uint32_t i;
    p = append(line, "stipple: cases ");
    p = append_u(p, ACC_M0_CASES);
    *p++ = '\n';
    *p = 0;
    stp_semihost_write(line);
    for (i = 0; i < ACC_M0_CASES; i++) {
        stp_vec3 n;
        stp_fix face, classic;
        acc_case_make(&c, i);
        stp_shade_fast_prepare(&fast, &c.lighting, &c.material, c.eye, c.parallel, c.parallel_dir);
        face = stp_shade_fast_face(&fast, c.normal, c.point);
        n.x = (stp_fix)c.normal[0] * (1 << (STP_FIX_FRAC_BITS - 14));
        n.y = (stp_fix)c.normal[1] * (1 << (STP_FIX_FRAC_BITS - 14));
        n.z = (stp_fix)c.normal[2] * (1 << (STP_FIX_FRAC_BITS - 14));
        classic = stp_shade_point(&c.lighting, &c.material, n, c.point, c.eye, c.parallel, c.parallel_dir);
        p = append(line, "stipple: case ");
        p = append_u(p, i);
        p = append_u(p, acc_case_digest(&c));
        p = append_u(p, (uint32_t)face);
        p = append_u(p, (uint32_t)classic);
        *p++ = '\n';
        *p = 0;
        stp_semihost_write(line);
    }
    stp_semihost_exit(0);
}
