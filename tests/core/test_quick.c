/* SPDX-License-Identifier: MIT */
/*
 * The short path to a first picture (issue 12, item 4): defaults for the
 * output and the frame memory (stp_output_default, stp_frame_memory_split),
 * implicit segments, shading on once a light is set, the alignment check of
 * stp_renderer_create / stp_rt_create, and every renderer setter returning a
 * status and refusing bad arguments without changing anything.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "stipple/stipple.h"

#define W 32
#define H 24
#define ONE STP_FIX_ONE

typedef struct grab {
    stp_port port;
    uint8_t pixels[W * H];
    uint32_t flushes;
} grab;

static int grab_rows(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *px, size_t stride)
{
    grab *g = (grab *)port->user;
    uint32_t y;
    for (y = 0; y < rows; y++)
        memcpy(&g->pixels[(y0 + y) * W], px + y * stride, W);
    g->flushes++;
    return 0;
}

static void grab_init(grab *g)
{
    memset(g, 0, sizeof *g);
    g->port.width = W;
    g->port.height = H;
    g->port.format = STP_PIXEL_GREY8;
    g->port.flush = grab_rows;
    g->port.user = g;
}

static stp_vec3 v3(stp_fix x, stp_fix y, stp_fix z)
{
    stp_vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

/* Two overlapping squares at depths 1/2 and 0, seen from the default view
 * (eye (0,0,-1), 90 degrees: 12 pixels per unit of x/z at H = 24): the far
 * one reaches 8 pixels from the centre, the near one 3. */
static const stp_vec3 far_square[4] = {{-ONE, -ONE, ONE / 2},
                                       {ONE, -ONE, ONE / 2},
                                       {ONE, ONE, ONE / 2},
                                       {-ONE, ONE, ONE / 2}};
static const stp_vec3 near_square[4] = {{-ONE / 4, -ONE / 4, 0},
                                        {ONE / 4, -ONE / 4, 0},
                                        {ONE / 4, ONE / 4, 0},
                                        {-ONE / 4, ONE / 4, 0}};

/* The five calls: create, light, two polygons, split, render. */
static void test_first_picture_in_five_calls(void **state)
{
    static stp_renderer_storage storage;
    static stp_instr display_file[32];
    static uint16_t frame_memory[300]; /* 600 bytes: 600 / (32 + 64) = 6 rows */
    static grab quick, full;
    static uint8_t band[W * H];
    static uint16_t zbuf[W * H];
    stp_frame_memory memory, whole = {band, sizeof band, H, zbuf, W * H, NULL, 0, NULL, 0};
    stp_output output;
    stp_renderer *r;
    (void)state;
    grab_init(&quick);
    r = stp_renderer_create(&storage, sizeof storage, display_file, 32, W, H);
    assert_non_null(r);
    assert_int_equal(stp_renderer_set_light(r, v3(0, ONE, -2 * ONE), ONE, ONE / 5), STP_OK);
    assert_int_equal(stp_renderer_polygon(r, far_square, 4), STP_OK);
    assert_int_equal(stp_renderer_polygon(r, near_square, 4), STP_OK);
    assert_int_equal(stp_frame_memory_split(&memory, r, &quick.port, NULL, frame_memory,
                                            sizeof frame_memory),
                     STP_OK);
    assert_int_equal(memory.band_rows, 6);
    assert_int_equal(stp_renderer_render(r, &quick.port, NULL, &memory), STP_OK);
    assert_int_equal(quick.flushes, 4); /* 24 rows in bands of 6 */

    /* the same display file through the explicit path: one band, output
     * spelled out, the Z buffer */
    grab_init(&full);
    memset(&output, 0, sizeof output);
    output.hidden = STP_HIDDEN_ZBUFFER;
    assert_int_equal(stp_renderer_render(r, &full.port, &output, &whole), STP_OK);
    assert_memory_equal(quick.pixels, full.pixels, sizeof quick.pixels);

    /* and the picture is a lit picture: background in the corner, the near
     * square in front of the far one, both shaded (not the flat fill style,
     * which would be 255) */
    assert_int_equal(quick.pixels[0], 0);
    assert_true(quick.pixels[(H / 2) * W + W / 2] > 0);
    assert_true(quick.pixels[(H / 2) * W + W / 2] < 255);
    assert_true(quick.pixels[(H / 2 - 6) * W + W / 2 - 6] > 0);
    assert_true(quick.pixels[(H / 2 - 6) * W + W / 2 - 6] < 255);
    assert_int_equal(quick.pixels[(H / 2 - 9) * W + W / 2 - 9], 0);
}

