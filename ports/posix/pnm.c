/* SPDX-License-Identifier: MIT */
/*
 * Netpbm files: PBM/PGM/PPM writers for frames, and a reader for all six
 * PNM variants into 8-bit samples.  Format reference: the Netpbm manual
 * pages pbm(5), pgm(5), ppm(5).
 */
#include <errno.h>
#include <inttypes.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

#include "posix_internal.h"

#define PNM_MAX_SIDE 32767u
#define PNM_MAX_MAXVAL 65535u
/* Plain PBM lines may be at most 70 characters (pbm(5)). */
#define PNM_PLAIN_LINE 70u

/* ------------------------------------------------------------- writing */

static int mono_bit(const uint8_t *row, uint32_t x)
{
    return (row[x >> 3] >> (7u - (x & 7u))) & 1u;
}

static int put_header(FILE *out, char magic, uint32_t w, uint32_t h, int maxval)
{
    if (fprintf(out, "P%c\n%" PRIu32 " %" PRIu32 "\n", magic, w, h) < 0)
        return -1;
    if (maxval > 0 && fprintf(out, "%d\n", maxval) < 0)
        return -1;
    return 0;
}

static int encode_p4(const stp_posix_frame *f, FILE *out, uint8_t *buf)
{
    unsigned spare = f->width % 8u;
    uint32_t y;
    size_t i;

    if (put_header(out, '4', f->width, f->height, 0) != 0)
        return -1;
    for (y = 0; y < f->height; y++) {
        const uint8_t *row = f->pixels + (size_t)y * f->stride;

        /* PBM's 1 is black, MONO1's 1 is light. */
        for (i = 0; i < f->stride; i++)
            buf[i] = (uint8_t)~row[i];
        /* Padding bits stay 0, as netpbm writes them. */
        if (spare != 0)
            buf[f->stride - 1] &= (uint8_t)(0xFFu << (8u - spare));
        if (fwrite(buf, 1, f->stride, out) != f->stride)
            return -1;
    }
    return 0;
}

static int encode_p1(const stp_posix_frame *f, FILE *out)
{
    uint32_t x, y;

    if (put_header(out, '1', f->width, f->height, 0) != 0)
        return -1;
    for (y = 0; y < f->height; y++) {
        const uint8_t *row = f->pixels + (size_t)y * f->stride;

        for (x = 0; x < f->width; x++) {
            if (putc(mono_bit(row, x) ? '0' : '1', out) == EOF)
                return -1;
            /* Break full lines; each row also ends its own line. */
            if ((x + 1u) % PNM_PLAIN_LINE == 0 || x + 1u == f->width) {
                if (putc('\n', out) == EOF)
                    return -1;
            }
        }
    }
    return 0;
}

/* One row of f as 8-bit samples, channels per pixel (1 or 3). */
static void expand_row(const stp_posix_frame *f, const uint8_t *row, int channels,
                       uint8_t *buf)
{
    uint32_t x;
    int c;

    for (x = 0; x < f->width; x++) {
        uint8_t v = f->format == STP_PIXEL_MONO1 ? (mono_bit(row, x) ? 255u : 0u) : row[x];

        for (c = 0; c < channels; c++)
            buf[(size_t)x * (size_t)channels + (size_t)c] = v;
    }
}

static int encode_bytes(const stp_posix_frame *f, FILE *out, char magic, int channels,
                        uint8_t *buf)
{
    size_t len = (size_t)f->width * (size_t)channels;
    /* Rows already in the file's layout are written straight from the frame. */
    int direct = (channels == 1 && f->format == STP_PIXEL_GREY8) ||
                 (channels == 3 && f->format == STP_PIXEL_RGB888);
    uint32_t y;

    if (put_header(out, magic, f->width, f->height, 255) != 0)
        return -1;
    for (y = 0; y < f->height; y++) {
        const uint8_t *row = f->pixels + (size_t)y * f->stride;

        if (!direct) {
            expand_row(f, row, channels, buf);
            row = buf;
        }
        if (fwrite(row, 1, len, out) != len)
            return -1;
    }
    return 0;
}

int stp_posix_priv_encode_pnm(const stp_posix_frame *f, stp_posix_file_kind kind, FILE *out)
{
    uint8_t *buf;
    int rc;

    if (kind == STP_POSIX_FILE_P1)
        return encode_p1(f, out);
    /* A scratch row large enough for any conversion (3 bytes per pixel). */
    buf = (uint8_t *)malloc((size_t)f->width * 3u);
    if (buf == NULL) {
        errno = ENOMEM;
        return -1;
    }
    switch (kind) {
    case STP_POSIX_FILE_P4:
        rc = encode_p4(f, out, buf);
        break;
    case STP_POSIX_FILE_P5:
        rc = encode_bytes(f, out, '5', 1, buf);
        break;
    case STP_POSIX_FILE_P6:
        rc = encode_bytes(f, out, '6', 3, buf);
        break;
    default:
        errno = EINVAL;
        rc = -1;
        break;
    }
    free(buf);
    return rc;
}

