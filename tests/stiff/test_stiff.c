/* SPDX-License-Identifier: MIT */
/*
 * The stiff and extreme suite and the property tests of the shading
 * function (issue 3, items 3 and 4), for the configuration this is built
 * with (the default one in CI, plain and under ASan + UBSan).
 *
 *  - One test per case of tests/stiff/stiff_cases.c: the core's status is
 *    the documented one, its shade is in [0, 1], and it is within the case's
 *    tolerance of the answer (the double reference at the exact inputs, or
 *    the documented value).  The case's comment says what was decided.
 *  - test_stiff_summary prints the worst error against half an INTENSITY
 *    step (1/30 at 16 levels) and the cases above it with their reasons.
 *  - Property tests (fixed seed): stp_shade_point against ref_shade_point
 *    on thousands of random well-conditioned inputs (the reference taken at
 *    the core's rounded inputs, so what is measured is the core's
 *    arithmetic); the specular factors D, G, F against theirs; INTENSITY
 *    exactly; and wild random inputs (any position, brightness, background,
 *    n, k, C, up to four lights) that must give a shade in [0, 1] with no
 *    undefined behaviour.
 *  - Pictures: polygons clipped at the hither plane, behind the eye and
 *    across the window cover the pixels the reference renderer covers, up
 *    to the pixels whose centres lie within the core's 1/16-pixel vertex
 *    rounding of an edge.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "stiff_cases.h"

/* ---- random numbers: xorshift64*, fixed seed ---- */

static uint64_t rng_state;

static void rng_seed(uint64_t s)
{
    rng_state = s ? s : 0x9E3779B97F4A7C15ull;
}

static uint64_t rng_next(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return rng_state * 0x2545F4914F6CDD1Dull;
}

/* uniform in [lo, hi) */
static double rng_uniform(double lo, double hi)
{
    return lo + (hi - lo) * (double)(rng_next() >> 11) / 9007199254740992.0;
}

static ref_vec3 rng_direction(void)
{
    for (;;) {
        ref_vec3 v = ref_v3(rng_uniform(-1, 1), rng_uniform(-1, 1), rng_uniform(-1, 1)), u;
        double len = ref_unit(v, &u);
        if (len > 0.1 && len <= 1)
            return u;
    }
}

static double from_fix(stp_fix v)
{
    return (double)v / (double)STP_FIX_ONE;
}

static stp_vec3 fix3(ref_vec3 v)
{
    stp_vec3 r;
    r.x = stiff_to_fix(v.x);
    r.y = stiff_to_fix(v.y);
    r.z = stiff_to_fix(v.z);
    return r;
}

static ref_vec3 unfix3(stp_vec3 v)
{
    return ref_v3(from_fix(v.x), from_fix(v.y), from_fix(v.z));
}

/* ---- the cases ---- */

static void test_case(void **state)
{
    const stiff_case *c = (const stiff_case *)*state;
    stiff_outcome o;
    stiff_run(c, &o);
    print_message("%-34s core %.6f ref %.6f ref@rounded %.6f err %.6f tol %.4f\n", c->name, o.core,
                  o.ref, o.ref_q, o.err, c->tol);
    if (c->kind == STIFF_POLYGON && o.status != c->expect_status &&
        !(c->or_degenerate && o.status == STP_ERR_DEGENERATE))
        fail_msg("%s: status %d (%s), want %d (%s) -- %s", c->name, o.status,
                 stp_status_text(o.status), c->expect_status, stp_status_text(c->expect_status),
                 c->behaviour);
    if (o.core != -1 && !(o.core >= 0 && o.core <= 1))
        fail_msg("%s: shade %g outside [0, 1]", c->name, o.core);
    if (c->kind == STIFF_SHADE && !(o.core >= 0))
        fail_msg("%s: no shade", c->name);
    if (o.has_err && o.err > c->tol)
        fail_msg("%s: |core %.6f - answer %.6f| = %.6f above %.6f -- %s", c->name, o.core, o.answer,
                 o.err, c->tol, c->behaviour);
    if (c->expect >= 0 && !o.has_err && c->expect_status == STP_OK)
        fail_msg("%s: the core gave no shade where %g is documented", c->name, c->expect);
}