static void test_output_default(void **state)
{
    stp_output o;
    (void)state;
    memset(&o, 0xA5, sizeof o);
    assert_int_equal(stp_output_default(&o), STP_OK);
    assert_int_equal(o.hidden, STP_WITH_ZBUFFER ? STP_HIDDEN_ZBUFFER : STP_HIDDEN_PAINTER);
    assert_null(o.cell);
    assert_null(o.gamma);
    assert_null(o.styles);
    assert_null(o.background_colour);
    assert_int_equal(o.background, 0);
    assert_int_equal(stp_output_default(NULL), STP_ERR_ARG);
}

static void test_frame_memory_split(void **state)
{
    static stp_renderer_storage storage;
    static stp_instr display_file[32];
    static uint32_t buffer[1024];
    uint8_t *bytes = (uint8_t *)buffer;
    stp_port port = {W, H, STP_PIXEL_MONO1, NULL, NULL};
    stp_output painter;
    stp_frame_memory m;
    stp_renderer *r;
    size_t need;
    (void)state;
    r = stp_renderer_create(&storage, sizeof storage, display_file, 32, W, H);
    assert_non_null(r);
    assert_int_equal(stp_renderer_polygon(r, far_square, 4), STP_OK);
    assert_int_equal(stp_renderer_polygon(r, near_square, 4), STP_OK);

    /* Z buffer, MONO1: 4 + 64 bytes a row; a misaligned start is rounded up */
    assert_int_equal(stp_frame_memory_split(&m, r, &port, NULL, bytes + 1, 3 + 68 * 5 + 67), STP_OK);
    assert_int_equal(m.band_rows, 5);
    assert_ptr_equal(m.zbuf, (void *)(bytes + 4));
    assert_int_equal(m.zbuf_count, W * 5);
    assert_ptr_equal(m.band, bytes + 4 + 2 * W * 5);
    assert_int_equal(m.band_size, 4 * 5);
    assert_null(m.sort);
    /* never more rows than the port has */
    assert_int_equal(stp_frame_memory_split(&m, r, &port, NULL, buffer, sizeof buffer), STP_OK);
    assert_int_equal(m.band_rows, H);
    /* too small for one row */
    assert_int_equal(stp_frame_memory_split(&m, r, &port, NULL, buffer, 67), STP_ERR_MEMORY);
    assert_null(m.band);

    /* the painter's sort array comes first, one entry per polygon */
    stp_output_default(&painter);
    painter.hidden = STP_HIDDEN_PAINTER;
    need = stp_frame_memory_bytes(&port, STP_HIDDEN_PAINTER, 3, stp_renderer_polygon_count(r));
    assert_int_equal(need, 2 * sizeof(stp_sort_entry) + 3 * 4 + 3);
    assert_int_equal(stp_frame_memory_split(&m, r, &port, &painter, bytes + 1, need), STP_OK);
    assert_int_equal(m.band_rows, 3);
    assert_int_equal(m.sort_count, 2);
    assert_ptr_equal(m.sort, (void *)(bytes + 4));
    assert_null(m.zbuf);
    assert_int_equal(stp_frame_memory_split(&m, r, &port, &painter, bytes + 1, need - 1), STP_OK);
    assert_int_equal(m.band_rows, 2);
    assert_int_equal(stp_frame_memory_split(&m, NULL, &port, &painter, buffer, sizeof buffer),
                     STP_ERR_ARG);
    /* stp_frame_memory_bytes and the split agree for every row count */
    {
        uint32_t rows;
        for (rows = 1; rows <= H; rows++) {
            need = stp_frame_memory_bytes(&port, STP_HIDDEN_ZBUFFER, rows, 0);
            assert_int_equal(stp_frame_memory_split(&m, r, &port, NULL, bytes + 3, need), STP_OK);
            assert_int_equal(m.band_rows, rows);
        }
    }
    port.format = (stp_pixel_format)9;
    assert_int_equal(stp_frame_memory_split(&m, r, &port, NULL, buffer, sizeof buffer), STP_ERR_ARG);
    assert_int_equal(stp_frame_memory_bytes(&port, STP_HIDDEN_ZBUFFER, 1, 0), 0);
    assert_int_equal(stp_frame_memory_split(NULL, r, &port, NULL, buffer, sizeof buffer), STP_ERR_ARG);
}

