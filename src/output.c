/* SPDX-License-Identifier: MIT */
/* Style index to device value (see output_private.h). */
#include "output_private.h"
#include "run_fill_private.h" /* stp_mono_put */

uint8_t stp_output_level(const stp_output *out, int levels, int index)
{
    if (index < 1)
        index = 1;
    if (index > levels)
        index = levels;
    if (out->gamma)
        return out->gamma[index - 1];
    return (uint8_t)(((int32_t)(index - 1) * 255 + (levels - 1) / 2) / (levels - 1)); /* > 2^15 */
}

void stp_output_put_shade(uint8_t *row, stp_pixel_format format, uint32_t x, uint32_t y,
                          const stp_output *out, const stp_cell *cell, int levels, stp_fix shade)
{
    int index = stp_intensity_index(shade, levels);
    uint8_t level;
    if (format == STP_PIXEL_STYLE8) {
        row[x] = stp_output_style_code(out, levels, index);
        return;
    }
    level = stp_output_level(out, levels, index);
    switch (format) {
    case STP_PIXEL_MONO1: stp_mono_put(row, 0, x, stp_cell_on(cell, x, y, level)); break;
    case STP_PIXEL_MONO1_PAGES:
        stp_mono_put(row, (uint8_t)(1u << (y & 7u)), x, stp_cell_on(cell, x, y, level));
        break;
    case STP_PIXEL_GREY8: row[x] = level; break;
    default: row[3 * x] = row[3 * x + 1] = row[3 * x + 2] = level; break;
    }
}

uint8_t stp_output_style_code(const stp_output *out, int levels, int index)
{
    if (index > levels)
        index = levels;
    if (out->styles)
        return stp_style_lookup(out->styles, index);
    return (uint8_t)index;
}