/* ------------------------------------------------------------- reading */

typedef struct pnm_reader {
    FILE *fp;
    const char *name; /* for messages: the path, or "stdin" */
    char *err;
    size_t errlen;
} pnm_reader;

static int rd_fail(pnm_reader *rd, const char *fmt, ...) STP_POSIX_PRINTF(2, 3);

/* Always returns -1, so callers can "return rd_fail(...)". */
static int rd_fail(pnm_reader *rd, const char *fmt, ...)
{
    char what[256];
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    stp_posix_priv_error(rd->err, rd->errlen, "%s: %s", rd->name, what);
    return -1;
}

/* The stream ended early: a read error if the stream says so, else the
 * file is short. */
static int rd_eof(pnm_reader *rd, const char *where)
{
    if (ferror(rd->fp))
        return rd_fail(rd, "read error %s: %s", where, strerror(errno != 0 ? errno : EIO));
    return rd_fail(rd, "truncated: the file ends %s", where);
}

static int is_pnm_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

static void describe_char(int c, char *buf, size_t len)
{
    if (c >= 0x20 && c < 0x7F)
        snprintf(buf, len, "'%c'", c);
    else
        snprintf(buf, len, "byte 0x%02X", (unsigned)c & 0xFFu);
}

/* A comment runs from '#' to the end of its line. */
static int skip_comment(FILE *fp)
{
    int c;

    do {
        c = getc(fp);
    } while (c != '\n' && c != '\r' && c != EOF);
    return c;
}

/* The next character that is neither white space nor in a comment. */
static int next_token_char(FILE *fp)
{
    int c;

    for (;;) {
        c = getc(fp);
        if (c == '#')
            c = skip_comment(fp);
        if (c == EOF || !is_pnm_space(c))
            return c;
    }
}

/* Reads decimal digits starting with first (a digit); stops at the first
 * non-digit, which is returned through *stop (still consumed).  Numbers of
 * ten digits or more saturate at UINT32_MAX, which every caller rejects as
 * too big. */
static uint32_t read_digits(FILE *fp, int first, int *stop)
{
    uint32_t v = 0;
    int c = first;

    while (c >= '0' && c <= '9') {
        /* Below 10^8, v * 10 + 9 cannot wrap. */
        v = v < 100000000u ? v * 10u + (uint32_t)(c - '0') : UINT32_MAX;
        c = getc(fp);
    }
    *stop = c;
    return v;
}

/* One header field.  Like libnetpbm, the single character ending the number
 * is consumed (a comment counts as one), so a raw raster starts right after
 * it. */
static int read_header_uint(pnm_reader *rd, const char *what, uint32_t *out)
{
    char found[16];
    int c = next_token_char(rd->fp);
    int stop;

    if (c == EOF) {
        char where[64];

        snprintf(where, sizeof where, "before the %s", what);
        return rd_eof(rd, where);
    }
    if (c < '0' || c > '9') {
        describe_char(c, found, sizeof found);
        return rd_fail(rd, "bad header: the %s is not a number (found %s)", what, found);
    }
    *out = read_digits(rd->fp, c, &stop);
    if (stop == '#') {
        (void)skip_comment(rd->fp);
    } else if (stop != EOF && !is_pnm_space(stop)) {
        describe_char(stop, found, sizeof found);
        return rd_fail(rd, "bad header: the %s is followed by %s", what, found);
    }
    return 0;
}

static int check_side(pnm_reader *rd, const char *what, uint32_t v)
{
    if (v == 0)
        return rd_fail(rd, "bad header: %s 0", what);
    if (v > PNM_MAX_SIDE) {
        if (v == UINT32_MAX)
            return rd_fail(rd, "bad header: %s too large (limit %u)", what, PNM_MAX_SIDE);
        return rd_fail(rd, "bad header: %s %" PRIu32 " too large (limit %u)", what, v,
                       PNM_MAX_SIDE);
    }
    return 0;
}

typedef struct pnm_header {
    int type;          /* 1..6 */
    uint32_t width, height, maxval;
    int channels;      /* in the file: 1 or 3 */
    int plain;         /* 1 for P1..P3 */
} pnm_header;

