/* SPDX-License-Identifier: MIT */
/*
 * compare_screendump DUMP.ppm HOST.pbm [SCALE]
 *
 * Checks a QEMU screendump of a grey OLED against stipple's 1-bit render:
 * each panel pixel is a SCALE x SCALE block (QEMU's SSD0323 draws 4x4) whose
 * R, G and B are all 255 where the render is ON (PBM 0: stipple's PBM
 * writer inverts, PBM 1 is black) and 0 where it is OFF: the firmware sends
 * ON as grey 15, which QEMU shows as 15 x 17.  Prints the first differences;
 * exit 0 when every pixel matches, 1 otherwise, 2 on a bad file.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Read a PNM header: magic, width, height and (not for P4) maxval. */
static int read_header(FILE *f, char magic[3], long *w, long *h, long *maxval)
{
    int c;
    long *fields[3];
    int i, nfields;
    if (fscanf(f, "%2s", magic) != 1)
        return -1;
    fields[0] = w;
    fields[1] = h;
    fields[2] = maxval;
    nfields = strcmp(magic, "P4") == 0 ? 2 : 3;
    for (i = 0; i < nfields; i++) {
        for (;;) {
            c = fgetc(f);
            if (c == '#') {
                while (c != '\n' && c != EOF)
                    c = fgetc(f);
            } else if (c != ' ' && c != '\t' && c != '\n' && c != '\r') {
                break;
            }
        }
        if (c == EOF)
            return -1;
        ungetc(c, f);
        if (fscanf(f, "%ld", fields[i]) != 1)
            return -1;
    }
    fgetc(f); /* the single whitespace before the raster */
    return 0;
}

int main(int argc, char **argv)
{
    FILE *fd, *fh;
    char m1[3], m2[3];
    long dw, dh, dmax, hw, hh, hmax = 1, scale = 4, x, y, bad = 0;
    unsigned char *dump, *pbm;
    size_t dsize, hstride;
    if (argc < 3 || argc > 4) {
        fprintf(stderr, "usage: compare_screendump DUMP.ppm HOST.pbm [SCALE]\n");
        return 2;
    }
    if (argc == 4)
        scale = strtol(argv[3], 0, 10);
    fd = fopen(argv[1], "rb");
    fh = fopen(argv[2], "rb");
    if (!fd || !fh || read_header(fd, m1, &dw, &dh, &dmax) || read_header(fh, m2, &hw, &hh, &hmax) ||
        strcmp(m1, "P6") || strcmp(m2, "P4") || dmax != 255 || scale < 1) {
        fprintf(stderr, "compare_screendump: want a P6 dump and a P4 render\n");
        return 2;
    }
    if (dw != hw * scale || dh != hh * scale) {
        fprintf(stderr, "compare_screendump: dump %ldx%ld is not %ld x the render's %ldx%ld\n", dw,
                dh, scale, hw, hh);
        return 1;
    }
    dsize = (size_t)dw * (size_t)dh * 3;
    hstride = ((size_t)hw + 7) / 8;
    dump = malloc(dsize);
    pbm = malloc(hstride * (size_t)hh);
    if (!dump || !pbm || fread(dump, 1, dsize, fd) != dsize ||
        fread(pbm, 1, hstride * (size_t)hh, fh) != hstride * (size_t)hh) {
        fprintf(stderr, "compare_screendump: short file\n");
        return 2;
    }
    for (y = 0; y < dh; y++) {
        for (x = 0; x < dw; x++) {
            long px = x / scale, py = y / scale;
            int black = (pbm[(size_t)py * hstride + (size_t)(px / 8)] >> (7 - px % 8)) & 1;
            int want = black ? 0 : 255;
            const unsigned char *p = dump + ((size_t)y * (size_t)dw + (size_t)x) * 3;
            if (p[0] != want || p[1] != want || p[2] != want) {
                if (bad < 10 && x % scale == 0 && y % scale == 0)
                    fprintf(stderr, "panel pixel (%ld, %ld): dump %d,%d,%d, render wants %d\n", px,
                            py, p[0], p[1], p[2], want);
                bad++;
            }
        }
    }
    free(dump);
    free(pbm);
    fclose(fd);
    fclose(fh);
    if (bad) {
        fprintf(stderr, "compare_screendump: %ld dump pixels differ\n", bad);
        return 1;
    }
    printf("compare_screendump: %ldx%ld panel pixels match\n", hw, hh);
    return 0;
}
