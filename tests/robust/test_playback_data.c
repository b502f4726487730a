/* SPDX-License-Identifier: MIT */
/*
 * The display-file player (stipple/playback.h) fed a display file whole,
 * cut short at every entry, and with one field of one entry corrupted at
 * a time: a file that is not one the entry side makes is refused
 * (stp_playback_create returns NULL, stp_playback_check STP_ERR_ARG with
 * the first bad entry), never read past its end (each copy lives in a heap
 * block of exactly its size, so under AddressSanitizer a read past `used`
 * fails the test), and a file cut between records plays like the same
 * records entered alone.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "stipple/playback.h"
#include "stipple/stipple.h"

#define W 32
#define H 24
/* the guard band of compact builds (src/project_private.h): 512 pixels */
#if STP_DIRECT_COMPACT
#define GUARD_Q4 (512 << STP_SUBPIXEL_BITS)
#else
#define GUARD_Q4 0
#endif
#define LEVELS 16
#define ONE STP_FIX_ONE

static stp_vec3 v3(double x, double y, double z)
{
    stp_vec3 p;
    p.x = (stp_fix)(x * ONE);
    p.y = (stp_fix)(y * ONE);
    p.z = (stp_fix)(z * ONE);
    return p;
}

/* A display file entered through the API: flat and smooth polygons of 3
 * and 5 vertices, a transparent one and a line; *used gets its length. */
static stp_instr *entered(uint32_t *used)
{
    static stp_instr df[256];
    void *mem = malloc(stp_renderer_size());
    stp_renderer *r = stp_renderer_create(mem, stp_renderer_size(), df, 256, W, H);
    stp_view view;
    stp_lighting light;
    stp_vec3 tri[3], pent[5], normals[5];
    int i;
    assert_non_null(r);
    memset(&view, 0, sizeof view);
    view.from = v3(0, 0, -6);
    view.up = v3(0, 1, 0);
    view.fov_degrees = 45 * ONE;
    view.hither = ONE / 4;
    view.projection = STP_PERSPECTIVE;
    assert_int_equal(stp_renderer_set_view(r, &view), STP_OK);
    stp_lighting_default(&light);
    light.lights[0].position = v3(-3, 4, -6);
    assert_int_equal(stp_renderer_set_lighting(r, &light), STP_OK);
    assert_int_equal(stp_renderer_set_levels(r, LEVELS), STP_OK);
    tri[0] = v3(-2, -1.5, 0);
    tri[1] = v3(2, -1.5, 1);
    tri[2] = v3(0, 1.5, 0.5);
    assert_int_equal(stp_renderer_polygon(r, tri, 3), STP_OK);
    for (i = 0; i < 5; i++) {
        pent[i] = v3(1.2 * (i % 3) - 1.5, 1.0 * (i / 2) - 1, -1);
        normals[i] = v3(0.1 * i, 0.2, -1);
    }
    pent[0] = v3(-1.5, -1, -1);
    pent[1] = v3(0.5, -1.2, -1);
    pent[2] = v3(1.5, 0, -1);
    pent[3] = v3(0.2, 1.4, -1);
    pent[4] = v3(-1.4, 0.8, -1);
    assert_int_equal(stp_renderer_polygon_smooth(r, pent, normals, 5), STP_OK);
    assert_int_equal(stp_renderer_set_transparency(r, ONE / 2, ONE / 2, 1, 0, 0), STP_OK);
    tri[2] = v3(0, 2.5, -2);
    assert_int_equal(stp_renderer_polygon(r, tri, 3), STP_OK);
    assert_int_equal(stp_renderer_move(r, v3(-2, 2, 0)), STP_OK);
    assert_int_equal(stp_renderer_line(r, v3(2, -2, 0)), STP_OK);
    *used = stp_renderer_display_file_used(r);
    free(mem);
    return df;
}

