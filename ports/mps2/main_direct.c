/* SPDX-License-Identifier: MIT */
/* Cortex-M bench firmware for QEMU's mps2-an385: the spinning torus of
 * direct drawing (ports/direct/direct_spin.h) in STP_FW_BAND_ROWS-row
 * bands; reports the instructions of one frame (projection and shading,
 * then every band) and of its two halves, and prints the last frame in
 * hex over semihosting for the host to compare with
 * tools/bench/direct_spin_host (same frame number, same integers).
 * Counting as main_torus.c: SysTick under QEMU -icount shift=0. */
#include "direct_spin.h"
#include "stellaris.h"

#ifndef STP_FW_BAND_ROWS
#define STP_FW_BAND_ROWS 8
#endif
#ifndef STP_DIRECT_FRAME
#define STP_DIRECT_FRAME 10 /* the frame measured and printed */
#endif

static direct_spin spin;
static uint8_t band[SPIN_STRIDE * STP_FW_BAND_ROWS];
static uint8_t picture[SPIN_STRIDE * SPIN_HEIGHT];

static void report(const char *what, uint32_t value)
{
    char num[12];
    stp_semihost_write("stipple: ");
    stp_semihost_write(what);
    stp_semihost_write(" ");
    stp_semihost_write(stp_utoa(value, num));
    stp_semihost_write("\n");
}

/* "stipple: row Y" and the row in hex, per picture row */
static void dump_picture(void)
{
    static const char digits[] = "0123456789abcdef";
    char line[2 * SPIN_STRIDE + 2];
    uint32_t y, i;
    for (y = 0; y < SPIN_HEIGHT; y++) {
        for (i = 0; i < SPIN_STRIDE; i++) {
            line[2 * i] = digits[picture[y * SPIN_STRIDE + i] >> 4];
            line[2 * i + 1] = digits[picture[y * SPIN_STRIDE + i] & 15u];
        }
        line[2 * SPIN_STRIDE] = '\n';
        line[2 * SPIN_STRIDE + 1] = '\0';
        report("row", y);
        stp_semihost_write(line);
    }
}

/* Every band of frame f, each copied into the picture (a panel's flush). */
static int draw_bands(const stp_direct_frame *f)
{
    uint32_t y, i;
    for (y = 0; y < SPIN_HEIGHT; y += STP_FW_BAND_ROWS) {
        uint32_t rows = SPIN_HEIGHT - y < STP_FW_BAND_ROWS ? SPIN_HEIGHT - y : STP_FW_BAND_ROWS;
        int status = stp_direct_draw_band(f, band, SPIN_STRIDE, (uint16_t)y, (uint16_t)rows);
        if (status != STP_OK)
            return status;
        for (i = 0; i < rows * SPIN_STRIDE; i++)
            picture[y * SPIN_STRIDE + i] = band[i];
    }
    return STP_OK;
}

int main(void)
{
    stp_direct_frame f;
    uint32_t per_tick;
    uint64_t t0 = 0, t1 = 0, t2 = 0;
    uint16_t n;
    int status;
    stp_count_start();
    per_tick = stp_count_calibrate();
    status = direct_spin_init(&spin);
    for (n = 0; status == STP_OK && n <= STP_DIRECT_FRAME; n++) {
        t0 = stp_count_now();
        status = direct_spin_frame(&spin, n, &f);
        t1 = stp_count_now();
        if (status == STP_OK)
            status = draw_bands(&f);
        t2 = stp_count_now();
    }
    if (status != STP_OK || per_tick == 0) {
        stp_semihost_write("stipple: direct frame failed\n");
        return 1;
    }
    report("instructions per tick", per_tick);
    report("band rows", STP_FW_BAND_ROWS);
    report("frame", STP_DIRECT_FRAME);
    report("instructions to project and shade", (uint32_t)((t1 - t0) * per_tick));
    report("instructions to draw the bands", (uint32_t)((t2 - t1) * per_tick));
    report("instructions per direct frame", (uint32_t)((t2 - t0) * per_tick));
    dump_picture();
    return 0;
}