static void test_stiff_summary(void **state)
{
    size_t i, n = stiff_case_count(), over = 0;
    double worst = 0, sum = 0;
    const char *worst_name = "";
    int counted = 0;
    (void)state;
    for (i = 0; i < n; i++) {
        const stiff_case *c = stiff_case_at(i);
        stiff_outcome o;
        stiff_run(c, &o);
        if (!o.has_err)
            continue;
        counted++;
        sum += o.err;
        if (o.err > worst) {
            worst = o.err;
            worst_name = c->name;
        }
        if (o.err > STIFF_HALF_STEP) {
            over++;
            print_message("above half a step: %s err %.4f (core %.4f, answer %.4f, reference at "
                          "the rounded inputs %.4f): %s\n",
                          c->name, o.err, o.core, o.answer, o.ref_q,
                          c->reason ? c->reason : "NO REASON GIVEN");
            assert_non_null(c->reason);
        }
    }
    print_message("stiff suite (F=%d, sqrt %s): %d cases with a shade, worst error %.5f (%s), "
                  "mean %.5f, half a step %.5f, %zu above it\n",
                  STP_FIX_FRAC_BITS, STP_SQRT_FAST ? "fast" : "exact", counted, worst, worst_name,
                  counted ? sum / counted : 0.0, STIFF_HALF_STEP, over);
}

/* ---- property tests ---- */

/* A random lighting / material / geometry in view-plane units, the kind a
 * scene gives: point in front of the eye, normal facing it, lights a few
 * units off with power (1 - B)(C + U). */
typedef struct shade_input {
    ref_lighting lighting;
    ref_material material;
    ref_vec3 normal, point, eye, pdir;
    int parallel;
} shade_input;

static void random_input(shade_input *in)
{
    int j;
    ref_vec3 e;
    memset(in, 0, sizeof *in);
    in->lighting.brightness = rng_uniform(0.5, 2);
    in->lighting.background = rng_uniform(0, 0.5);
    in->lighting.c = rng_uniform(0.5, 2);
    in->lighting.count = 1 + (int)(rng_next() % 2);
    in->material.reflectivity = rng_uniform(0, 1);
    in->material.refraction = rng_uniform(1.05, 20);
    in->material.gloss = exp(rng_uniform(log(0.02), log(20)));
    in->material.specular = rng_uniform(0, 1);
    in->point = ref_v3(rng_uniform(-5, 5), rng_uniform(-5, 5), rng_uniform(1, 20));
    in->eye = ref_v3(0, 0, 0);
    in->parallel = (rng_next() % 8) == 0;
    in->pdir = ref_v3(0, 0, -1);
    if (in->parallel)
        e = in->pdir;
    else
        (void)ref_unit(ref_v3(-in->point.x, -in->point.y, -in->point.z), &e);
    in->normal = rng_direction();
    if (ref_dot(in->normal, e) < 0)
        in->normal = ref_v3(-in->normal.x, -in->normal.y, -in->normal.z);
    for (j = 0; j < in->lighting.count; j++) {
        ref_vec3 d = rng_direction();
        double u = rng_uniform(0.5, 30);
        in->lighting.lights[j].position =
            ref_v3(in->point.x + d.x * u, in->point.y + d.y * u, in->point.z + d.z * u);
        in->lighting.lights[j].power =
            (1 - in->lighting.background) * (in->lighting.c + u) / sqrt((double)in->lighting.count);
    }
}

static stp_fix core_shade(const shade_input *in, ref_lighting *lq, ref_material *mq, ref_vec3 *nq,
                          ref_vec3 *pq, ref_vec3 *eq, ref_vec3 *dq)
{
    stp_lighting l;
    stp_material m;
    int j;
    stp_lighting_default(&l);
    l.brightness = stiff_to_fix(in->lighting.brightness);
    l.background = stiff_to_fix(in->lighting.background);
    l.attenuation_c = stiff_to_fix(in->lighting.c);
    l.count = in->lighting.count > STP_MAX_LIGHTS ? STP_MAX_LIGHTS : in->lighting.count;
    for (j = 0; j < l.count; j++) {
        l.lights[j].position = fix3(in->lighting.lights[j].position);
        l.lights[j].power = stiff_to_fix(in->lighting.lights[j].power);
    }
    m.reflectivity = stiff_to_fix(in->material.reflectivity);
    m.refraction = stiff_to_fix(in->material.refraction);
    m.gloss = stiff_to_fix(in->material.gloss);
    m.specular = stiff_to_fix(in->material.specular);
    if (lq) {
        memset(lq, 0, sizeof *lq);
        lq->brightness = from_fix(l.brightness);
        lq->background = from_fix(l.background);
        lq->c = from_fix(l.attenuation_c);
        lq->count = l.count;
        for (j = 0; j < l.count; j++) {
            lq->lights[j].position = unfix3(l.lights[j].position);
            lq->lights[j].power = from_fix(l.lights[j].power);
        }
        mq->reflectivity = from_fix(m.reflectivity);
        mq->refraction = from_fix(m.refraction);
        mq->gloss = from_fix(m.gloss);
        mq->specular = from_fix(m.specular);
        *nq = unfix3(fix3(in->normal));
        *pq = unfix3(fix3(in->point));
        *eq = unfix3(fix3(in->eye));
        *dq = unfix3(fix3(in->pdir));
    }
    return stp_shade_point(&l, &m, fix3(in->normal), fix3(in->point), fix3(in->eye), in->parallel,
                           fix3(in->pdir));
}

