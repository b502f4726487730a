/* SPDX-License-Identifier: MIT */
/*
 * stipple firmware for the lm3s6965evb: render the compiled scene in bands
 * onto the SSD0323 OLED, report instruction counts over semihosting, exit.
 *
 * RAM: the renderer object, the scene's display file (in the generated
 * source), and per band STP_FW_BAND_ROWS rows of MONO1 pixels plus their
 * Z-buffer rows; the picture itself lives only in the panel.
 *
 * Besides the frame it times the shading function alone (shade_bench): the
 * instructions per stp_shade_point call over a fixed set of the scene's own
 * polygons, its lights and materials.
 */
#include "lm3s6965_oled.h"
#include "stellaris.h"
#include "stp_panel.h"
#include "stp_scene_data.h"
#include "stipple/stipple.h"

#ifndef STP_FW_BAND_ROWS
#define STP_FW_BAND_ROWS 4
#endif

#define PANEL_W 128u
#define PANEL_H 64u
#define ROW_BYTES (PANEL_W / 8u)

/* The shading micro-benchmark: STP_FW_SHADE_INPUTS points taken from the
 * scene's polygons, each shaded STP_FW_SHADE_REPEAT times. */
#ifndef STP_FW_SHADE_INPUTS
#define STP_FW_SHADE_INPUTS 64u
#endif
#ifndef STP_FW_SHADE_REPEAT
#define STP_FW_SHADE_REPEAT 4u
#endif

/* The renderer object in static storage, sized by STP_RENDERER_BYTES (the
 * compile-time bound of stp_renderer_size()). */
static stp_renderer_storage renderer;

static uint8_t band[STP_FW_BAND_ROWS * ROW_BYTES];
#if STP_WITH_ZBUFFER
static uint16_t zbuf[STP_FW_BAND_ROWS * PANEL_W];
#endif
static uint8_t packed[PANEL_W / 2u];

static int panel_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                       size_t stride)
{
    (void)port;
    (void)y0; /* bands come top to bottom and the window was set for the frame */
    return stp_panel_send_mono_rows(&stp_panel_ssd0323, &stp_lm3s6965_oled_bus, pixels, stride,
                                    PANEL_W, rows, packed) == 0
               ? 0
               : -1;
}

static int discard_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                         size_t stride)
{
    (void)port;
    (void)y0;
    (void)rows;
    (void)pixels;
    (void)stride;
    return 0;
}

/* Hold the picture until the board's "up" key (PE0) changes level, then
 * return: a test harness takes its screendump first and then presses the
 * key (QMP send-key up), so the firmware's own exit status still ends QEMU.
 * A change rather than a level: QEMU's gamepad drives PE0 through an
 * inverter and the pin reads 0 until the first key event. */
static void wait_for_key(void)
{
    uint32_t first;
    STP_SYSCTL_RCGC2 |= 1u << 4;
    STP_GPIO_DIR(STP_GPIO_E) &= ~1u;
    STP_GPIO_DEN(STP_GPIO_E) |= 1u;
    first = STP_GPIO_DATA(STP_GPIO_E, 1u);
    stp_semihost_write("stipple: frame done; press up to finish\n");
    while (STP_GPIO_DATA(STP_GPIO_E, 1u) == first)
        ;
}

static void report(const char *what, uint64_t count)
{
    char num[12];
    stp_semihost_write("stipple: ");
    stp_semihost_write(what);
    stp_semihost_write(" ");
    stp_semihost_write(stp_utoa(count > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)count, num));
    stp_semihost_write("\n");
}

/* One stp_shade_point call's inputs, in world space (where the compiled
 * scene's vertices and lights are). */
typedef struct shade_input {
    const stp_material *material;
    stp_vec3 normal, point;
} shade_input;

static int64_t abs64(int64_t v)
{
    return v < 0 ? -v : v;
}

/* The unit normal of a polygon from its first three vertices (the core takes
 * Newell's normal in view space; for the timing a plane's normal is as good),
 * turned towards the viewer, and the mean of its vertices.  Returns 0 for a
 * polygon with no direction (collinear or repeated vertices). */
