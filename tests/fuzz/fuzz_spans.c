/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer target: the span player (include/stipple/playback_spans.h), fed
 * span data as it comes from flash: any header, any patterns, any runs,
 * copied into arrays of exactly their size so a read past them is an ASan
 * finding.  Checked:
 *  - the picture drawn in bands of the input's height and in one band both
 *    succeed or both fail;
 *  - where they succeed, both equal an independent decoding of the runs
 *    (each run {last x, shade} fills its pixels from the shade's pattern
 *    row y & (cell_rows - 1), pixel x from bit 7 - (x & 7)).
 */
#include <string.h>

#include "fuzz_common.h"
#include "stipple/stipple.h"

static void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    FZ_CHECK(p != NULL, "out of memory (%zu bytes)", n);
    return p;
}

/* The picture of s, decoded here; 0 when the runs do not make one (a run
 * backwards, past the row, a bad shade, or the data ending early). */
static int decode(const stp_spans *s, uint8_t *pixels)
{
    uint32_t i = 0, y;
    for (y = 0; y < s->height; y++) {
        uint32_t x = 0;
        while (x < s->width) {
            uint32_t last, shade;
            if (i + 2 > s->run_bytes)
                return 0;
            last = s->runs[i];
            shade = s->runs[i + 1];
            i += 2;
            if (last < x || last >= s->width || shade >= s->shade_count)
                return 0;
            for (; x <= last; x++) {
                uint8_t pattern = s->patterns[shade * s->cell_rows + (y & (s->cell_rows - 1u))];
                pixels[y * s->width + x] = (uint8_t)((pattern >> (7 - (x & 7))) & 1);
            }
        }
    }
    return 1;
}

/* Draw the whole picture in bands of band_rows; returns 1 and the pixels,
 * or 0 when a band was refused. */
static int play(const stp_spans *s, uint32_t band_rows, uint8_t *pixels)
{
    size_t stride = ((size_t)s->width + 7) / 8;
    uint8_t *band = xmalloc(stride * band_rows);
    stp_spans_cursor cursor;
    uint32_t y0, r, x;
    int ok = 1;
    stp_spans_start(s, &cursor);
    for (y0 = 0; y0 < s->height && ok; y0 += band_rows) {
        uint32_t rows = s->height - y0 < band_rows ? s->height - y0 : band_rows;
        if (stp_spans_draw(s, &cursor, band, stride, rows) != STP_OK) {
            ok = 0;
            break;
        }
        for (r = 0; r < rows; r++)
            for (x = 0; x < s->width; x++)
                pixels[(y0 + r) * s->width + x] =
                    (uint8_t)((band[r * stride + x / 8] >> (7 - (x & 7))) & 1);
    }
    free(band);
    return ok;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const uint8_t cells[4] = {1, 2, 4, 8};
    fz_reader in;
    stp_spans s;
    uint8_t *patterns, *runs, *banded, *whole, *ref;
    uint32_t band_rows, n, k;
    int banded_ok, whole_ok, ref_ok;
    fz_init(&in, data, size);
    memset(&s, 0, sizeof s);
    s.width = (uint16_t)(fz_u8(&in) + 1u);
    s.height = (uint16_t)fz_range(&in, 1, 48);
    s.cell_rows = cells[fz_u8(&in) & 3u];
    s.shade_count = (uint8_t)fz_range(&in, 1, 17);
    band_rows = (uint32_t)fz_range(&in, 1, s.height);
    n = (uint32_t)s.shade_count * s.cell_rows;
    patterns = xmalloc(n);
    for (k = 0; k < n; k++)
        patterns[k] = fz_u8(&in);
    s.run_bytes = (uint32_t)in.left;
    runs = xmalloc(in.left);
    if (in.left)
        memcpy(runs, in.p, in.left);
    s.patterns = patterns;
    s.runs = runs;
    banded = xmalloc((size_t)s.width * s.height);
    whole = xmalloc((size_t)s.width * s.height);
    ref = xmalloc((size_t)s.width * s.height);
    banded_ok = play(&s, band_rows, banded);
    whole_ok = play(&s, s.height, whole);
    ref_ok = decode(&s, ref);
    FZ_CHECK(banded_ok == whole_ok, "bands of %u rows %s, one band %s", (unsigned)band_rows,
             banded_ok ? "played" : "refused", whole_ok ? "played" : "refused");
    FZ_CHECK(whole_ok == ref_ok, "the player %s data the decoding %s",
             whole_ok ? "played" : "refused", ref_ok ? "accepts" : "refuses");
    if (ref_ok) {
        FZ_CHECK(memcmp(banded, ref, (size_t)s.width * s.height) == 0, "banded picture differs");
        FZ_CHECK(memcmp(whole, ref, (size_t)s.width * s.height) == 0, "one-band picture differs");
    }
    free(ref);
    free(whole);
    free(banded);
    free(runs);
    free(patterns);
    return 0;
}