/* Smallest N.E and N.L of an input (for its conditioning). */
static double min_cosine(const shade_input *in)
{
    ref_vec3 e, l;
    double m;
    int j;
    if (in->parallel)
        e = in->pdir;
    else
        (void)ref_unit(ref_v3(in->eye.x - in->point.x, in->eye.y - in->point.y, in->eye.z - in->point.z), &e);
    m = ref_dot(in->normal, e);
    for (j = 0; j < in->lighting.count; j++) {
        ref_vec3 p = in->lighting.lights[j].position;
        double nl;
        (void)ref_unit(ref_v3(p.x - in->point.x, p.y - in->point.y, p.z - in->point.z), &l);
        nl = fabs(ref_dot(in->normal, l));
        if (nl < m)
            m = nl;
    }
    return m;
}

#define PROPERTY_CASES 20000

static void test_property_shade_point(void **state)
{
    int i, counted = 0, style_diff = 0;
    double worst = 0, sum = 0, worst_exact = 0;
    (void)state;
    rng_seed(3);
    for (i = 0; i < PROPERTY_CASES; i++) {
        shade_input in;
        ref_lighting lq;
        ref_material mq;
        ref_vec3 nq, pq, eq, dq;
        double core, ref, exact, err;
        random_input(&in);
        core = from_fix(core_shade(&in, &lq, &mq, &nq, &pq, &eq, &dq));
        assert_true(core >= 0 && core <= 1);
        /* conditioning: the shade jumps at N.E = 0 and N.L = 0; keep the
         * cosines 2^-10 or more away from them */
        if (min_cosine(&in) < 1.0 / 1024)
            continue;
        ref = ref_shade_point(&lq, &mq, nq, pq, eq, in.parallel, dq);
        exact = ref_shade_point(&in.lighting, &in.material, in.normal, in.point, in.eye, in.parallel,
                                in.pdir);
        err = fabs(core - ref);
        counted++;
        sum += err;
        if (err > worst)
            worst = err;
        if (fabs(core - exact) > worst_exact)
            worst_exact = fabs(core - exact);
        if (stp_intensity_index(stiff_to_fix(core), 16) != ref_intensity_index(exact, 16))
            style_diff++;
        /* a quarter of the half step: 1/120 (the worst is about 1e-3) */
        if (err > 1.0 / 120)
            fail_msg("case %d: core %.6f, reference at the rounded inputs %.6f (err %.6f, smallest "
                     "cosine %.2e)",
                     i, core, ref, err, min_cosine(&in));
    }
    print_message("stp_shade_point vs reference, %d random well-conditioned inputs: worst %.2e, "
                  "mean %.2e (at the rounded inputs); worst %.2e at the exact inputs; INTENSITY "
                  "differs in %d (at a step boundary)\n",
                  counted, worst, sum / counted, worst_exact, style_diff);
    assert_true(counted > PROPERTY_CASES / 2);
}

