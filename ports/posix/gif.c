/* SPDX-License-Identifier: MIT */
/* Animated GIF output of 1-bit frames through giflib: see stp_posix_gif.h. */
#include "stp_posix_gif.h"

#include <errno.h>
#include <gif_lib.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "posix_internal.h"

int stp_posix_gif_path(const char *path)
{
    size_t n = path ? strlen(path) : 0;
    return n >= 4 && strcasecmp(path + n - 4, ".gif") == 0;
}

int stp_posix_gif_init(stp_posix_gif *g, uint32_t width, uint32_t height)
{
    memset(g, 0, sizeof *g);
    if (width < 1 || height < 1 || width > 32767 || height > 32767)
        return -1;
    g->width = width;
    g->height = height;
    g->stride = (width + 7) / 8;
    g->delay_cs = 5;
    g->on_rgb = 0xFFFFFF;
    return 0;
}

int stp_posix_gif_add(stp_posix_gif *g, const stp_posix_frame *f, char *err, size_t errlen)
{
    size_t bytes = g->stride * g->height;
    uint32_t y;
    if (f->format != STP_PIXEL_MONO1 || f->width != g->width || f->height != g->height) {
        stp_posix_priv_error(err, errlen, "GIF: a frame of another size or format");
        return -1;
    }
    if (g->count == g->capacity) {
        size_t cap = g->capacity ? g->capacity * 2 : 16;
        uint8_t *more = realloc(g->bits, cap * bytes);
        if (!more) {
            stp_posix_priv_error(err, errlen, "GIF: out of memory for %zu frames", cap);
            return -1;
        }
        g->bits = more;
        g->capacity = cap;
    }
    for (y = 0; y < g->height; y++)
        memcpy(g->bits + g->count * bytes + y * g->stride, f->pixels + (size_t)y * f->stride, g->stride);
    g->count++;
    return 0;
}

void stp_posix_gif_free(stp_posix_gif *g)
{
    free(g->bits);
    memset(g, 0, sizeof *g);
}

static int bit_at(const uint8_t *frame, size_t stride, uint32_t x, uint32_t y)
{
    return (frame[y * stride + (x >> 3)] >> (7 - (x & 7))) & 1;
}

/* The rectangle of frame now that differs from before (all of it when
 * before is NULL; one pixel when nothing differs). */
static void changed_box(const stp_posix_gif *g, const uint8_t *before, const uint8_t *now, uint32_t box[4])
{
    uint32_t x, y, x0 = g->width, y0 = g->height, x1 = 0, y1 = 0;
    if (!before) {
        box[0] = box[1] = 0;
        box[2] = g->width;
        box[3] = g->height;
        return;
    }
    for (y = 0; y < g->height; y++)
        for (x = 0; x < g->width; x++)
            if (bit_at(before, g->stride, x, y) != bit_at(now, g->stride, x, y)) {
                x0 = x < x0 ? x : x0;
                y0 = y < y0 ? y : y0;
                x1 = x + 1 > x1 ? x + 1 : x1;
                y1 = y + 1 > y1 ? y + 1 : y1;
            }
    if (x1 == 0) {
        x0 = y0 = 0;
        x1 = y1 = 1;
    }
    box[0] = x0;
    box[1] = y0;
    box[2] = x1 - x0;
    box[3] = y1 - y0;
}

static int write_bytes(GifFileType *gif, const GifByteType *bytes, int n)
{
    return (int)fwrite(bytes, 1, (size_t)n, (FILE *)gif->UserData);
}

/* The looping extension and the frames, each after its delay. */
static int put_frames(GifFileType *gif, const stp_posix_gif *g)
{
    static const GifByteType loop[3] = {1, 0, 0}; /* sub-block 1: loop for ever */
    size_t bytes = g->stride * g->height, i;
    GifPixelType *line = malloc(g->width);
    int ok = line != NULL;
    ok = ok && EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE) == GIF_OK &&
         EGifPutExtensionBlock(gif, 11, "NETSCAPE2.0") == GIF_OK &&
         EGifPutExtensionBlock(gif, 3, loop) == GIF_OK && EGifPutExtensionTrailer(gif) == GIF_OK;
    for (i = 0; ok && i < g->count; i++) {
        const uint8_t *now = g->bits + i * bytes, *before = i ? now - bytes : NULL;
        GraphicsControlBlock gcb;
        GifByteType ext[4];
        uint32_t box[4], x, y;
        memset(&gcb, 0, sizeof gcb);
        gcb.DisposalMode = DISPOSE_DO_NOT;
        gcb.DelayTime = (int)g->delay_cs;
        gcb.TransparentColor = NO_TRANSPARENT_COLOR;
        changed_box(g, before, now, box);
        ok = EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, (int)EGifGCBToExtension(&gcb, ext), ext) == GIF_OK &&
             EGifPutImageDesc(gif, (int)box[0], (int)box[1], (int)box[2], (int)box[3], false, NULL) == GIF_OK;
        for (y = box[1]; ok && y < box[1] + box[3]; y++) {
            for (x = 0; x < box[2]; x++)
                line[x] = (GifPixelType)bit_at(now, g->stride, box[0] + x, y);
            ok = EGifPutLine(gif, line, (int)box[2]) == GIF_OK;
        }
    }
    free(line);
    return ok ? 0 : -1;
}

static int emit_gif(FILE *out, void *ctx)
{
    const stp_posix_gif *g = ctx;
    GifColorType colours[2];
    ColorMapObject *map;
    GifFileType *gif;
    int error = 0, rc;
    colours[0].Red = (GifByteType)(g->off_rgb >> 16);
    colours[0].Green = (GifByteType)(g->off_rgb >> 8);
    colours[0].Blue = (GifByteType)g->off_rgb;
    colours[1].Red = (GifByteType)(g->on_rgb >> 16);
    colours[1].Green = (GifByteType)(g->on_rgb >> 8);
    colours[1].Blue = (GifByteType)g->on_rgb;
    map = GifMakeMapObject(2, colours);
    gif = map ? EGifOpen(out, write_bytes, &error) : NULL;
    if (!gif) {
        GifFreeMapObject(map);
        errno = ENOMEM;
        return -1;
    }
    EGifSetGifVersion(gif, true);
    rc = EGifPutScreenDesc(gif, (int)g->width, (int)g->height, 1, 0, map) == GIF_OK ? put_frames(gif, g) : -1;
    GifFreeMapObject(map);
    if (EGifCloseFile(gif, &error) != GIF_OK)
        rc = -1;
    if (rc != 0 && errno == 0)
        errno = EIO;
    return rc;
}

int stp_posix_gif_write(const stp_posix_gif *g, const char *path, char *err, size_t errlen)
{
    if (g->count == 0) {
        stp_posix_priv_error(err, errlen, "%s: no frames to write", path);
        return -1;
    }
    return stp_posix_write_file(path, emit_gif, (void *)g, err, errlen);
}
