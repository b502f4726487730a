/* SPDX-License-Identifier: MIT */
/* 1-bit frames as C source (XBM, rows, SSD1306 pages): see stp_posix_bitmap.h. */
#include "stp_posix_bitmap.h"

#include <ctype.h>
#include <errno.h>
#include <string.h>
#include <strings.h>

#include "posix_internal.h"

int stp_posix_bitmap_layout_from_path(const char *path)
{
    size_t n = path ? strlen(path) : 0;
    if (n >= 4 && strcasecmp(path + n - 4, ".xbm") == 0)
        return STP_POSIX_BITMAP_XBM;
    if (n >= 2 && strcasecmp(path + n - 2, ".h") == 0)
        return STP_POSIX_BITMAP_ROWS;
    return -1;
}

void stp_posix_bitmap_name(const char *path, char *name, size_t size)
{
    const char *base = strrchr(path, '/'), *dot;
    size_t n = 0, len;
    base = base ? base + 1 : path;
    dot = strrchr(base, '.');
    len = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    if (size == 0)
        return;
    if (len > 0 && isdigit((unsigned char)base[0]) && n + 1 < size)
        name[n++] = '_';
    for (; len > 0 && n + 1 < size; len--, base++)
        name[n++] = isalnum((unsigned char)*base) ? *base : '_';
    name[n] = '\0';
    if (n == 0 || !strcmp(path, "-"))
        snprintf(name, size, "img");
}

static int bit_at(const stp_posix_frame *f, uint32_t x, uint32_t y)
{
    return (f->pixels[(size_t)y * f->stride + (x >> 3)] >> (7 - (x & 7))) & 1;
}

/* The i-th byte of the array in layout. */
static unsigned byte_at(const stp_posix_frame *f, stp_posix_bitmap_layout layout, size_t i)
{
    size_t row_bytes = (f->width + 7) / 8;
    unsigned v = 0;
    int k;
    if (layout == STP_POSIX_BITMAP_PAGES) {
        uint32_t x = (uint32_t)(i % f->width), page = (uint32_t)(i / f->width);
        for (k = 0; k < 8; k++)
            if (page * 8 + (uint32_t)k < f->height && bit_at(f, x, page * 8 + (uint32_t)k))
                v |= 1u << k;
        return v;
    }
    {
        uint32_t y = (uint32_t)(i / row_bytes), x0 = (uint32_t)(i % row_bytes) * 8;
        for (k = 0; k < 8 && x0 + (uint32_t)k < f->width; k++)
            if (bit_at(f, x0 + (uint32_t)k, y))
                v |= layout == STP_POSIX_BITMAP_XBM ? 1u << k : 0x80u >> k;
    }
    return v;
}

typedef struct bitmap_job {
    const stp_posix_frame *f;
    stp_posix_bitmap_layout layout;
    char name[64];
} bitmap_job;

static int emit_bitmap(FILE *out, void *ctx)
{
    const bitmap_job *job = ctx;
    const stp_posix_frame *f = job->f;
    size_t count = job->layout == STP_POSIX_BITMAP_PAGES ? (size_t)f->width * ((f->height + 7) / 8)
                                                         : (size_t)((f->width + 7) / 8) * f->height,
           i;
    int rc;
    if (job->layout == STP_POSIX_BITMAP_XBM)
        rc = fprintf(out, "#define %s_width %u\n#define %s_height %u\nstatic unsigned char %s_bits[] = {",
                     job->name, (unsigned)f->width, job->name, (unsigned)f->height, job->name);
    else
        rc = fprintf(out,
                     "/* %ux%u pixels, 1 = lit: %s */\n#define %s_WIDTH %u\n#define %s_HEIGHT %u\n"
                     "static const unsigned char %s[%zu] = {",
                     (unsigned)f->width, (unsigned)f->height,
                     job->layout == STP_POSIX_BITMAP_PAGES
                         ? "SSD1306 pages (8 rows each, bit 0 the top row), a byte per column"
                         : "rows top first, leftmost pixel in the most significant bit",
                     job->name, (unsigned)f->width, job->name, (unsigned)f->height, job->name, count);
    for (i = 0; rc >= 0 && i < count; i++)
        rc = fprintf(out, "%s0x%02x", i % 12 ? ", " : (i ? ",\n    " : "\n    "), byte_at(f, job->layout, i));
    if (rc >= 0)
        rc = fprintf(out, "\n};\n");
    return rc < 0 ? -1 : 0;
}

int stp_posix_write_bitmap(const stp_posix_frame *f, const char *path, stp_posix_bitmap_layout layout,
                           char *err, size_t errlen)
{
    bitmap_job job;
    if (!f || !f->pixels || f->format != STP_PIXEL_MONO1) {
        stp_posix_priv_error(err, errlen, "%s: XBM and C arrays hold 1-bit pictures", path);
        errno = EINVAL;
        return -1;
    }
    job.f = f;
    job.layout = layout;
    stp_posix_bitmap_name(path, job.name, sizeof job.name);
    return stp_posix_write_file(path, emit_bitmap, &job, err, errlen);
}