static void test_property_specular_terms(void **state)
{
    int i;
    double wd = 0, wg = 0, wf = 0;
    (void)state;
    rng_seed(4);
    for (i = 0; i < PROPERTY_CASES; i++) {
        /* random N, E, L with N.E, N.L > 0 */
        ref_vec3 n = rng_direction(), e = rng_direction(), l = rng_direction(), h;
        double ne, nl, nh, eh, k = exp(rng_uniform(log(0.01), log(100))), nr = rng_uniform(1.01, 50);
        double d, g, f;
        stp_specular_terms t;
        stp_fix fnh, fne, fnl, feh, fk, fnr;
        if (ref_dot(n, e) < 0)
            e = ref_v3(-e.x, -e.y, -e.z);
        if (ref_dot(n, l) < 0)
            l = ref_v3(-l.x, -l.y, -l.z);
        if (ref_unit(ref_v3(l.x + e.x, l.y + e.y, l.z + e.z), &h) == 0)
            continue;
        fnh = stiff_to_fix(ref_dot(n, h));
        fne = stiff_to_fix(ref_dot(n, e));
        fnl = stiff_to_fix(ref_dot(n, l));
        feh = stiff_to_fix(ref_dot(e, h));
        fk = stiff_to_fix(k);
        fnr = stiff_to_fix(nr);
        nh = from_fix(fnh);
        ne = from_fix(fne);
        nl = from_fix(fnl);
        eh = from_fix(feh);
        if (ne <= 0 || nl <= 0 || nh <= 0 || eh <= 1.0 / 64)
            continue;
        t = stp_specular(fnh, fne, fnl, feh, fnr, fk);
        d = ref_facet_d(nh, from_fix(fk));
        g = ref_blocking_g(nh, ne, nl, eh);
        f = ref_fresnel_f(eh, from_fix(fnr));
        if (fabs(from_fix(t.d) - d) > wd)
            wd = fabs(from_fix(t.d) - d);
        if (fabs(from_fix(t.g) - g) > wg)
            wg = fabs(from_fix(t.g) - g);
        if (fabs(from_fix(t.f) - f) > wf)
            wf = fabs(from_fix(t.f) - f);
    }
    print_message("specular factors vs reference, worst absolute error: D %.2e, G %.2e, F %.2e\n", wd,
                  wg, wf);
    /* a few steps of 2^-F each (the quotients truncate; Fresnel goes
     * through a square root and two quotients) */
    assert_true(wd <= 16.0 / STP_FIX_ONE);
    assert_true(wg <= 16.0 / STP_FIX_ONE);
    assert_true(wf <= 64.0 / STP_FIX_ONE);
}

static void test_property_intensity(void **state)
{
    int i, levels;
    (void)state;
    rng_seed(5);
    for (levels = 2; levels <= 256; levels++) {
        for (i = 0; i < 200; i++) {
            stp_fix s = (stp_fix)(rng_next() % ((uint64_t)STP_FIX_ONE + 1));
            if (i == 0)
                s = 0;
            if (i == 1)
                s = STP_FIX_ONE;
            assert_int_equal(stp_intensity_index(s, levels), ref_intensity_index(from_fix(s), levels));
        }
    }
}

/* Wild inputs: anything a caller can pass.  The shade must be in [0, 1]
 * (UBSan checks there is no undefined behaviour on the way). */
