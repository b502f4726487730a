/* SPDX-License-Identifier: MIT */
/*
 * Error against run time of the face shader's configurations (the routes
 * inside stp_shade_fast_face, which really differ in cost):
 *   lambert-fast   Ks = 0, the fast route (16-bit scaled directions,
 *                  table-seeded reciprocal square roots, soft 16-bit
 *                  mantissas)
 *   lambert-exact  Ks = 0, the exact route (30-bit directions, 32-bit
 *                  mantissas, exact quotients and roots)
 *   full-fast      the whole equation on the fast route (the 49-node
 *                  Fresnel table, Q30 D, Q16 F, approximate reciprocals)
 *   full-exact     the whole equation on the exact route (Fresnel
 *                  computed, every factor with 32 significant bits)
 *   full-default   what stp_shade_fast_face does: fast where it keeps the
 *                  2e-3 bound, exact elsewhere
 * over the non-extreme cases of tests/shade_accuracy (the ones a scene
 * meets; Lambert's error is the highlight it leaves out), and the max
 * error over all of them, extremes included.
 * Host build (SHADE_COST_HOST): prints per configuration the max and mean
 * error against the double reference; with "--config K" it only shades
 * with configuration K (for callgrind --toggle-collect=stp_shade_fast_face).
 * Target build (shade_cost_m0/): prints the Cortex-M0+ instructions per
 * face under QEMU -icount (prepare not counted).
 */
#include "cases.h"
#include "shade_fast_private.h"

#ifndef SHADE_COST_CASES
#define SHADE_COST_CASES 3000u /* cases looked at; about 30 % are non-extreme */
#endif

enum { CFG_LAMBERT_FAST, CFG_LAMBERT_EXACT, CFG_FULL_FAST, CFG_FULL_EXACT, CFG_FULL_DEFAULT, CFG_COUNT };
static const char *const cfg_names[CFG_COUNT] = {"lambert-fast", "lambert-exact", "full-fast", "full-exact",
                                                  "full-default"};

/* the prepared shading of case c in configuration k */
static void prepare_cfg(stp_shade_fast *f, const acc_case *c, int k)
{
    stp_material m = c->material;
    if (k == CFG_LAMBERT_FAST || k == CFG_LAMBERT_EXACT)
        m.specular = 0;
    stp_shade_fast_prepare(f, &c->lighting, &m, c->eye, c->parallel, c->parallel_dir);
    if (k == CFG_LAMBERT_FAST || k == CFG_FULL_FAST) {
        f->exact_always = 0;
        f->fast_min_cos = 0;
    } else if (k == CFG_LAMBERT_EXACT || k == CFG_FULL_EXACT) {
        f->exact_always = 1;
    }
}

static int typical(const acc_case *c)
{
    return !(c->flags & ACC_EXTREME);
}

#ifdef SHADE_COST_HOST
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case_reference.h"

static double fixd(stp_fix v)
{
    return (double)v / STP_FIX_ONE;
}

int main(int argc, char **argv)
{
    int only = argc > 2 && strcmp(argv[1], "--config") == 0 ? atoi(argv[2]) : -1, k;
    uint32_t i;
    for (k = 0; k < CFG_COUNT; k++) {
        double max = 0, sum = 0, max_all = 0;
        unsigned long n = 0;
        if (only >= 0 && k != only)
            continue;
        for (i = 0; i < SHADE_COST_CASES; i++) {
            acc_case c;
            stp_shade_fast f;
            double err;
            acc_case_make(&c, i);
            if (only >= 0 && !typical(&c))
                continue;
            prepare_cfg(&f, &c, k);
            err = fabs(fixd(stp_shade_fast_face(&f, c.normal, c.point)) - (only >= 0 ? 0.0 : acc_reference(&c, NULL)));
            if (err > max_all)
                max_all = err;
            if (!typical(&c))
                continue;
            n++;
            sum += err;
            if (err > max)
                max = err;
        }
        if (only < 0) /* name, typical cases, their max and mean, the max over all cases */
            printf("%s %lu %.3e %.3e %.3e\n", cfg_names[k], n, max, sum / (double)n, max_all);
    }
    return 0;
}
#else
#include "stellaris.h"

static void report(const char *name, uint32_t v)
{
    char num[12];
    stp_semihost_write("stipple: cost ");
    stp_semihost_write(name);
    stp_semihost_write(" ");
    stp_semihost_write(stp_utoa(v, num));
    stp_semihost_write("\n");
}

int main(void)
{
    static acc_case c;
    static stp_shade_fast f;
    volatile stp_fix sink;
    uint32_t per_tick, i, n, overhead;
    uint64_t t0, t1, total;
    int k;
    stp_count_start();
    per_tick = stp_count_calibrate();
    t0 = stp_count_now();
    t1 = stp_count_now();
    overhead = (uint32_t)((t1 - t0) * per_tick);
    for (k = 0; k < CFG_COUNT; k++) {
        total = 0;
        n = 0;
        for (i = 0; i < SHADE_COST_CASES; i++) {
            acc_case_make(&c, i);
            if (!typical(&c))
                continue;
            prepare_cfg(&f, &c, k);
            t0 = stp_count_now();
            sink = stp_shade_fast_face(&f, c.normal, c.point);
            t1 = stp_count_now();
            total += (t1 - t0) * per_tick - overhead;
            n++;
        }
        report(cfg_names[k], (uint32_t)(total / n));
    }
    (void)sink;
    stp_semihost_exit(0);
}
#endif
