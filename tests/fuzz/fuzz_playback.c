/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer target: the display-file player (include/stipple/playback.h),
 * fed display files as they come from flash or a file: whole, cut short or
 * corrupted.  The input is a header (device size, levels, fill style, output
 * format, band rows) and then the entries, either raw bytes (any opcode,
 * any value) or built from a few bytes each so most are near the ones the
 * entry side makes (polygons of 3..8 vertices on the device, shades,
 * styles, lines), with a byte in eight taken raw.  The entries are copied
 * into an array of exactly `used` entries, so a read past the data is an
 * ASan finding.  Checked:
 *  - stp_playback_check and stp_playback_create agree (a renderer exactly
 *    when the check passes), and the check's bad index is inside the data;
 *  - every prefix the input names (cut short) is refused or played alike;
 *  - an accepted file renders with STP_OK under every hidden-surface
 *    method into bands and into one band, the two pictures equal.
 */
#include <string.h>

#include "fuzz_common.h"
#include "stipple/playback.h"
#include "stipple/stipple.h"

#define FZ_MAX_ENTRIES 512

static void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    FZ_CHECK(p != NULL, "out of memory (%zu bytes)", n);
    return p;
}

typedef struct capture {
    stp_port port;
    uint8_t *frame;
    size_t stride;
} capture;

static int capture_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *band,
                         size_t stride)
{
    capture *c = (capture *)port->user;
    uint32_t y;
    FZ_CHECK(y0 + rows <= port->height, "band %u + %u rows past the frame", (unsigned)y0,
             (unsigned)rows);
    FZ_CHECK(stride >= c->stride, "stride %zu below a row's %zu bytes", stride, c->stride);
    for (y = 0; y < rows; y++)
        memcpy(c->frame + (size_t)(y0 + y) * c->stride, band + (size_t)y * stride, c->stride);
    return 0;
}

/* Render r into a fresh frame (returned; the caller frees it). */
static uint8_t *render(stp_renderer *r, uint32_t w, uint32_t h, stp_pixel_format format,
                       stp_hidden hidden, uint32_t band_rows)
{
    stp_frame_memory mem;
    stp_output out;
    capture cap;
    uint32_t polygons = stp_renderer_polygon_count(r);
    int status;

    memset(&mem, 0, sizeof mem);
    memset(&cap, 0, sizeof cap);
    cap.stride = stp_row_bytes(format, w);
    cap.frame = (uint8_t *)xmalloc(cap.stride * h);
    memset(cap.frame, 0xEE, cap.stride * h);
    cap.port.width = w;
    cap.port.height = h;
    cap.port.format = format;
    cap.port.flush = capture_flush;
    cap.port.user = &cap;
    mem.band_rows = band_rows;
    mem.band_size = cap.stride * band_rows;
    mem.band = (uint8_t *)xmalloc(mem.band_size);
    mem.zbuf_count = (size_t)w * band_rows;
    mem.zbuf = (uint16_t *)xmalloc(mem.zbuf_count * sizeof *mem.zbuf);
    mem.sort_count = polygons;
    mem.sort = (stp_sort_entry *)xmalloc(polygons * sizeof *mem.sort);
    FZ_CHECK(stp_output_default(&out) == STP_OK, "stp_output_default failed");
    out.hidden = hidden;
    status = stp_renderer_render(r, &cap.port, &out, &mem);
    FZ_CHECK(status == STP_OK, "render (hidden %d, format %d, %u rows) returned %d", (int)hidden,
             (int)format, (unsigned)band_rows, status);
    free(mem.band);
    free(mem.zbuf);
    free(mem.sort);
    return cap.frame;
}

static int32_t value(fz_reader *in, int32_t lo, int32_t hi)
{
    uint8_t kind = fz_u8(in);
    if (kind % 8 == 7) {
        int32_t raw = (int32_t)fz_u32(in);
        /* raw, except where a scale would take it out of int32_t */
        return lo == -4096 ? raw % 4097 : raw;
    }
    return lo + (int32_t)(fz_u16(in) % (uint32_t)(hi - lo + 1));
}

/* A point near what the entry side makes. */
static void point(fz_reader *in, stp_instr *e, uint32_t w, uint32_t h, int32_t shade)
{
    e->x = value(in, 0, (int32_t)(w << STP_SUBPIXEL_BITS));
    e->y = value(in, 0, (int32_t)(h << STP_SUBPIXEL_BITS));
    /* perspective keys (0, 2^30] in steps of 2^18, parallel ones below 0 */
    e->z = value(in, -4096, 4096) * (1 << 18);
#if STP_WITH_GOURAUD
    e->shade = shade;
#else
    (void)shade;
#endif
}

