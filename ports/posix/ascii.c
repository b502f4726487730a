/* SPDX-License-Identifier: MIT */
/*
 * Text output of STYLE8 frames, the way the seed printed pictures on a line
 * printer: one character per pixel, one line per row.
 */
#include "posix_internal.h"

/* Lit pixels of each glyph in netpbm's built-in pbmtext font:
 * @ 42, M 38, & 35, B 32, % 29, $ 24, # 22, k 17, a 14, o 12, = 10, + 9,
 * - 5, : 2, . 1, space 0: strictly falling, so darker styles print darker. */
const uint8_t stp_posix_lineprinter_styles[16] = {
    '@', 'M', '&', 'B', '%', '$', '#', 'k',
    'a', 'o', '=', '+', '-', ':', '.', ' '
};

void stp_posix_lineprinter_table(stp_style_table *table)
{
    if (table == NULL)
        return;
    table->levels = 16;
    table->codes = stp_posix_lineprinter_styles;
}

int stp_posix_priv_encode_ascii(const stp_posix_frame *f, FILE *out)
{
    uint32_t y;

    for (y = 0; y < f->height; y++) {
        const uint8_t *row = f->pixels + (size_t)y * f->stride;

        /* Bytes go out untouched: the style table chose them. */
        if (fwrite(row, 1, f->width, out) != f->width || putc('\n', out) == EOF)
            return -1;
    }
    return 0;
}
