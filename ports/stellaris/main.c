/* SPDX-License-Identifier: MIT */
/*
 * stipple firmware, board-independent: render the compiled scene in bands
 * onto the board's panel (board.h, board_<name>.c), hold the picture, exit.
 *
 * RAM: the renderer object (STP_RENDERER_BYTES of the configuration), the
 * scene's display file (in the generated source, with the error rows of a
 * scene compiled with error diffusion), STP_FW_BAND_ROWS rows of 1-bit
 * pixels (8-bit pixels with diffusion) and their Z-buffer rows; the picture
 * lives only in the panel.
 *
 * The band's pixel format is the board's (board.h): MONO1 rows, or with
 * STP_FW_PAGES 1 (a page panel: the lm3s811evb's SSD0303) the panel's own
 * 8-row pages, STP_PIXEL_MONO1_PAGES, which the renderer writes directly
 * and the board sends as they are; STP_FW_BAND_ROWS is then a multiple of
 * 8 (whole pages).
 *
 * STP_FW_STATIC 1: the scene is static (`stipple compile --static`): its
 * display file, entered on the host, is played back from flash
 * (stp_scene_static_open); nothing is entered on the chip.
 *
 * STP_FW_SPANS 1: the scene was compiled with --spans: its picture's rows
 * as runs of one shade (stipple/playback_spans.h), drawn into the band by
 * stp_spans_draw; no renderer, no display file, no Z buffer on the chip.
 *
 * STP_FW_BENCH 1 makes the bench image: it also renders the frame once
 * without the panel and reports instruction counts over semihosting
 * ("stipple: WHAT N", read by tests/firmware/run_qemu_test.sh), and with
 * STP_FW_SHADE_BENCH 1 the instructions per shade (bench_shade.c).  The
 * shipping image (STP_FW_BENCH 0) carries none of that.
 */
#include "board.h"
#include "stellaris.h"
#include "stp_scene_data.h"
#include "stipple/stipple.h"
#if STP_FW_SHADE_BENCH && !STP_FW_STATIC && !STP_FW_SPANS
#include "bench_shade.h"
#endif

#ifndef STP_FW_BAND_ROWS
#define STP_FW_BAND_ROWS 4
#endif
#ifndef STP_FW_PANEL_W
#define STP_FW_PANEL_W 128u /* the buffers' width: the board's panel's */
#endif
#ifndef STP_FW_BENCH
#define STP_FW_BENCH 0
#endif
#ifndef STP_FW_STATIC
#define STP_FW_STATIC 0
#endif
#ifndef STP_FW_SPANS
#define STP_FW_SPANS 0
#endif
#ifndef STP_FW_PAGES
#define STP_FW_PAGES 0
#endif

#if STP_FW_PAGES
#if STP_FW_BAND_ROWS % 8 != 0
#error "a page panel's bands are whole pages: STP_FW_BAND_ROWS a multiple of 8"
#endif
#if STP_FW_SPANS
#error "the span player draws MONO1 rows, not a page panel's pages"
#endif
#define STP_FW_FORMAT STP_PIXEL_MONO1_PAGES
#define STP_FW_MONO_BAND_BYTES (((STP_FW_BAND_ROWS + 7u) / 8u) * STP_FW_PANEL_W)
#else
#define STP_FW_FORMAT STP_PIXEL_MONO1
#define STP_FW_MONO_BAND_BYTES (STP_FW_BAND_ROWS * (STP_FW_PANEL_W / 8u))
#endif

#if STP_FW_SPANS
static uint8_t band[STP_FW_MONO_BAND_BYTES];

static int fail(const char *what)
{
    stp_semihost_write("stipple: ");
    stp_semihost_write(what);
    stp_semihost_write(" failed\n");
    return 1;
}

#if STP_FW_BENCH
static void report(const char *what, uint32_t count)
{
    char num[12];
    stp_semihost_write("stipple: ");
    stp_semihost_write(what);
    stp_semihost_write(" ");
    stp_semihost_write(stp_utoa(count, num));
    stp_semihost_write("\n");
}
#endif

/* The frame, band by band, to flush (the panel's, or none). */
static int draw_frame(const stp_board *board, stp_port *port, int to_panel)
{
    const stp_spans *spans = &stp_compiled_spans;
    stp_spans_cursor cursor;
    uint32_t y, rows;
    stp_spans_start(spans, &cursor);
    for (y = 0; y < spans->height; y += rows) {
        rows = spans->height - y < STP_FW_BAND_ROWS ? spans->height - y : STP_FW_BAND_ROWS;
        if (stp_spans_draw(spans, &cursor, band, STP_FW_PANEL_W / 8u, rows) != STP_OK ||
            (to_panel && board->flush(port, y, rows, band, STP_FW_PANEL_W / 8u) != 0))
            return -1;
    }
    return 0;
}