static void test_alignment_checked(void **state)
{
    static stp_renderer_storage storage[2];
    static stp_instr display_file[8];
    static stp_raytracer_storage rt_storage[2];
    stp_rt_memory m;
    (void)state;
    memset(&m, 0, sizeof m);
    assert_null(stp_renderer_create((uint8_t *)&storage[0] + 1, sizeof storage[0], display_file, 4, 8, 8));
    assert_null(stp_renderer_create((uint8_t *)&storage[0] + 4, sizeof storage[0], display_file, 4, 8, 8));
    assert_null(stp_renderer_create(&storage[0], sizeof storage[0],
                                    (stp_instr *)(void *)((uint8_t *)display_file + 2), 4, 8, 8));
    assert_non_null(stp_renderer_create(&storage[1], sizeof storage[1], display_file, 4, 8, 8));
#if STP_WITH_RAYTRACE
    assert_null(stp_rt_create((uint8_t *)&rt_storage[0] + 4, sizeof rt_storage[0], &m, 8, 8));
    assert_non_null(stp_rt_create(&rt_storage[1], sizeof rt_storage[1], &m, 8, 8));
#else
    (void)rt_storage;
#endif
}

/* Shading is off at creation (the fill style, the lightest) and on once a
 * light is set; stp_renderer_set_shading(r, 0) still turns it off. */
static void test_shading_on_with_light(void **state)
{
    static stp_renderer_storage storage;
    static stp_instr display_file[64];
    stp_renderer *r;
    stp_lighting l;
    (void)state;
    r = stp_renderer_create(&storage, sizeof storage, display_file, 64, W, H);
    assert_non_null(r);
    assert_int_equal(stp_renderer_polygon(r, far_square, 4), STP_OK);
    assert_int_equal(stp_renderer_last_shade(r), ONE); /* style 16 of 16 */
    assert_int_equal(stp_renderer_set_light(r, v3(ONE, ONE, -2 * ONE), ONE, ONE / 5), STP_OK);
    assert_int_equal(stp_renderer_polygon(r, far_square, 4), STP_OK);
    assert_true(stp_renderer_last_shade(r) > 0 && stp_renderer_last_shade(r) < ONE);
    assert_int_equal(stp_renderer_set_shading(r, 0), STP_OK);
    assert_int_equal(stp_renderer_polygon(r, far_square, 4), STP_OK);
    assert_int_equal(stp_renderer_last_shade(r), ONE);
    stp_lighting_default(&l);
    assert_int_equal(stp_renderer_set_lighting(r, &l), STP_OK);
    assert_int_equal(stp_renderer_polygon(r, far_square, 4), STP_OK);
    assert_true(stp_renderer_last_shade(r) < ONE);
}

/* Implicit segments: -1 opened by the first polygon, ended by a change of
 * lighting (so the next polygons get the new light), -2 opened next; a
 * created segment ends one too. */
static void test_implicit_segments(void **state)
{
    static stp_renderer_storage storage;
    static stp_instr display_file[64];
    stp_renderer *r;
    stp_fix first, second;
    uint32_t used;
    (void)state;
    r = stp_renderer_create(&storage, sizeof storage, display_file, 64, W, H);
    assert_non_null(r);
    assert_int_equal(stp_renderer_set_light(r, v3(ONE, 0, -2 * ONE), ONE, ONE / 5), STP_OK);
    assert_int_equal(stp_renderer_polygon(r, far_square, 4), STP_OK);
    first = stp_renderer_last_shade(r);
    assert_int_equal(stp_segment_delete(r, -1), STP_ERR_SEGMENT); /* still open */
    /* a light behind the square: the next implicit segment copies it */
    assert_int_equal(stp_renderer_set_light(r, v3(0, 0, 4 * ONE), ONE, ONE / 5), STP_OK);
    assert_int_equal(stp_renderer_polygon(r, far_square, 4), STP_OK);
    second = stp_renderer_last_shade(r);
    assert_true(second < first);
    assert_int_equal(stp_renderer_polygon_count(r), 2);
    assert_int_equal(stp_segment_create(r, 7), STP_OK); /* ends -2 */
    assert_int_equal(stp_renderer_polygon(r, near_square, 4), STP_OK);
    assert_int_equal(stp_segment_close(r), STP_OK);
    assert_int_equal(stp_renderer_polygon_count(r), 3);
    used = stp_renderer_display_file_used(r);
    assert_int_equal(stp_segment_visibility(r, -2, 0), STP_OK);
    assert_int_equal(stp_renderer_polygon_count(r), 2);
    assert_int_equal(stp_segment_delete(r, -1), STP_OK);
    assert_true(stp_renderer_display_file_used(r) < used);
    assert_int_equal(stp_renderer_polygon_count(r), 1);
    /* a failed stp_segment_create does not end the implicit segment */
    assert_int_equal(stp_renderer_polygon(r, near_square, 4), STP_OK); /* opens -1 again */
    assert_int_equal(stp_segment_create(r, 7), STP_ERR_SEGMENT);
    assert_int_equal(stp_segment_delete(r, -1), STP_ERR_SEGMENT); /* open */
}

