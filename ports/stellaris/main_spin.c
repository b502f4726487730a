/* SPDX-License-Identifier: MIT */
/*
 * The spinning teapot on the board's panel (issue 11 item 4): the scene of
 * ports/spin (teapot-s1 as indexed meshes in flash, written by
 * tools/bench/spin_mesh_gen), the teapot turned SPIN_DEGREES_PER_FRAME
 * degrees per frame about its vertical axis and re-entered with
 * stp_renderer_mesh into a fresh segment, rendered in STP_FW_BAND_ROWS-row
 * bands straight to the OLED, in the board's format (board.h: MONO1 rows,
 * or a page panel's own 8-row pages, sent as drawn).  After STP_SPIN_FRAMES
 * frames the picture is held (board->hold); 0 spins for ever.
 *
 * Counting (tests/firmware/run_spin_oled_test.sh runs QEMU with -icount
 * shift=0): SysTick ticks of every frame, calibrated to emulated
 * instructions (stp_count_calibrate), reported over semihosting per frame
 * (entering, then rendering including sending the bands to the panel), and
 * frames 1..N-1's largest and mean with the frames per second they give at
 * 48 MHz counting one instruction per cycle (48e6 / instructions: an upper
 * bound; a Cortex-M0+ takes 2 cycles for loads, stores and taken branches).
 */
#include "board.h"
#include "spin_frame.h"
#include "stellaris.h"

#ifndef STP_FW_BAND_ROWS
#define STP_FW_BAND_ROWS 8
#endif
#ifndef STP_SPIN_FRAMES
#define STP_SPIN_FRAMES 0
#endif
#define SPIN_STRIDE 16u /* 128 pixels, MONO1 */
#define CLOCK_HZ 48000000u

static stp_renderer_storage storage;
static uint8_t band[SPIN_STRIDE * STP_FW_BAND_ROWS]; /* rows, or as many bytes of pages */
static uint16_t zbuf[8u * SPIN_STRIDE * STP_FW_BAND_ROWS];

static void report(const char *what, uint32_t value, const char *after)
{
    char num[12];
    stp_semihost_write(what);
    stp_semihost_write(stp_utoa(value, num));
    stp_semihost_write(after);
}

/* "F.F" frames per second at 48 MHz for `instructions` per frame */
static void report_fps(const char *what, uint32_t instructions)
{
    uint32_t tenths = instructions ? (uint32_t)(((uint64_t)CLOCK_HZ * 10u + instructions / 2u) / instructions) : 0;
    report(what, instructions, " instructions, ");
    report("", tenths / 10u, ".");
    report("", tenths % 10u, " frames/s at 48 MHz (1 instruction/cycle)\n");
}

int main(void)
{
    const stp_board *board = &stp_board_this;
    stp_renderer *r;
    stp_port port;
    stp_frame_memory mem;
    uint32_t per_tick, n, most = 0, enter, render;
    uint64_t t0, t1, t2, sum = 0;
    int status;
    stp_count_start();
    per_tick = stp_count_calibrate();
    port.width = board->width;
    port.height = board->height;
    port.format = board->format; /* pages: STP_FW_BAND_ROWS a multiple of 8 (stp_renderer_render) */
    port.flush = board->flush;
    port.user = 0;
    mem.band = band;
    mem.band_size = sizeof band;
    mem.band_rows = STP_FW_BAND_ROWS;
    mem.zbuf = zbuf;
    mem.zbuf_count = sizeof zbuf / sizeof zbuf[0];
    mem.sort = 0;
    mem.sort_count = 0;
    mem.setup = 0;
    mem.setup_count = 0;
    r = stp_renderer_create(&storage, sizeof storage, spin_display_file, spin_display_file_capacity,
                            board->width, board->height);
    if (!r || board->width != 8u * SPIN_STRIDE || board->panel_start() != 0 ||
        spin_setup(r) != STP_OK) {
        stp_semihost_write("stipple: spin setup failed\n");
        return 1;
    }
    report("stipple: instructions per tick ", per_tick, "\n");
#if STP_SPIN_FRAMES > 0
    for (n = 0; n < STP_SPIN_FRAMES; n++) {
#else
    for (n = 0;; n++) {
#endif
        t0 = stp_count_now();
        status = spin_enter(r, n);
        t1 = stp_count_now();
        if (status == STP_OK)
            status = spin_render(r, &port, &mem);
        t2 = stp_count_now();
        if (status != STP_OK) {
            stp_semihost_write("stipple: frame failed: ");
            stp_semihost_write(stp_status_text(status));
            stp_semihost_write("\n");
            return 1;
        }
        enter = (uint32_t)((t1 - t0) * per_tick);
        render = (uint32_t)((t2 - t1) * per_tick);
        report("stipple: frame ", n, ": ");
        report("enter ", enter, ", ");
        report("render ", render, ", ");
        report("total ", enter + render, " instructions\n");
        if (n > 0) { /* frame 0 has no segment to delete */
            sum += enter + render;
            most = enter + render > most ? enter + render : most;
        }
    }
#if STP_SPIN_FRAMES > 1
    report_fps("stipple: mean of frames 1.. : ", (uint32_t)(sum / (STP_SPIN_FRAMES - 1u)));
    report_fps("stipple: largest frame      : ", most);
#endif
    board->hold();
    return 0;
}
