/* SPDX-License-Identifier: MIT */
/* Deterministic shading cases: see cases.h.  Only double + - * / and
 * integer conversions, so the host and the Cortex-M0+ (soft float) build
 * the same bits; -ffp-contract=off keeps the host from fusing them. */
#include "cases.h"

#define ONE_D ((double)STP_FIX_ONE)
#define COORD_MAX 30000.0 /* within stp_fix's +-32767 at F = 16 */

typedef struct acc_rng {
    uint64_t s;
} acc_rng;

typedef struct v3 {
    double x, y, z;
} v3;

static uint64_t next64(acc_rng *r)
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* uniform in [0, 1) */
static double uni(acc_rng *r)
{
    return (double)(next64(r) >> 11) * (1.0 / 9007199254740992.0);
}

static double range(acc_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * uni(r);
}

static int chance(acc_rng *r, double p)
{
    return uni(r) < p;
}

/* 2^x by its integer part and a series for the fraction */
static double exp2_d(double x)
{
    double k = 0.0, f, t, s = 1.0, r;
    int n;
    while (k + 1.0 <= x)
        k += 1.0;
    while (k > x)
        k -= 1.0;
    f = (x - k) * 0.69314718055994530942;
    t = 1.0;
    for (n = 1; n < 24; n++) {
        t = t * f / n;
        s += t;
    }
    r = s;
    for (; k > 0.0; k -= 1.0)
        r *= 2.0;
    for (; k < 0.0; k += 1.0)
        r *= 0.5;
    return r;
}

/* log-uniform in [2^lo, 2^hi] */
static double logu(acc_rng *r, double lo, double hi)
{
    return exp2_d(range(r, lo, hi));
}

static double sqrt_d(double x)
{
    double scale = 1.0, y = 1.0;
    int i;
    if (x <= 0.0)
        return 0.0;
    while (x > 4.0) {
        x *= 0.25;
        scale *= 2.0;
    }
    while (x < 0.25) {
        x *= 4.0;
        scale *= 0.5;
    }
    for (i = 0; i < 8; i++)
        y = 0.5 * (y + x / y);
    return y * scale;
}