static int keep(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    uint8_t *frame = (uint8_t *)port->user;
    uint32_t y;
    for (y = 0; y < rows; y++)
        memcpy(frame + (size_t)(y0 + y) * W, pixels + (size_t)y * stride, W);
    return 0;
}

/* Play df[0, used) from an exact-size heap copy: 1 with the GREY8 picture
 * (Z buffer) in frame when accepted, 0 when refused (then *bad gets the
 * check's bad entry). */
static int play(const stp_instr *df, uint32_t used, uint8_t *frame, uint32_t *bad)
{
    stp_instr *copy = malloc(used * sizeof *copy);
    void *mem = malloc(stp_renderer_size());
    uint8_t band[W * 4];
    uint16_t zbuf[W * 4];
    stp_sort_entry sort[64];
    stp_frame_memory fm;
    stp_output out;
    stp_port port;
    stp_renderer *r;
    int check;
    memcpy(copy, df, used * sizeof *copy);
    *bad = UINT32_MAX;
    check = stp_playback_check(copy, used, W, H, bad);
    r = stp_playback_create(mem, stp_renderer_size(), copy, used, W, H, LEVELS, 1);
    assert_int_equal(r != NULL, check == STP_OK);
    if (r) {
        int hidden;
        for (hidden = STP_HIDDEN_NONE; hidden <= STP_HIDDEN_ZBUFFER; hidden++) {
            memset(&fm, 0, sizeof fm);
            fm.band = band;
            fm.band_size = sizeof band;
            fm.band_rows = 4;
            fm.zbuf = zbuf;
            fm.zbuf_count = W * 4;
            fm.sort = sort;
            fm.sort_count = 64;
            assert_int_equal(stp_output_default(&out), STP_OK);
            out.hidden = (stp_hidden)hidden;
            port.width = W;
            port.height = H;
            port.format = STP_PIXEL_GREY8;
            port.flush = keep;
            port.user = frame;
            assert_int_equal(stp_renderer_render(r, &port, &out, &fm), STP_OK);
        }
    } else {
        assert_int_equal(check, STP_ERR_ARG);
    }
    free(mem);
    free(copy);
    return r != NULL;
}

/* The header of the polygon that entry k belongs to, or k. */
static uint32_t record_of(const stp_instr *df, uint32_t used, uint32_t k)
{
    uint32_t i;
    for (i = 0; i < used; i++) {
        if (df[i].op >= 3) {
            if (k < i + (uint32_t)df[i].op)
                return k >= i ? i : k;
            i += (uint32_t)df[i].op - 1;
        } else if (i == k) {
            return k;
        }
    }
    return k;
}

static void test_whole_and_cut_short(void **state)
{
    uint32_t used, cut, bad;
    const stp_instr *df = entered(&used);
    uint8_t frame[W * H];
    (void)state;
    assert_true(used >= 12);
    assert_int_equal(play(df, used, frame, &bad), 1);
    for (cut = 1; cut < used; cut++) {
        uint32_t record = record_of(df, used, cut);
        int inside = record < cut; /* the cut falls inside a polygon */
        int accepted = play(df, cut, frame, &bad);
        if (accepted == inside)
            fail_msg("file cut to %u entries (polygon at %u): %s", cut, record,
                     accepted ? "accepted" : "refused");
        if (!accepted)
            assert_int_equal(bad, record);
    }
}

/* One field of entry k made what the entry side never writes. */
typedef struct corruption {
    const char *what;
    int field; /* 0 op, 1 x, 2 y, 3 z, 4 shade */
    int32_t value;
} corruption;

