/* SPDX-License-Identifier: MIT */
/* The host's render of the direct-drawing spinning torus
 * (ports/direct/direct_spin.h): frame N in B-row bands as a binary PBM,
 * for tools/bench/mps2_direct.sh to compare with the firmware's (bit 1 =
 * ON, as the firmware's rows), or with -i 1 as stipple writes PBM (1 =
 * black = OFF) for tests/firmware/run_direct_oled_test.sh.
 * usage: direct_spin_host [-n FRAME] [-b BAND_ROWS] [-i 0|1] -o OUT.pbm */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "direct_spin.h"

int main(int argc, char **argv)
{
    static direct_spin spin;
    static uint8_t picture[SPIN_STRIDE * SPIN_HEIGHT];
    stp_direct_frame f;
    const char *out = NULL;
    long n = 10, rows = 8, invert = 0;
    uint32_t y;
    int i, status;
    FILE *o;
    for (i = 1; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "-n") == 0)
            n = strtol(argv[i + 1], NULL, 10);
        else if (strcmp(argv[i], "-b") == 0)
            rows = strtol(argv[i + 1], NULL, 10);
        else if (strcmp(argv[i], "-i") == 0)
            invert = strtol(argv[i + 1], NULL, 10);
        else if (strcmp(argv[i], "-o") == 0)
            out = argv[i + 1];
        else
            break;
    }
    if (i != argc || out == NULL || n < 0 || n > 65535 || rows < 1 || rows > (long)SPIN_HEIGHT ||
        (invert != 0 && invert != 1)) {
        fprintf(stderr, "usage: %s [-n FRAME] [-b BAND_ROWS] [-i 0|1] -o OUT.pbm\n", argv[0]);
        return 2;
    }
    status = direct_spin_init(&spin);
    if (status == STP_OK)
        status = direct_spin_frame(&spin, (uint16_t)n, &f);
    for (y = 0; status == STP_OK && y < SPIN_HEIGHT; y += (uint32_t)rows) {
        uint32_t r = SPIN_HEIGHT - y < (uint32_t)rows ? SPIN_HEIGHT - y : (uint32_t)rows;
        status = stp_direct_draw_band(&f, picture + y * SPIN_STRIDE, SPIN_STRIDE, (uint16_t)y, (uint16_t)r);
    }
    if (status != STP_OK) {
        fprintf(stderr, "%s: frame %ld: %s\n", argv[0], n, stp_status_text(status));
        return 1;
    }
    for (y = 0; invert && y < sizeof picture; y++)
        picture[y] = (uint8_t)~picture[y];
    o = fopen(out, "wb");
    if (o == NULL || fprintf(o, "P4\n%u %u\n", SPIN_WIDTH, SPIN_HEIGHT) < 0 ||
        fwrite(picture, 1, sizeof picture, o) != sizeof picture || fclose(o) != 0) {
        fprintf(stderr, "%s: cannot write %s\n", argv[0], out);
        if (o != NULL)
            remove(out); /* never a half-written picture */
        return 1;
    }
    return 0;
}