static int polygon_input(const stp_scene_data *s, const stp_scene_data_polygon *p,
                         const stp_vec3 *v, stp_vec3 towards_viewer_parallel, shade_input *in)
{
    int64_t a[3], b[3], c[3], sum[3] = {0, 0, 0}, big;
    stp_vec3 cross, to_eye;
    uint32_t i;
    int k;

    if (p->count < 3)
        return 0;
    a[0] = (int64_t)v[1].x - v[0].x;
    a[1] = (int64_t)v[1].y - v[0].y;
    a[2] = (int64_t)v[1].z - v[0].z;
    b[0] = (int64_t)v[2].x - v[0].x;
    b[1] = (int64_t)v[2].y - v[0].y;
    b[2] = (int64_t)v[2].z - v[0].z;
    /* edges below 2^30 so that the products and their sums fit 64 bits */
    big = 0;
    for (k = 0; k < 3; k++) {
        big |= abs64(a[k]);
        big |= abs64(b[k]);
    }
    while (big >= ((int64_t)1 << 30)) {
        for (k = 0; k < 3; k++) {
            a[k] /= 2;
            b[k] /= 2;
        }
        big /= 2;
    }
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
    /* only the direction counts: bring it into stp_fix's range */
    big = abs64(c[0]) | abs64(c[1]) | abs64(c[2]);
    while (big >= ((int64_t)1 << 30)) {
        for (k = 0; k < 3; k++)
            c[k] /= 2;
        big /= 2;
    }
    cross.x = (stp_fix)c[0];
    cross.y = (stp_fix)c[1];
    cross.z = (stp_fix)c[2];
    if (stp_vec3_unity(cross, &in->normal) == 0)
        return 0;

    for (i = 0; i < p->count; i++) {
        sum[0] += v[i].x;
        sum[1] += v[i].y;
        sum[2] += v[i].z;
    }
    in->point.x = (stp_fix)(sum[0] / (int64_t)p->count);
    in->point.y = (stp_fix)(sum[1] / (int64_t)p->count);
    in->point.z = (stp_fix)(sum[2] / (int64_t)p->count);
    in->material = &s->materials[p->material];

    /* the side the viewer sees, as the core shades it */
    if (s->view.projection == STP_PARALLEL) {
        to_eye = towards_viewer_parallel;
    } else {
        to_eye.x = stp_fix_sub(s->view.from.x, in->point.x);
        to_eye.y = stp_fix_sub(s->view.from.y, in->point.y);
        to_eye.z = stp_fix_sub(s->view.from.z, in->point.z);
    }
    if (stp_vec3_dot(in->normal, to_eye) < 0) {
        in->normal.x = -in->normal.x;
        in->normal.y = -in->normal.y;
        in->normal.z = -in->normal.z;
    }
    return 1;
}

static volatile uint32_t shade_sink;

/* Instructions per stp_shade_point call, counted with SysTick: the inputs are
 * STP_FW_SHADE_INPUTS polygons spread evenly over the scene's polygon list
 * (a scene with fewer polygons repeats them; one with no direction is
 * replaced by the next that has one), with the scene's lighting (its
 * world-space lights), the polygons' materials and the eye of its view; every
 * input is shaded STP_FW_SHADE_REPEAT times.  The count covers the calls and
 * the loop around them (argument passing included, as the host benchmark's
 * ns per shade does) and is rounded to whole instructions; a SysTick tick is
 * per_tick instructions, so the figure is within per_tick / calls of the
 * count.  *calls receives the number of calls timed (0: no usable polygon). */