static void test_property_wild_inputs(void **state)
{
    int i, j;
    double range = from_fix(STP_FIX_MAX);
    (void)state;
    rng_seed(6);
    for (i = 0; i < PROPERTY_CASES; i++) {
        stp_lighting l;
        stp_material m;
        stp_vec3 n, p, e, d;
        stp_fix s;
        double scale = pow(2.0, rng_uniform(-20, log2(range)));
        stp_lighting_default(&l);
        l.brightness = stiff_to_fix(rng_uniform(-2, 1) * pow(2.0, rng_uniform(0, 14)));
        l.background = stiff_to_fix(rng_uniform(-1, 2));
        l.attenuation_c = stiff_to_fix(rng_uniform(-1, 3));
        l.count = (int)(rng_next() % (STP_MAX_LIGHTS + 1));
        if (rng_next() % 16 == 0)
            l.count = -1 - (int)(rng_next() % 4); /* out of range: taken as 0 */
        for (j = 0; j < STP_MAX_LIGHTS; j++) {
            l.lights[j].position.x = stiff_to_fix(rng_uniform(-1, 1) * scale);
            l.lights[j].position.y = stiff_to_fix(rng_uniform(-1, 1) * scale);
            l.lights[j].position.z = stiff_to_fix(rng_uniform(-1, 1) * scale);
            l.lights[j].power = stiff_to_fix(rng_uniform(-1, 1) * pow(2.0, rng_uniform(-10, 15)));
        }
        m.reflectivity = stiff_to_fix(rng_uniform(-0.5, 1.5));
        m.refraction = stiff_to_fix(rng_uniform(-1, 1) * pow(2.0, rng_uniform(-16, 15)));
        m.gloss = stiff_to_fix(rng_uniform(-1, 1) * pow(2.0, rng_uniform(-18, 15)));
        m.specular = stiff_to_fix(rng_uniform(-1, 2));
        n = fix3(rng_direction());
        if (rng_next() % 8 == 0) {
            /* not unit, or zero */
            n.x = (stp_fix)(rng_next() % 3) - 1;
            n.y = stiff_to_fix(rng_uniform(-3, 3));
        }
        p = fix3(ref_v3(rng_uniform(-1, 1) * scale, rng_uniform(-1, 1) * scale, rng_uniform(-1, 1) * scale));
        e = fix3(ref_v3(rng_uniform(-1, 1) * scale, rng_uniform(-1, 1) * scale, rng_uniform(-1, 1) * scale));
        if (rng_next() % 8 == 0)
            e = p;
        if (rng_next() % 8 == 0) {
            p.x = rng_next() % 2 ? STP_FIX_MAX : STP_FIX_MIN;
            e.x = -p.x;
        }
        d = fix3(rng_direction());
        s = stp_shade_point(&l, &m, n, p, e, (int)(rng_next() % 2), d);
        if (s < 0 || s > STP_FIX_ONE)
            fail_msg("wild input %d: shade %d outside [0, ONE]", i, (int)s);
    }
}

/* ---- pictures of clipped polygons ---- */

typedef struct picture_case {
    const char *name;
    ref_view view;
    int n;
    ref_vec3 v[8];
} picture_case;

static int flush_into(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    uint8_t *dst = (uint8_t *)port->user;
    uint32_t r;
    for (r = 0; r < rows; r++)
        memcpy(dst + (size_t)(y0 + r) * port->width, pixels + (size_t)r * stride, port->width);
    return 0;
}

#define PW 64
#define PH 48

/* Coverage of one polygon (shading off, fill style 16 = level 255, on a
 * black background) by the core and by the reference; returns the number
 * of differing pixels and the reference's edge length in pixels. */
static int compare_coverage(const picture_case *pc, double *perimeter, int *covered)
{
    static int64_t rmem[8192];
    static stp_instr df[64];
    static uint8_t band[PW * PH], core_px[PW * PH];
    static uint16_t zbuf[PW * PH];
    static unsigned char ref_grey[PW * PH];
    stp_renderer *r;
    stp_view view;
    stp_vec3 v[8];
    stp_port port;
    stp_output out;
    stp_frame_memory mem;
    ref_ctx ctx;
    ref_output rout;
    int i, diff = 0, status;
    size_t k;
    assert_true(stp_renderer_size() <= sizeof rmem);
    r = stp_renderer_create(rmem, sizeof rmem, df, 64, PW, PH);
    assert_non_null(r);
    memset(&view, 0, sizeof view);
    view.from = fix3(pc->view.from);
    view.at = fix3(pc->view.at);
    view.up = fix3(pc->view.up);
    view.fov_degrees = stiff_to_fix(pc->view.fov_degrees);
    view.window_half = stiff_to_fix(pc->view.window_half);
    view.hither = stiff_to_fix(pc->view.hither);
    view.projection = pc->view.perspective ? STP_PERSPECTIVE : STP_PARALLEL;
    assert_int_equal(stp_renderer_set_view(r, &view), STP_OK);
    stp_renderer_set_shading(r, 0);
    stp_renderer_set_fill_style(r, 16);
    assert_int_equal(stp_segment_create(r, 1), STP_OK);
    for (i = 0; i < pc->n; i++)
        v[i] = fix3(pc->v[i]);
    status = stp_renderer_polygon(r, v, pc->n);
    assert_int_equal(status, STP_OK);
    assert_int_equal(stp_segment_close(r), STP_OK);
    memset(&port, 0, sizeof port);
    port.width = PW;
    port.height = PH;
    port.format = STP_PIXEL_GREY8;
    port.flush = flush_into;
    port.user = core_px;
    memset(&out, 0, sizeof out);
    out.hidden = STP_HIDDEN_ZBUFFER;
    memset(&mem, 0, sizeof mem);
    mem.band = band;
    mem.band_size = sizeof band;
    mem.band_rows = PH;
    mem.zbuf = zbuf;
    mem.zbuf_count = PW * PH;
    assert_int_equal(stp_renderer_render(r, &port, &out, &mem), STP_OK);

    assert_int_equal(ref_ctx_init(&ctx, PW, PH), 0);
    assert_int_equal(ref_set_view(&ctx, &pc->view), REF_OK);
    ctx.shading = 0;
    ctx.fill_style = 16;
    assert_int_equal(ref_polygon(&ctx, pc->v, pc->n, 0, 0), REF_OK);
    /* the edge length on screen of what is left after clipping */
    *perimeter = 0;
    for (k = 0; k < ctx.poly_count; k++) {
        const ref_poly2 *p = &ctx.polys[k];
        for (i = 0; i < p->count; i++) {
            const double *a = ctx.xy + 2 * (p->first + (size_t)i);
            const double *b = ctx.xy + 2 * (p->first + (size_t)((i + 1) % p->count));
            double dx = b[0] - a[0], dy = b[1] - a[1];
            /* only the part of the edge on the device counts, roughly */
            double len = sqrt(dx * dx + dy * dy);
            *perimeter += len < 2 * (PW + PH) ? len : 2 * (PW + PH);
        }
    }
    memset(&rout, 0, sizeof rout);
    rout.hidden = REF_HIDDEN_ZBUFFER;
    rout.cell = 4;
    rout.gamma = rout.gamma_k = 1;
    assert_int_equal(ref_finish(&ctx, &rout, ref_grey, 0, 0, 0), 0);
    ref_ctx_free(&ctx);
    *covered = 0;
    for (i = 0; i < PW * PH; i++) {
        if ((core_px[i] == 255) != (ref_grey[i] == 255))
            diff++;
        if (ref_grey[i] == 255)
            (*covered)++;
    }
    return diff;
}