/* Every setter: STP_ERR_ARG for a NULL renderer and out-of-range values,
 * leaving the renderer byte for byte as it was. */
static void test_setters_check_arguments(void **state)
{
    static stp_renderer_storage storage, before;
    static stp_instr display_file[8];
    stp_renderer *r;
    stp_material m;
    stp_vec3 p = v3(0, 0, -ONE);
    (void)state;
    r = stp_renderer_create(&storage, sizeof storage, display_file, 8, W, H);
    assert_non_null(r);
    stp_material_default(&m);
    before = storage;
#define UNCHANGED() assert_memory_equal(&before, &storage, stp_renderer_size())
    assert_int_equal(stp_renderer_set_light(NULL, p, ONE, 0), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_light(r, p, -1, 0), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_light(r, p, ONE, -1), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_light(r, p, ONE, ONE + 1), STP_ERR_ARG);
    UNCHANGED();
    assert_int_equal(stp_renderer_set_object_shade(NULL, &m), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_object_shade(r, NULL), STP_ERR_ARG);
    m.reflectivity = ONE + 1;
    assert_int_equal(stp_renderer_set_object_shade(r, &m), STP_ERR_ARG);
    stp_material_default(&m);
    m.refraction = -1;
    assert_int_equal(stp_renderer_set_object_shade(r, &m), STP_ERR_ARG);
    stp_material_default(&m);
    m.gloss = -1;
    assert_int_equal(stp_renderer_set_object_shade(r, &m), STP_ERR_ARG);
    stp_material_default(&m);
    m.specular = -1;
    assert_int_equal(stp_renderer_set_object_shade(r, &m), STP_ERR_ARG);
    stp_material_default(&m);
    m.colour[2] = ONE + 1;
    assert_int_equal(stp_renderer_set_object_shade(r, &m), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_shading(NULL, 1), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_fill_style(NULL, 1), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_fill_style(r, 0), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_fill_style(r, 17), STP_ERR_ARG); /* 16 levels */
    assert_int_equal(stp_renderer_set_backface_removal(NULL, 1), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_levels(NULL, 16), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_colour(NULL, 1), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_view(NULL, NULL), STP_ERR_ARG);
    assert_int_equal(stp_renderer_set_lighting(r, NULL), STP_ERR_ARG);
    UNCHANGED();
    /* and in range they take */
    stp_material_default(&m);
    assert_int_equal(stp_renderer_set_object_shade(r, &m), STP_OK);
    assert_int_equal(stp_renderer_set_fill_style(r, 16), STP_OK);
    assert_int_equal(stp_renderer_set_fill_style(r, 1), STP_OK);
    assert_int_equal(stp_renderer_set_backface_removal(r, 1), STP_OK);
    assert_int_equal(stp_renderer_set_shading(r, 1), STP_OK);
    assert_int_equal(stp_renderer_set_light(r, p, 0, ONE), STP_OK);
#undef UNCHANGED
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_first_picture_in_five_calls),
        cmocka_unit_test(test_output_default),
        cmocka_unit_test(test_frame_memory_split),
        cmocka_unit_test(test_alignment_checked),
        cmocka_unit_test(test_shading_on_with_light),
        cmocka_unit_test(test_implicit_segments),
        cmocka_unit_test(test_setters_check_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