static uint32_t shade_bench(const stp_scene_data *s, uint32_t per_tick, uint32_t *calls)
{
    shade_input in[STP_FW_SHADE_INPUTS];
    const stp_vec3 *v = s->vertices;
    stp_vec3 dir = {0, 0, 0}, back;
    uint32_t i = 0, k, rep, used = 0, acc = 0;
    int parallel = s->view.projection == STP_PARALLEL;
    uint64_t t0, t1, n;

    back.x = stp_fix_sub(s->view.from.x, s->view.at.x);
    back.y = stp_fix_sub(s->view.from.y, s->view.at.y);
    back.z = stp_fix_sub(s->view.from.z, s->view.at.z);
    if (stp_vec3_unity(back, &dir) == 0)
        dir.z = STP_FIX_ONE;
    *calls = 0;
    if (s->polygon_count == 0)
        return 0;
    for (k = 0; k < STP_FW_SHADE_INPUTS && i < s->polygon_count; k++) {
        uint32_t target = (uint32_t)(((uint64_t)k * s->polygon_count) / STP_FW_SHADE_INPUTS);
        while (i < target) {
            v += s->polygons[i].count;
            i++;
        }
        /* a polygon with no direction gives way to the next one */
        while (i < s->polygon_count && !polygon_input(s, &s->polygons[i], v, dir, &in[used])) {
            v += s->polygons[i].count;
            i++;
        }
        if (i < s->polygon_count)
            used++;
    }
    if (used == 0)
        return 0;

    t0 = stp_count_now();
    for (rep = 0; rep < STP_FW_SHADE_REPEAT; rep++)
        for (k = 0; k < used; k++)
            acc += (uint32_t)stp_shade_point(&s->lighting, in[k].material, in[k].normal,
                                             in[k].point, s->view.from, parallel, dir);
    t1 = stp_count_now();
    shade_sink = acc; /* the shades are used, whatever the compiler sees */

    n = (uint64_t)used * STP_FW_SHADE_REPEAT;
    *calls = (uint32_t)n;
    return (uint32_t)(((t1 - t0) * per_tick + n / 2u) / n);
}

static int fail(const char *what, int status)
{
    stp_semihost_write("stipple: ");
    stp_semihost_write(what);
    stp_semihost_write(": ");
    stp_semihost_write(stp_status_text(status));
    stp_semihost_write("\n");
    return 1;
}

int main(void)
{
    const stp_scene_data *scene = &stp_compiled_scene;
    stp_renderer *r;
    stp_port port;
    stp_output out;
    stp_frame_memory mem;
    uint64_t t0, t1, t2, t3, t4;
    uint32_t per_tick, per_shade, shade_calls;
    int status;

    stp_count_start();
    per_tick = stp_count_calibrate();
    if (scene->width != PANEL_W || scene->height != PANEL_H)
        return fail("scene size", STP_ERR_ARG);

    t0 = stp_count_now();
    status = stp_scene_data_enter(scene, &renderer, sizeof renderer, &r);
    t1 = stp_count_now();
    if (status != STP_OK)
        return fail("enter", status);

    stp_scene_data_output(scene, &out);
    mem.band = band;
    mem.band_size = sizeof band;
    mem.band_rows = STP_FW_BAND_ROWS;
#if STP_WITH_ZBUFFER
    mem.zbuf = zbuf;
    mem.zbuf_count = sizeof zbuf / sizeof zbuf[0];
#else
    mem.zbuf = 0;
    mem.zbuf_count = 0;
#endif
    mem.sort = scene->sort;
    mem.sort_count = scene->sort_count;

    port.width = PANEL_W;
    port.height = PANEL_H;
    port.format = STP_PIXEL_MONO1;
    port.user = 0;

    /* the frame through the core alone, the panel's transfer left out */
    port.flush = discard_flush;
    status = stp_renderer_render(r, &port, &out, &mem);
    t2 = stp_count_now();
    if (status != STP_OK)
        return fail("render", status);

    stp_lm3s6965_oled_setup();
    if (stp_panel_init(&stp_panel_ssd0323, &stp_lm3s6965_oled_bus) != 0 ||
        stp_panel_window_all(&stp_panel_ssd0323, &stp_lm3s6965_oled_bus) != 0)
        return fail("panel", STP_ERR_PORT);
    t3 = stp_count_now();
    port.flush = panel_flush;
    status = stp_renderer_render(r, &port, &out, &mem);
    if (status != STP_OK)
        return fail("render to panel", status);

    t4 = stp_count_now();
    per_shade = shade_bench(scene, per_tick, &shade_calls);
    report("instructions per SysTick tick:", per_tick);
    report("instructions to enter the scene:", (t1 - t0) * per_tick);
    report("instructions per frame (core):", (t2 - t1) * per_tick);
    report("instructions per frame (core + panel):", (t4 - t3) * per_tick);
    report("instructions per shade:", per_shade);
    report("shade calls timed:", shade_calls);
    report("band rows:", STP_FW_BAND_ROWS);
    report("renderer bytes:", stp_renderer_size());
    report("display-file entries:", stp_renderer_display_file_used(r));
    wait_for_key();
    return 0;
}