static int read_header(pnm_reader *rd, pnm_header *h)
{
    int c1 = getc(rd->fp);
    int c2 = c1 == EOF ? EOF : getc(rd->fp);

    if (c1 == EOF) {
        if (ferror(rd->fp))
            return rd_eof(rd, "at the start");
        return rd_fail(rd, "empty file");
    }
    if (c1 != 'P' || c2 < '1' || c2 > '6')
        return rd_fail(rd, "not a PBM/PGM/PPM file (no P1..P6 magic number)");
    h->type = c2 - '0';
    h->plain = h->type <= 3;
    h->channels = (h->type == 3 || h->type == 6) ? 3 : 1;
    if (read_header_uint(rd, "width", &h->width) != 0 ||
        check_side(rd, "width", h->width) != 0 ||
        read_header_uint(rd, "height", &h->height) != 0 ||
        check_side(rd, "height", h->height) != 0)
        return -1;
    if (h->type == 1 || h->type == 4) {
        h->maxval = 1;
        return 0;
    }
    if (read_header_uint(rd, "maxval", &h->maxval) != 0)
        return -1;
    if (h->maxval == 0)
        return rd_fail(rd, "bad header: maxval 0");
    if (h->maxval > PNM_MAX_MAXVAL) {
        if (h->maxval == UINT32_MAX)
            return rd_fail(rd, "bad header: maxval too large (limit %u)", PNM_MAX_MAXVAL);
        return rd_fail(rd, "bad header: maxval %" PRIu32 " over %u", h->maxval,
                       PNM_MAX_MAXVAL);
    }
    return 0;
}

/* Bytes of raster one row takes in the file (raw formats). */
static size_t raw_row_bytes(const pnm_header *h)
{
    if (h->type == 4)
        return ((size_t)h->width + 7u) / 8u;
    return (size_t)h->width * (size_t)h->channels * (h->maxval > 255u ? 2u : 1u);
}

/* Rejects a short regular file before allocating for what its header
 * claims: a damaged 20-byte file must not make us allocate gigabytes.
 * Plain rasters need at least one byte per sample. */
static int check_length(pnm_reader *rd, const pnm_header *h)
{
    struct stat st;
    long pos;
    uint64_t need, have;

    if (fstat(fileno(rd->fp), &st) != 0 || !S_ISREG(st.st_mode))
        return 0;
    pos = ftell(rd->fp);
    if (pos < 0 || (uint64_t)st.st_size < (uint64_t)pos)
        return 0;
    have = (uint64_t)st.st_size - (uint64_t)pos;
    if (h->plain)
        need = (uint64_t)h->width * h->height * (uint64_t)h->channels;
    else
        need = (uint64_t)raw_row_bytes(h) * h->height;
    if (have < need)
        return rd_fail(rd, "truncated: the raster needs %s%" PRIu64 " bytes, the file has %" PRIu64,
                       h->plain ? "at least " : "", need, have);
    return 0;
}

static int sample_over(pnm_reader *rd, uint32_t v, const pnm_header *h, uint32_t y)
{
    return rd_fail(rd, "sample %" PRIu32 " over maxval %" PRIu32 " in row %" PRIu32, v,
                   h->maxval, y);
}

/* One row of raw raster into vals (width * channels samples, 0..maxval). */
static int read_raw_row(pnm_reader *rd, const pnm_header *h, uint32_t y, uint8_t *bytes,
                        uint16_t *vals)
{
    size_t len = raw_row_bytes(h);
    size_t n = (size_t)h->width * (size_t)h->channels;
    size_t i;

    if (fread(bytes, 1, len, rd->fp) != len) {
        char where[64];

        snprintf(where, sizeof where, "in row %" PRIu32 " of %" PRIu32, y, h->height);
        return rd_eof(rd, where);
    }
    if (h->type == 4) {
        /* Bit 1 is black: sample 0 of maxval 1. */
        for (i = 0; i < n; i++)
            vals[i] = (uint16_t)(((bytes[i >> 3] >> (7u - (i & 7u))) & 1u) ? 0u : 1u);
        return 0;
    }
    for (i = 0; i < n; i++) {
        uint32_t v = h->maxval > 255u ? ((uint32_t)bytes[2 * i] << 8) | bytes[2 * i + 1]
                                      : bytes[i];

        if (v > h->maxval)
            return sample_over(rd, v, h, y);
        vals[i] = (uint16_t)v;
    }
    return 0;
}

static int plain_stray(pnm_reader *rd, int c, uint32_t y)
{
    char found[16];

    describe_char(c, found, sizeof found);
    return rd_fail(rd, "bad raster: unexpected %s in row %" PRIu32, found, y);
}

/* One row of plain raster into vals.  Comments are accepted between
 * samples, as netpbm does. */