int main(void)
{
    const stp_board *board = &stp_board_this;
    stp_port port;
#if STP_FW_BENCH
    uint64_t t0, t1, t2;
    uint32_t per_tick;
    stp_count_start();
    per_tick = stp_count_calibrate();
#endif
    if (board->width != STP_FW_PANEL_W || stp_compiled_spans.width != board->width ||
        stp_compiled_spans.height != board->height) {
        stp_semihost_write(board->size_hint);
        return fail(": compile the scene for that size");
    }
    port.width = board->width;
    port.height = board->height;
    port.format = STP_FW_FORMAT; /* the board's: its file refuses another STP_FW_PAGES */
    port.user = 0;
    port.flush = board->flush;
#if STP_FW_BENCH
    t0 = stp_count_now();
    if (draw_frame(board, &port, 0) != 0)
        return fail("render");
    t1 = stp_count_now();
#endif
    if (board->panel_start() != 0)
        return fail("panel");
    if (draw_frame(board, &port, 1) != 0)
        return fail("render to panel");
#if STP_FW_BENCH
    t2 = stp_count_now();
    report("instructions per SysTick tick:", per_tick);
    report("instructions to enter the scene:", 0);
    report("instructions per frame (core):", (uint32_t)((t1 - t0) * per_tick));
    report("instructions per frame (core + panel):", (uint32_t)((t2 - t1) * per_tick));
    report("band rows:", STP_FW_BAND_ROWS);
    report("stack bytes never used:", stp_stack_never_used());
#endif
    board->hold();
    return 0;
}
#else

#if STP_FW_STATIC
#define SCENE stp_compiled_static
#define SCENE_TYPE stp_scene_static
#define scene_open stp_scene_static_open
#define scene_output stp_scene_static_output
#else
#define SCENE stp_compiled_scene
#define SCENE_TYPE stp_scene_data
#define scene_open stp_scene_data_enter
#define scene_output stp_scene_data_output
#endif

static stp_renderer_storage renderer;
#if STP_FW_DIFFUSION
/* error diffusion draws the band as GREY8 rows (render.h, stp_output.diffusion) */
static uint8_t band[STP_FW_BAND_ROWS * STP_FW_PANEL_W];
#else
static uint8_t band[STP_FW_MONO_BAND_BYTES];
#endif
#if STP_WITH_ZBUFFER
static uint16_t zbuf[STP_FW_BAND_ROWS * STP_FW_PANEL_W];
#endif

static int fail(const char *what, int status)
{
    stp_semihost_write("stipple: ");
    stp_semihost_write(what);
    stp_semihost_write(": ");
    stp_semihost_write(stp_status_text(status));
    stp_semihost_write("\n");
    return 1;
}

#if STP_FW_BENCH
static void report(const char *what, uint64_t count)
{
    char num[12];
    stp_semihost_write("stipple: ");
    stp_semihost_write(what);
    stp_semihost_write(" ");
    stp_semihost_write(stp_utoa(count > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)count, num));
    stp_semihost_write("\n");
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
#endif

int main(void)
{
    const struct SCENE_TYPE *scene = &SCENE;
    const stp_board *board = &stp_board_this;
    stp_renderer *r;
    stp_port port;
    stp_output out;
    stp_frame_memory mem;
    int status;
#if STP_FW_BENCH
    uint64_t t0, t1, t2, t3, t4;
    uint32_t per_tick;
    stp_count_start();
    per_tick = stp_count_calibrate();
#endif

    if (board->width != STP_FW_PANEL_W || scene->width != board->width ||
        scene->height != board->height) {
        stp_semihost_write(board->size_hint);
        return fail(" is the size to compile the scene for", STP_ERR_ARG);
    }
#if STP_FW_BENCH
    t0 = stp_count_now();
#endif
    status = scene_open(scene, &renderer, sizeof renderer, &r);
    if (status != STP_OK)
        return fail("enter", status);
#if STP_FW_BENCH
    t1 = stp_count_now();
#endif

    scene_output(scene, &out);
    stp_scene_frame_memory(&mem, band, sizeof band, STP_FW_BAND_ROWS, scene->sort,
                           scene->sort_count);
#if STP_WITH_ZBUFFER
    mem.zbuf = zbuf;
    mem.zbuf_count = sizeof zbuf / sizeof zbuf[0];
#endif
    port.width = board->width;
    port.height = board->height;
    port.format = STP_FW_FORMAT; /* the board's: its file refuses another STP_FW_PAGES */
    port.user = 0;

#if STP_FW_BENCH
    /* the frame through the core alone, the panel's transfer left out */
    port.flush = discard_flush;
    status = stp_renderer_render(r, &port, &out, &mem);
    t2 = stp_count_now();
    if (status != STP_OK)
        return fail("render", status);
#endif

    if (board->panel_start() != 0)
        return fail("panel", STP_ERR_PORT);
#if STP_FW_BENCH
    t3 = stp_count_now();
#endif
    port.flush = board->flush;
    status = stp_renderer_render(r, &port, &out, &mem);
    if (status != STP_OK)
        return fail("render to panel", status);

#if STP_FW_BENCH
    t4 = stp_count_now();
    report("instructions per SysTick tick:", per_tick);
    report("instructions to enter the scene:", (t1 - t0) * per_tick);
    report("instructions per frame (core):", (t2 - t1) * per_tick);
    report("instructions per frame (core + panel):", (t4 - t3) * per_tick);
#if STP_FW_SHADE_BENCH && !STP_FW_STATIC
    {
        uint32_t calls, per_shade = stp_bench_shade(scene, per_tick, &calls);
        report("instructions per shade:", per_shade);
        report("shade calls timed:", calls);
    }
#endif
    report("band rows:", STP_FW_BAND_ROWS);
    report("stack bytes never used:", stp_stack_never_used());
    report("renderer bytes:", stp_renderer_size());
    report("renderer storage bytes:", STP_RENDERER_BYTES); /* the test: the same */
    report("display-file entries:", stp_renderer_display_file_used(r));
#endif
    board->hold();
    return 0;
}
#endif /* STP_FW_SPANS */