static void test_corrupted(void **state)
{
    static const corruption bad_values[] = {
        {"unknown opcode", 0, -9},
        {"polygon past the end", 0, 1000},
        {"polygon above the vertex limit", 0, STP_MAX_POLYGON_VERTICES + 1},
        /* beyond the device and, in compact builds, its guard band
         * (polygon points up to 512 pixels beyond: test_guard_band) */
        {"x below the device", 1, -GUARD_Q4 - 1},
        {"x past the device", 1, ((W << STP_SUBPIXEL_BITS) + GUARD_Q4) + 1},
        {"x huge", 1, INT32_MAX},
        {"y past the device", 2, ((H << STP_SUBPIXEL_BITS) + GUARD_Q4) + 1},
        {"y huge negative", 2, INT32_MIN},
        {"depth key out of range", 3, INT32_MIN},
#if STP_WITH_GOURAUD
        {"shade out of range", 4, -7},
#endif
    };
    uint32_t used, k, bad;
    const stp_instr *df = entered(&used);
    stp_instr *copy = malloc(used * sizeof *copy);
    uint8_t frame[W * H];
    size_t c;
    (void)state;
    for (k = 0; k < used; k++)
        for (c = 0; c < sizeof bad_values / sizeof bad_values[0]; c++) {
            const corruption *bv = &bad_values[c];
            int32_t *field;
            uint32_t record = record_of(df, used, k);
            memcpy(copy, df, used * sizeof *copy);
            switch (bv->field) {
            case 0: field = &copy[k].op; break;
            case 1: field = &copy[k].x; break;
            case 2: field = &copy[k].y; break;
            case 3: field = &copy[k].z; break;
#if STP_WITH_GOURAUD
            default: field = &copy[k].shade; break;
#else
            default: continue;
#endif
            }
            /* fields an entry does not read stay free */
            if (bv->field >= 1 && bv->field <= 3 && copy[k].op <= 0 && copy[k].op != STP_OP_LINE &&
                !(record < k))
                continue;
            if (bv->field == 4 && copy[record].op < 3)
                continue;
            /* op of a vertex that is no LINE: its polygon is refused */
            *field = bv->value;
            if (play(copy, used, frame, &bad))
                fail_msg("entry %u (op %d) with %s: accepted", k, df[k].op, bv->what);
            assert_int_equal(bad, record);
        }
    /* styles and transparency of the non-polygon entries */
    for (k = 0; k < used; k++) {
        memcpy(copy, df, used * sizeof *copy);
        if (copy[k].op == STP_OP_SHADE)
            copy[k].x = 0;
        else if (copy[k].op == STP_OP_TRANSPARENCY)
            copy[k].x = 2 * ONE;
        else
            continue;
        assert_int_equal(play(copy, used, frame, &bad), 0);
        assert_int_equal(bad, k);
    }
    free(copy);
}

/* A point a pixel left of the picture: in a polygon accepted with the
 * guard band of compact builds (the raster clamps it), refused without;
 * in a line refused in every build (lines are clipped to the picture) */
static void test_guard_band(void **state)
{
    uint32_t used, k, bad;
    const stp_instr *df = entered(&used);
    stp_instr *copy = malloc(used * sizeof *copy);
    uint8_t frame[W * H];
    int polygons = 0, lines = 0;
    (void)state;
    for (k = 0; k < used; k++) {
        uint32_t record = record_of(df, used, k);
        int in_polygon = record < k || df[k].op >= 3, in_line = df[k].op == STP_OP_MOVE || (df[k].op == STP_OP_LINE && !in_polygon);
        if (!in_polygon && !in_line)
            continue;
        memcpy(copy, df, used * sizeof *copy);
        copy[k].x = -16;
        if (in_polygon && GUARD_Q4 != 0) {
            assert_int_equal(play(copy, used, frame, &bad), 1);
            polygons++;
        } else {
            assert_int_equal(play(copy, used, frame, &bad), 0);
            assert_int_equal(bad, record);
            lines += in_line;
            polygons += in_polygon;
        }
    }
    assert_true(polygons >= 8 && lines >= 2);
    free(copy);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_whole_and_cut_short),
        cmocka_unit_test(test_corrupted),
        cmocka_unit_test(test_guard_band),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
