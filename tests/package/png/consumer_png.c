/* SPDX-License-Identifier: MIT */
/* A program built against an installed stipple's PNG component
 * (find_package(stipple COMPONENTS png)): writes a 3x2 grey frame as PNG
 * into the file named by argv[1], reads it back and checks every sample. */
#include <stdio.h>
#include <string.h>

#include "stp_posix_png.h"

int main(int argc, char **argv)
{
    static const uint8_t grey[6] = {0, 51, 102, 153, 204, 255};
    stp_posix_frame f;
    stp_posix_image img;
    char err[256];
    uint32_t y;
    int ok;
    if (argc != 2 || stp_posix_frame_init(&f, 3, 2, STP_PIXEL_GREY8) != 0)
        return 1;
    for (y = 0; y < 2; y++)
        memcpy(f.pixels + y * f.stride, grey + 3 * y, 3);
    if (stp_posix_write_png(&f, argv[1], err, sizeof err) != 0 ||
        stp_posix_read_png(argv[1], &img, 1, err, sizeof err) != 0) {
        printf("%s\n", err);
        stp_posix_frame_free(&f);
        return 1;
    }
    ok = img.width == 3 && img.height == 2 && img.channels == 1 && memcmp(img.samples, grey, 6) == 0;
    printf("%s: 3x2 grey PNG written and read back %s\n", argv[1], ok ? "equal" : "DIFFERENT");
    stp_posix_image_free(&img);
    stp_posix_frame_free(&f);
    return ok ? 0 : 1;
}