static void test_pictures_of_clipped_polygons(void **state)
{
    picture_case pcs[6];
    int i;
    (void)state;
    memset(pcs, 0, sizeof pcs);
    for (i = 0; i < 6; i++) {
        pcs[i].view.from = ref_v3(0, 0, -4);
        pcs[i].view.up = ref_v3(0, 1, 0);
        pcs[i].view.fov_degrees = 60;
        pcs[i].view.hither = 1.0 / 64;
        pcs[i].view.window_half = 2;
        pcs[i].view.perspective = 1;
    }
    pcs[0].name = "partly behind the eye";
    pcs[0].n = 3;
    pcs[0].v[0] = ref_v3(-1, -1, -6);
    pcs[0].v[1] = ref_v3(1, -1, 0);
    pcs[0].v[2] = ref_v3(0, 1, 1);
    pcs[1].name = "floor through the eye's feet to behind it";
    pcs[1].n = 4;
    pcs[1].v[0] = ref_v3(-3, -1, -10);
    pcs[1].v[1] = ref_v3(3, -1, -10);
    pcs[1].v[2] = ref_v3(3, -1, 10);
    pcs[1].v[3] = ref_v3(-3, -1, 10);
    pcs[2].name = "square in the hither plane";
    pcs[2].n = 4;
    pcs[2].v[0] = ref_v3(-0.005, -0.004, -4 + 1.0 / 64);
    pcs[2].v[1] = ref_v3(0.005, -0.004, -4 + 1.0 / 64);
    pcs[2].v[2] = ref_v3(0.005, 0.003, -4 + 1.0 / 64);
    pcs[2].v[3] = ref_v3(-0.005, 0.003, -4 + 1.0 / 64);
    pcs[3].name = "wider than the window";
    pcs[3].n = 3;
    pcs[3].v[0] = ref_v3(-50, -3, 2);
    pcs[3].v[1] = ref_v3(40, -2, 1);
    pcs[3].v[2] = ref_v3(0.3, 30, 0.5);
    pcs[4].name = "vertex just behind the eye";
    pcs[4].n = 3;
    pcs[4].v[0] = ref_v3(0.1, 0.2, -4.5);
    pcs[4].v[1] = ref_v3(1, -1, 0);
    pcs[4].v[2] = ref_v3(-1, -0.5, 1);
    pcs[5].name = "parallel view, tilted";
    pcs[5].view.perspective = 0;
    pcs[5].n = 4;
    pcs[5].v[0] = ref_v3(-1.3, -0.9, 0);
    pcs[5].v[1] = ref_v3(1.1, -1.2, 0.5);
    pcs[5].v[2] = ref_v3(1.4, 1.0, 1);
    pcs[5].v[3] = ref_v3(-0.8, 1.3, 0.2);
    for (i = 0; i < 6; i++) {
        double perimeter;
        int covered, diff = compare_coverage(&pcs[i], &perimeter, &covered);
        /* a pixel can change owner only where an edge passes within the
         * core's vertex rounding (1/32 pixel each way, plus the projection's
         * own rounding) of its centre: allow a tenth of the edge length */
        int bound = 2 + (int)(perimeter / 10);
        print_message("%-42s covered %4d, differing %3d (bound %d, edges %.0f px)\n", pcs[i].name,
                      covered, diff, bound, perimeter);
        assert_true(covered > 0);
        assert_true(diff <= bound);
    }
}

