/* SPDX-License-Identifier: MIT */
/* Cortex-M bench firmware for QEMU's mps2-an385: renders the torus frame
 * (torus_frame.h) at 128x64 into a 1-bit frame, reports the instructions
 * one frame takes (entering the 1000 triangles plus stp_renderer_render, as the host
 * bench times) and prints the frame in hex over semihosting for the host to
 * compare with its own render, then exits through semihosting.
 *
 * Counting: SysTick on the processor clock under QEMU -icount shift=0,
 * where the clock advances a fixed number of instructions per tick
 * (stp_count_calibrate measures it: 40 on this board's 25 MHz clock), so
 * the figure is emulated instructions, the same on every run, to within
 * one tick.  The second frame is measured (the first one has no segment to
 * delete, every later one does, as in an animation).  With bands of fewer
 * rows than the frame (STP_FW_BAND_ROWS) the renderer is lent a setup
 * array, so each polygon's depth setup is made once per frame. */
#include "stellaris.h"
#include "torus_frame.h"

#define WIDTH 128u
#define HEIGHT 64u
#define STRIDE (WIDTH / 8u)
#ifndef STP_FW_MESH
#define STP_FW_MESH 0 /* 1: stp_renderer_mesh instead of stp_renderer_polygon */
#endif
#ifndef STP_FW_BAND_ROWS
#define STP_FW_BAND_ROWS HEIGHT
#endif

static stp_renderer_storage storage;
static stp_instr display_file[TORUS_DF_CAPACITY];
#if STP_FW_MESH
/* the torus as one indexed mesh, entered by stp_renderer_mesh */
static stp_mesh mesh;
static stp_vec3 vertices[TORUS_MESH_VERTICES];
static uint16_t triangles[3 * TORUS_TRIANGLES];
static int16_t normals[3 * TORUS_TRIANGLES];
static stp_mesh_bounds bounds;
static stp_mesh_vertex scratch[TORUS_MESH_VERTICES];
#define TORUS_ENTER(r) torus_enter_mesh(r, &mesh, scratch)
#else
static stp_vec3 vertices[3 * TORUS_TRIANGLES];
#define TORUS_ENTER(r) torus_enter(r, vertices)
#endif
/* the band and the picture as words (STRIDE is a multiple of 4): keep_band
 * copies a word at a time; the renderer writes the band's bytes, which
 * may alias any object */
static uint32_t band[STRIDE * STP_FW_BAND_ROWS / 4u];
static uint16_t zbuf[WIDTH * STP_FW_BAND_ROWS];
static uint32_t picture[STRIDE * HEIGHT / 4u];
#ifndef STP_FW_KEEP_SETUP
#define STP_FW_KEEP_SETUP (STP_FW_BAND_ROWS < HEIGHT)
#endif
#if STP_FW_KEEP_SETUP
/* several bands: each polygon's depth setup made once per frame */
static stp_polygon_setup setup[TORUS_TRIANGLES];
#endif

/* pixels is band: read as the words it is, a row's four a step */
static int keep_band(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels, size_t stride)
{
    const uint32_t *from = (const uint32_t *)(const void *)pixels;
    uint32_t i, *to = &picture[y0 * STRIDE / 4u];
    (void)port;
    (void)stride; /* STRIDE */
    for (i = 0; i < 4u * rows; i += 4u) {
        to[i] = from[i];
        to[i + 1u] = from[i + 1u];
        to[i + 2u] = from[i + 2u];
        to[i + 3u] = from[i + 3u];
    }
    return 0;
}

static void report(const char *what, uint32_t value)
{
    char num[12];
    stp_semihost_write("stipple: ");
    stp_semihost_write(what);
    stp_semihost_write(" ");
    stp_semihost_write(stp_utoa(value, num));
    stp_semihost_write("\n");
}

/* "stipple: row Y HEX" per picture row */
static void dump_picture(void)
{
    static const char digits[] = "0123456789abcdef";
    char line[2 * STRIDE + 2];
    const uint8_t *bytes = (const uint8_t *)picture;
    uint32_t y, i;
    for (y = 0; y < HEIGHT; y++) {
        for (i = 0; i < STRIDE; i++) {
            line[2 * i] = digits[bytes[y * STRIDE + i] >> 4];
            line[2 * i + 1] = digits[bytes[y * STRIDE + i] & 15u];
        }
        line[2 * STRIDE] = '\n';
        line[2 * STRIDE + 1] = '\0';
        report("row", y);
        stp_semihost_write(line);
    }
}

int main(void)
{
    stp_renderer *r;
    stp_port port;
    stp_frame_memory mem;
    uint32_t per_tick;
    uint64_t t0, t1, t2;
    int status;
    stp_count_start();
    per_tick = stp_count_calibrate();
    r = stp_renderer_create(&storage, sizeof storage, display_file, TORUS_DF_CAPACITY, WIDTH, HEIGHT);
    if (!r || per_tick == 0) {
        stp_semihost_write("stipple: setup failed\n");
        return 1;
    }
#if STP_FW_MESH
    if (torus_mesh_build(&mesh, vertices, triangles, normals, &bounds) != STP_OK) {
        stp_semihost_write("stipple: mesh normals failed\n");
        return 1;
    }
#else
    torus_build(vertices);
#endif
    port.width = WIDTH;
    port.height = HEIGHT;
    port.format = STP_PIXEL_MONO1;
    port.flush = keep_band;
    port.user = 0;
    mem.band = (uint8_t *)band;
    mem.band_size = sizeof band;
    mem.band_rows = STP_FW_BAND_ROWS;
    mem.zbuf = zbuf;
    mem.zbuf_count = sizeof zbuf / sizeof zbuf[0];
    mem.sort = 0;
    mem.sort_count = 0;
#if STP_FW_KEEP_SETUP
    mem.setup = setup;
    mem.setup_count = TORUS_TRIANGLES;
#else
    mem.setup = 0;
    mem.setup_count = 0;
#endif
    status = torus_setup(r);
    if (status == STP_OK)
        status = TORUS_ENTER(r);
    if (status == STP_OK)
        status = torus_render(r, &port, &mem);
    t0 = stp_count_now();
    if (status == STP_OK)
        status = TORUS_ENTER(r);
    t1 = stp_count_now();
    if (status == STP_OK)
        status = torus_render(r, &port, &mem);
    t2 = stp_count_now();
    if (status != STP_OK) {
        stp_semihost_write("stipple: ");
        stp_semihost_write(stp_status_text(status));
        stp_semihost_write("\n");
        return 1;
    }
    report("instructions per tick", per_tick);
    report("band rows", STP_FW_BAND_ROWS);
    report("entered as one mesh", STP_FW_MESH);
    report("setups kept across bands", STP_FW_KEEP_SETUP);
    report("instructions to enter the torus", (uint32_t)((t1 - t0) * per_tick));
    report("instructions to render it", (uint32_t)((t2 - t1) * per_tick));
    report("instructions per torus frame", (uint32_t)((t2 - t0) * per_tick));
    dump_picture();
    return 0;
}