/* Entries built from a few bytes each; returns how many. */
static uint32_t build(fz_reader *in, stp_instr *df, uint32_t w, uint32_t h)
{
    uint32_t n = 0;
    while (n < FZ_MAX_ENTRIES && !fz_done(in)) {
        stp_instr *e = &df[n];
        uint8_t kind = fz_u8(in) % 8;
        memset(e, 0, sizeof *e);
#if STP_WITH_GOURAUD
        e->shade = -1;
#endif
        if (kind < 3) {
            int32_t count = 3 + fz_u8(in) % 6, i;
            int smooth = fz_u8(in) & 1;
            for (i = 0; i < count && n < FZ_MAX_ENTRIES; i++, n++) {
                int32_t shade = smooth ? value(in, 0, STP_FIX_ONE) : -1;
                df[n].op = i == 0 ? count : STP_OP_LINE;
                point(in, &df[n], w, h, shade);
            }
            continue;
        }
        switch (kind) {
        case 3:
            e->op = STP_OP_SHADE;
            e->x = value(in, 1, 16);
            e->y = value(in, 0, STP_FIX_ONE);
            e->z = fz_u8(in) & 1 ? (STP_COLOUR_FLAG | (int32_t)(fz_u32(in) & 0x0F0F0F)) : 0;
            break;
        case 4: e->op = STP_OP_TRANSPARENCY; e->x = value(in, 0, STP_FIX_ONE); break;
        case 5: e->op = STP_OP_LINE_STYLE; e->x = value(in, 1, 16); break;
        case 6: e->op = fz_u8(in) & 1 ? STP_OP_MOVE : STP_OP_LINE; point(in, e, w, h, -1); break;
        default: e->op = (int32_t)fz_u32(in); point(in, e, w, h, -1); break;
        }
        n++;
    }
    return n;
}

/* Play df[0, used) (an exact-size copy); returns 1 when it was accepted. */
static int play(const stp_instr *entries, uint32_t used, uint32_t w, uint32_t h, int levels,
                int fill, stp_pixel_format format, uint32_t band_rows)
{
    void *mem = xmalloc(stp_renderer_size());
    stp_instr *df = (stp_instr *)xmalloc(used * sizeof *df);
    uint32_t bad = UINT32_MAX;
    int status, hidden;
    stp_renderer *r;

    memcpy(df, entries, used * sizeof *df);
    status = stp_playback_check(df, used, w, h, &bad);
    FZ_CHECK(status == STP_OK || status == STP_ERR_ARG, "check returned %d", status);
    FZ_CHECK(status == STP_OK || used == 0 || bad < used, "bad entry %u of %u", (unsigned)bad,
             (unsigned)used);
    r = stp_playback_create(mem, stp_renderer_size(), df, used, w, h, levels, fill);
    FZ_CHECK((r != NULL) == (status == STP_OK), "create %s a file the check %s",
             r ? "took" : "refused", status == STP_OK ? "passed" : "refused");
    if (r) {
        for (hidden = 0; hidden < 3; hidden++) {
            uint8_t *banded = render(r, w, h, format, (stp_hidden)hidden, band_rows);
            uint8_t *whole = render(r, w, h, format, (stp_hidden)hidden, h);
            FZ_CHECK(memcmp(banded, whole, stp_row_bytes(format, w) * h) == 0,
                     "bands of %u rows differ from one band (hidden %d)", (unsigned)band_rows,
                     hidden);
            free(banded);
            free(whole);
        }
    }
    free(df);
    free(mem);
    return r != NULL;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static stp_instr entries[FZ_MAX_ENTRIES];
    fz_reader in;
    uint32_t w, h, used, band_rows, cut;
    int levels, fill, raw;
    stp_pixel_format format;

    fz_init(&in, data, size);
    raw = fz_u8(&in) % 4 == 0;
    w = 1u + fz_u8(&in) % 48u;
    h = 1u + fz_u8(&in) % 32u;
    levels = fz_range(&in, 2, 256);
    fill = fz_range(&in, 1, levels);
    format = (stp_pixel_format)fz_range(&in, 0, 3);
    if (format == STP_PIXEL_STYLE8 && levels > 255)
        format = STP_PIXEL_GREY8; /* STYLE8 without a table holds 1..255 */
    band_rows = 1u + fz_u8(&in) % h;
    cut = fz_u16(&in);
    if (raw) {
        used = (uint32_t)(in.left / sizeof(stp_instr));
        if (used > FZ_MAX_ENTRIES)
            used = FZ_MAX_ENTRIES;
        memcpy(entries, in.p, used * sizeof(stp_instr));
    } else {
        used = build(&in, entries, w, h);
    }
    if (used == 0)
        return 0;
    play(entries, used, w, h, levels, fill, format, band_rows);
    /* the same data cut short */
    if (used > 1)
        play(entries, 1u + cut % (used - 1u), w, h, levels, fill, format, band_rows);
    return 0;
}