static v3 mk(double x, double y, double z)
{
    v3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

static double dot(v3 a, v3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

static v3 axpy(double a, v3 x, v3 y)
{
    return mk(a * x.x + y.x, a * x.y + y.y, a * x.z + y.z);
}

static v3 unit(v3 v)
{
    double l = sqrt_d(dot(v, v));
    return mk(v.x / l, v.y / l, v.z / l);
}

static v3 random_unit(acc_rng *r)
{
    for (;;) {
        double x, y, z, q;
        v3 v;
        x = range(r, -1, 1); /* one statement each: the order of arguments is the compiler's */
        y = range(r, -1, 1);
        z = range(r, -1, 1);
        v = mk(x, y, z);
        q = dot(v, v);
        if (q > 0.01 && q <= 1.0)
            return unit(v);
    }
}

/* a unit vector at cosine c to the unit n */
static v3 at_cosine(acc_rng *r, v3 n, double c)
{
    for (;;) {
        v3 w = random_unit(r), t = axpy(-dot(w, n), n, w);
        if (dot(t, t) > 0.01)
            return axpy(c, n, axpy(sqrt_d(1.0 - c * c), unit(t), mk(0, 0, 0)));
    }
}

static int32_t quant(double x)
{
    double v = x * ONE_D;
    if (v > 2147483000.0)
        v = 2147483000.0;
    if (v < -2147483000.0)
        v = -2147483000.0;
    return v >= 0.0 ? (int32_t)(v + 0.5) : -(int32_t)(-v + 0.5);
}

static stp_vec3 quant3(v3 v)
{
    stp_vec3 q;
    q.x = quant(v.x);
    q.y = quant(v.y);
    q.z = quant(v.z);
    return q;
}

static v3 dequant3(stp_vec3 q)
{
    return mk(q.x / ONE_D, q.y / ONE_D, q.z / ONE_D);
}

/* p + d u, d shortened so that every component stays within COORD_MAX */
static stp_vec3 place(v3 p, v3 u, double d)
{
    v3 q = axpy(d, u, p);
    while (q.x > COORD_MAX || q.x < -COORD_MAX || q.y > COORD_MAX || q.y < -COORD_MAX ||
           q.z > COORD_MAX || q.z < -COORD_MAX) {
        d *= 0.5;
        q = axpy(d, u, p);
    }
    return quant3(q);
}

static void make_normal(acc_case *c, acc_rng *r, v3 *n)
{
    v3 u = random_unit(r);
    double x = u.x * 16384.0, y = u.y * 16384.0, z = u.z * 16384.0;
    c->normal[0] = (int16_t)(x >= 0 ? (int32_t)(x + 0.5) : -(int32_t)(-x + 0.5));
    c->normal[1] = (int16_t)(y >= 0 ? (int32_t)(y + 0.5) : -(int32_t)(-y + 0.5));
    c->normal[2] = (int16_t)(z >= 0 ? (int32_t)(z + 0.5) : -(int32_t)(-z + 0.5));
    *n = unit(mk(c->normal[0], c->normal[1], c->normal[2]));
}

/* the eye (or the parallel direction); *e gets the direction towards it */
static void make_eye(acc_case *c, acc_rng *r, v3 n, v3 p, int extreme, v3 *e)
{
    double cosine;
    if (extreme && chance(r, 0.35)) {
        cosine = logu(r, -13.3, -5.0); /* 1e-4 .. 3e-2 */
        c->flags |= ACC_GRAZING_EYE;
    } else if (chance(r, 0.05)) {
        cosine = -range(r, 0.0, 1.0); /* a back face */
    } else {
        cosine = range(r, 0.05, 1.0);
    }
    *e = at_cosine(r, n, cosine);
    c->parallel = chance(r, 0.2);
    if (c->parallel) {
        c->parallel_dir = quant3(*e);
        c->eye.x = c->eye.y = c->eye.z = 0;
        *e = unit(dequant3(c->parallel_dir));
    } else {
        c->parallel_dir.x = c->parallel_dir.y = c->parallel_dir.z = 0;
        c->eye = place(p, *e, logu(r, -6.6, 10.0)); /* 1e-2 .. 1e3 */
        *e = unit(axpy(-1.0, p, dequant3(c->eye)));
    }
}

static void make_light(acc_case *c, acc_rng *r, int j, v3 n, v3 p, v3 e, int extreme)
{
    stp_light *light = &c->lighting.lights[j];
    double pick = uni(r), d;
    v3 l;
    light->colour[0] = light->colour[1] = light->colour[2] = STP_FIX_ONE;
    if (extreme && pick < 0.3 && dot(n, e) > 0.0) {
        /* near the mirror direction of E */
        v3 m = axpy(2.0 * dot(n, e), n, mk(-e.x, -e.y, -e.z));
        double angle = logu(r, -20.0, -3.3); /* 1e-6 .. 0.1 */
        l = unit(axpy(angle, random_unit(r), m));
        c->flags |= ACC_NEAR_MIRROR;
    } else if (extreme && pick < 0.5) {
        l = at_cosine(r, n, logu(r, -13.3, -5.0));
        c->flags |= ACC_GRAZING_LIGHT;
    } else if (extreme && pick < 0.6) {
        l = at_cosine(r, n, -range(r, 1e-3, 1.0));
        c->flags |= ACC_BEHIND;
    } else {
        l = at_cosine(r, n, range(r, 0.02, 1.0));
    }
    if (chance(r, 0.005)) {
        d = 0.0; /* the light on the point */
    } else if (extreme && chance(r, 0.5)) {
        d = logu(r, -11.7, 14.6); /* 3e-4 .. 2.5e4 */
        if (d < 1e-2)
            c->flags |= ACC_NEAR_LIGHT;
    } else {
        d = logu(r, -1.0, 6.6); /* 0.5 .. 100 */
    }
    light->position = place(p, l, d);
    if (chance(r, 0.1)) {
        light->power = 0;
        c->flags |= ACC_POWER_ZERO;
    } else {
        light->power = quant(extreme ? logu(r, -6.6, 3.3) : range(r, 0.2, 1.5)); /* 0.01 .. 10 */
    }
}

static void make_parameters(acc_case *c, acc_rng *r, int extreme)
{
    stp_lighting *lg = &c->lighting;
    stp_material *m = &c->material;
    double pick = uni(r);
    lg->brightness = quant(extreme && chance(r, 0.6) ? logu(r, -6.6, 13.3) : range(r, 0.5, 2.0));
    lg->background = pick < 0.2 ? 0 : (pick < 0.25 ? STP_FIX_ONE : quant(uni(r)));
    if (extreme && chance(r, 0.4)) {
        lg->attenuation_c = quant(logu(r, -16.0, 4.0));
        if (lg->attenuation_c <= STP_FIX_ONE >> 8)
            c->flags |= ACC_SMALL_C;
    } else {
        lg->attenuation_c = STP_FIX_ONE;
    }
    pick = uni(r);
    m->reflectivity = pick < 0.1 ? 0 : (pick < 0.2 ? STP_FIX_ONE : quant(uni(r)));
    m->refraction = quant(extreme && chance(r, 0.5) ? logu(r, 0.00432, 11.55) : logu(r, 0.263, 4.32));
    m->gloss = quant(extreme && chance(r, 0.5) ? logu(r, -15.93, 9.97) : logu(r, -4.32, 3.32));
    if (m->gloss < 1)
        m->gloss = 1;
    if (m->gloss <= quant(2e-4))
        c->flags |= ACC_TINY_GLOSS;
    pick = uni(r);
    m->specular = pick < 0.05 ? 0 : (pick < 0.15 ? quant(logu(r, -6.6, 3.3)) : STP_FIX_ONE);
    m->colour[0] = m->colour[1] = m->colour[2] = STP_FIX_ONE;
}

void acc_case_make(acc_case *c, uint32_t index)
{
    acc_rng r;
    v3 n, p, e;
    int j, extreme;
    r.s = 0x5EED0000ull + (uint64_t)index * 0x100000001ull;
    (void)next64(&r);
    c->flags = 0;
    extreme = chance(&r, 0.7);
    if (extreme)
        c->flags |= ACC_EXTREME;
    make_normal(c, &r, &n);
    {
        double s = logu(&r, -2.0, 8.0); /* the point within +-256 */
        double x, y, z;
        v3 pr;
        x = range(&r, -s, s);
        y = range(&r, -s, s);
        z = range(&r, -s, s);
        pr = mk(x, y, z);
        c->point = quant3(pr);
        p = dequant3(c->point);
    }
    make_eye(c, &r, n, p, extreme, &e);
    make_parameters(c, &r, extreme);
    c->lighting.count = 1 + (int)(uni(&r) * 4.0);
    for (j = 0; j < STP_MAX_LIGHTS; j++) {
        if (j < c->lighting.count) {
            make_light(c, &r, j, n, p, e, extreme);
        } else {
            c->lighting.lights[j].position.x = c->lighting.lights[j].position.y = 0;
            c->lighting.lights[j].position.z = STP_FIX_ONE;
            c->lighting.lights[j].power = 0;
            c->lighting.lights[j].colour[0] = c->lighting.lights[j].colour[1] =
                c->lighting.lights[j].colour[2] = STP_FIX_ONE;
        }
    }
    if ((c->flags & ACC_POWER_ZERO) && extreme && chance(&r, 0.5)) {
        c->lighting.brightness = quant(logu(&r, 9.0, 13.3)); /* 512 .. 10 000 */
        if (chance(&r, 0.5))
            c->material.reflectivity = 0;
    }
    if (c->lighting.brightness >= 512 * STP_FIX_ONE)
        c->flags |= ACC_BIG_BRIGHT;
}

static uint32_t mix(uint32_t h, int32_t v)
{
    return (h ^ (uint32_t)v) * 16777619u;
}

uint32_t acc_case_digest(const acc_case *c)
{
    uint32_t h = 2166136261u;
    int j;
    h = mix(h, c->normal[0]);
    h = mix(h, c->normal[1]);
    h = mix(h, c->normal[2]);
    h = mix(mix(mix(h, c->point.x), c->point.y), c->point.z);
    h = mix(mix(mix(h, c->eye.x), c->eye.y), c->eye.z);
    h = mix(mix(mix(mix(h, c->parallel), c->parallel_dir.x), c->parallel_dir.y), c->parallel_dir.z);
    h = mix(mix(mix(mix(h, c->lighting.brightness), c->lighting.background), c->lighting.attenuation_c),
            c->lighting.count);
    for (j = 0; j < c->lighting.count; j++) {
        const stp_light *l = &c->lighting.lights[j];
        h = mix(mix(mix(mix(h, l->position.x), l->position.y), l->position.z), l->power);
    }
    h = mix(mix(mix(mix(h, c->material.reflectivity), c->material.refraction), c->material.gloss),
            c->material.specular);
    return h;
}
