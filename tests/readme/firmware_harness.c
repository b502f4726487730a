/* SPDX-License-Identifier: MIT */
/* Runs the README's firmware example (readme_firmware.c, extracted from
 * README.md by test_readme_example.sh) on the host: its ssd1306_page is a
 * panel model that rebuilds the 128x64 picture from the SSD1306 pages
 * (byte = 8 rows of one column, bit r = row r), and after a few frames the
 * harness leaves its endless loop.  Checks, from the geometry alone (not
 * from the renderer): the tetrahedron's vertices lie on a sphere of radius
 * sqrt(3) around the origin, 5 units in front of the eye, seen with a focal length of 64 pixels, so every lit
 * pixel lies within 64 sqrt(3) / sqrt(25 - 3) = 23.63 pixels of the
 * picture's centre (plus a pixel's half diagonal); a lit model covers a
 * good part of that disc; the model turns (frames differ); every page of
 * every frame is written once, in order.  Prints frame 0 as text. */
#include <math.h>
#include <setjmp.h>
#include <stdio.h>
#include <string.h>

#include "readme_firmware.c"

enum { FRAMES = 6 };
static uint8_t picture[FRAMES][64][128];
static unsigned pages_seen, bad_order;
static jmp_buf done;

void ssd1306_page(uint8_t page, const uint8_t columns[128])
{
    unsigned frame = pages_seen / 8, x, r;
    if (page != pages_seen % 8)
        bad_order++;
    for (x = 0; x < 128; x++)
        for (r = 0; r < 8; r++)
            picture[frame][page * 8 + r][x] = (uint8_t)((columns[x] >> r) & 1u);
    if (++pages_seen == FRAMES * 8)
        longjmp(done, 1);
}

int main(void)
{
    const double radius = 64.0 * sqrt(3.0) / sqrt(25.0 - 3.0) + 0.71;
    unsigned f, x, y, lit0 = 0, outside = 0, differing = 0;
    if (setjmp(done) == 0)
        spin();
    for (f = 0; f < FRAMES; f++)
        for (y = 0; y < 64; y++)
            for (x = 0; x < 128; x++) {
                double dx = x + 0.5 - 64.0, dy = y + 0.5 - 32.0;
                if (picture[f][y][x] && sqrt(dx * dx + dy * dy) > radius)
                    outside++;
                if (f == 0 && picture[0][y][x])
                    lit0++;
                if (f == FRAMES - 1 && picture[f][y][x] != picture[0][y][x])
                    differing++;
            }
    for (y = 0; y < 64; y += 2) {
        for (x = 0; x < 128; x++)
            putchar(picture[0][y][x] || picture[0][y + 1][x] ? '#' : '.');
        putchar('\n');
    }
    printf("frame 0: %u lit pixels; lit outside the %.2f-pixel disc in %u frames: %u; "
           "frame %u differs from frame 0 in %u pixels; pages out of order: %u\n",
           lit0, radius, FRAMES, outside, FRAMES - 1, differing, bad_order);
    /* the disc holds pi 23.63^2 = 1754 pixels; a lit tetrahedron covers at
     * least a fifth of it, of which the dither lights a share */
    return outside == 0 && bad_order == 0 && lit0 > 150 && differing > 20 ? 0 : 1;
}