static int read_plain_row(pnm_reader *rd, const pnm_header *h, uint32_t y, uint16_t *vals)
{
    size_t n = (size_t)h->width * (size_t)h->channels;
    size_t i;
    char where[64];

    snprintf(where, sizeof where, "in row %" PRIu32 " of %" PRIu32, y, h->height);
    for (i = 0; i < n; i++) {
        int c = next_token_char(rd->fp);

        if (c == EOF)
            return rd_eof(rd, where);
        if (h->type == 1) {
            /* P1 digits need no separators: "0110" is four pixels. */
            if (c != '0' && c != '1')
                return plain_stray(rd, c, y);
            vals[i] = (uint16_t)(c == '1' ? 0u : 1u);
        } else {
            uint32_t v;
            int stop;

            if (c < '0' || c > '9')
                return plain_stray(rd, c, y);
            v = read_digits(rd->fp, c, &stop);
            /* The character after the number belongs to what follows. */
            if (stop != EOF)
                (void)ungetc(stop, rd->fp);
            if (v > h->maxval)
                return sample_over(rd, v, h, y);
            vals[i] = (uint16_t)v;
        }
    }
    return 0;
}

/* vals (one file row) to 8-bit output samples, rounding to nearest. */
static void convert_row(const pnm_header *h, const uint16_t *vals, int grey, uint8_t *out)
{
    uint32_t m = h->maxval;
    size_t x;

    if (grey && h->channels == 3) {
        /* Weights in thousandths: exact integers, one rounding at the end. */
        uint64_t den = 1000u * (uint64_t)m;

        for (x = 0; x < h->width; x++) {
            const uint16_t *p = vals + 3 * x;
            uint64_t y = 299u * (uint64_t)p[0] + 587u * (uint64_t)p[1] + 114u * (uint64_t)p[2];

            out[x] = (uint8_t)((y * 255u + den / 2u) / den);
        }
        return;
    }
    for (x = 0; x < (size_t)h->width * (size_t)h->channels; x++)
        out[x] = (uint8_t)(((uint32_t)vals[x] * 255u + m / 2u) / m);
}

static int read_raster(pnm_reader *rd, const pnm_header *h, stp_posix_image *img, int grey)
{
    size_t n = (size_t)h->width * (size_t)h->channels;
    size_t out_row = (size_t)h->width * (size_t)img->channels;
    uint16_t *vals = (uint16_t *)malloc(n * sizeof *vals);
    uint8_t *bytes = h->plain ? NULL : (uint8_t *)malloc(raw_row_bytes(h));
    uint32_t y;
    int rc = 0;

    if (vals == NULL || (!h->plain && bytes == NULL)) {
        rc = rd_fail(rd, "out of memory");
    } else {
        for (y = 0; y < h->height && rc == 0; y++) {
            rc = h->plain ? read_plain_row(rd, h, y, vals) : read_raw_row(rd, h, y, bytes, vals);
            if (rc == 0)
                convert_row(h, vals, grey, img->samples + (size_t)y * out_row);
        }
    }
    free(bytes);
    free(vals);
    return rc;
}

static int read_pnm(const char *path, stp_posix_image *img, int grey, char *err,
                    size_t errlen)
{
    pnm_reader rd;
    pnm_header h;
    int from_stdin;
    int rc;

    if (img != NULL)
        memset(img, 0, sizeof *img);
    if (path == NULL || *path == '\0' || img == NULL) {
        stp_posix_priv_error(err, errlen, "%s: invalid arguments to the PNM reader",
                             path != NULL && *path != '\0' ? path : "(no path)");
        return -1;
    }
    from_stdin = strcmp(path, "-") == 0;
    rd.name = from_stdin ? "stdin" : path;
    rd.err = err;
    rd.errlen = errlen;
    rd.fp = from_stdin ? stdin : fopen(path, "rb");
    if (rd.fp == NULL) {
        stp_posix_priv_error(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    memset(&h, 0, sizeof h);
    rc = read_header(&rd, &h);
    if (rc == 0)
        rc = check_length(&rd, &h);
    if (rc == 0) {
        size_t total;

        img->width = h.width;
        img->height = h.height;
        img->channels = grey ? 1 : h.channels;
        img->pnm_type = h.type;
        img->maxval = h.maxval;
        total = (size_t)h.width * (size_t)img->channels;
        if (total > SIZE_MAX / h.height) {
            rc = rd_fail(&rd, "out of memory");
        } else {
            img->samples = (uint8_t *)malloc(total * h.height);
            rc = img->samples == NULL ? rd_fail(&rd, "out of memory") : 0;
        }
    }
    if (rc == 0)
        rc = read_raster(&rd, &h, img, grey);
    if (!from_stdin)
        (void)fclose(rd.fp);
    if (rc != 0)
        stp_posix_image_free(img);
    return rc;
}

int stp_posix_read_pnm(const char *path, stp_posix_image *img, char *err, size_t errlen)
{
    return read_pnm(path, img, 0, err, errlen);
}

int stp_posix_read_grey(const char *path, stp_posix_image *img, char *err, size_t errlen)
{
    return read_pnm(path, img, 1, err, errlen);
}

void stp_posix_image_free(stp_posix_image *img)
{
    if (img == NULL)
        return;
    free(img->samples);
    memset(img, 0, sizeof *img);
}