/* The fill rule's ties: with a parallel view of 16 pixels per unit, vertices
 * on pixel centres and edges vertical, horizontal or at 45 degrees, the
 * core's device coordinates and edge crossings are exact, so every centre
 * on an edge is decided by the top-left rule alone: the core and the
 * reference must agree pixel for pixel. */
static void test_fill_rule_ties_exact(void **state)
{
    /* device (x, y) of the vertices, y down */
    static const double shapes[][5][2] = {
        {{10.5, 5.5}, {20.5, 5.5}, {20.5, 15.5}, {10.5, 15.5}, {-1, -1}},  /* square */
        {{40.5, 4.5}, {50.5, 14.5}, {40.5, 24.5}, {30.5, 14.5}, {-1, -1}}, /* diamond */
        {{5.5, 30.5}, {25.5, 30.5}, {5.5, 45.5}, {-1, -1}, {-1, -1}},     /* right triangle */
        {{33, 30}, {60, 30}, {60, 44}, {33, 44}, {-1, -1}},               /* edges between centres */
    };
    size_t k;
    (void)state;
    for (k = 0; k < sizeof shapes / sizeof shapes[0]; k++) {
        picture_case pc;
        double perimeter;
        int covered, diff, i;
        memset(&pc, 0, sizeof pc);
        pc.name = "fill rule";
        pc.view.from = ref_v3(0, 0, -4);
        pc.view.up = ref_v3(0, 1, 0);
        pc.view.hither = 1.0 / 64;
        pc.view.window_half = 1.5; /* 48 / 2 / 1.5 = 16 pixels per unit */
        pc.view.perspective = 0;
        for (i = 0; i < 5 && shapes[k][i][0] >= 0; i++) {
            /* view x is world -x here (x right in a left-handed view of a
             * right-handed world seen along +z) */
            pc.v[i] = ref_v3(-(shapes[k][i][0] - PW / 2.0) / 16, (PH / 2.0 - shapes[k][i][1]) / 16, 0);
            pc.n++;
        }
        diff = compare_coverage(&pc, &perimeter, &covered);
        print_message("fill-rule shape %zu: covered %d, differing %d\n", k, covered, diff);
        assert_true(covered > 0);
        if (k == 0)
            assert_int_equal(covered, 100); /* centres 10.5..19.5 both ways */
        assert_int_equal(diff, 0);
    }
}

int main(void)
{
    static const struct CMUnitTest fixed[] = {
        cmocka_unit_test(test_stiff_summary),
        cmocka_unit_test(test_property_shade_point),
        cmocka_unit_test(test_property_specular_terms),
        cmocka_unit_test(test_property_intensity),
        cmocka_unit_test(test_property_wild_inputs),
        cmocka_unit_test(test_pictures_of_clipped_polygons),
        cmocka_unit_test(test_fill_rule_ties_exact),
    };
    size_t n = stiff_case_count(), i;
    struct CMUnitTest *tests = calloc(n, sizeof *tests);
    int failed;
    if (!tests)
        return 1;
    for (i = 0; i < n; i++) {
        tests[i].name = stiff_case_at(i)->name;
        tests[i].test_func = test_case;
        tests[i].initial_state = (void *)(uintptr_t)stiff_case_at(i);
    }
    failed = _cmocka_run_group_tests("stiff_cases", tests, n, NULL, NULL);
    failed += cmocka_run_group_tests_name("stiff_properties", fixed, NULL, NULL);
    free(tests);
    return failed ? 1 : 0;
}
