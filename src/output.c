/* Style index to device value (see output_private.h). */
#include "output_private.h"

uint8_t stp_output_level(const stp_output *out, int levels, int index)
{
    if (index < 1)
        index = 1;
    if (index > levels)
        index = levels;
    if (out->gamma)
        return out->gamma[index - 1];
    return (uint8_t)(((index - 1) * 255 + (levels - 1) / 2) / (levels - 1));
}

uint8_t stp_output_style_code(const stp_output *out, int levels, int index)
{
    if (index > levels)
        index = levels;
    if (out->styles)
        return stp_style_lookup(out->styles, index);
    return (uint8_t)index;
}
