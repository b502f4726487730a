/* SPDX-License-Identifier: MIT */
/*
 * Runs an ATmega2560 firmware image under simavr with an SSD1306 128x64
 * panel on its SPI (simavr's own part, libsimavrparts: CS# on PB4, D/C# on
 * PB5, RES# on PB6, as ports/avr/avr_ssd1306_spi.h wires them), until the
 * firmware sleeps with interrupts off, then writes the panel's RAM as a PBM
 * (row y is page y/8, bit y%8 of each column byte; a lit pixel is white,
 * PBM 0, as in stipple's own PBM of a MONO1 frame) and compares it with an expected
 * PBM pixel for pixel.
 *
 *   avr_ssd1306_sim FIRMWARE.elf OUT.pbm [EXPECTED.pbm]
 *
 * The firmware's verdict is GPIOR0 at the end (0 = it rendered, else the
 * step that failed, ports/avr/main_atmega2560.c).  Exit 0 only when the
 * firmware reported 0 and the picture equals EXPECTED; 1 otherwise; 2 for
 * a usage or file error.  Prints the emulated cycle count.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim_avr.h"
#include "sim_elf.h"
#include "ssd1306_virt.h"

#define PANEL_W 128
#define PANEL_H 64
#define ROW_BYTES (PANEL_W / 8)
#define GPIOR0_ADDR 0x3E /* I/O 0x1E in data space */
/* A frame of teapot-s1 takes well under a billion cycles; a firmware that
 * hangs is stopped here rather than by the test's time-out. */
#define CYCLE_LIMIT 4000000000ull

static int read_pbm(const char *path, uint8_t *bits)
{
    FILE *f = fopen(path, "rb");
    int w = 0, h = 0, ok;
    if (!f) {
        perror(path);
        return -1;
    }
    ok = fscanf(f, "P4 %d %d", &w, &h) == 2 && w == PANEL_W && h == PANEL_H && fgetc(f) != EOF &&
         fread(bits, 1, ROW_BYTES * PANEL_H, f) == ROW_BYTES * PANEL_H;
    fclose(f);
    if (!ok) {
        fprintf(stderr, "%s: not a %dx%d binary PBM\n", path, PANEL_W, PANEL_H);
        return -1;
    }
    return 0;
}

static int write_pbm(const char *path, const uint8_t *bits)
{
    FILE *f = fopen(path, "wb");
    if (!f || fprintf(f, "P4\n%d %d\n", PANEL_W, PANEL_H) < 0 ||
        fwrite(bits, 1, ROW_BYTES * PANEL_H, f) != ROW_BYTES * PANEL_H || fclose(f) != 0) {
        perror(path);
        return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    elf_firmware_t fw;
    avr_t *avr;
    ssd1306_t panel;
    ssd1306_wiring_t wiring = {{'B', 4}, {'B', 5}, {'B', 6}};
    uint8_t got[ROW_BYTES * PANEL_H], want[ROW_BYTES * PANEL_H];
    int state = cpu_Running, x, y, diff = 0, verdict;

    if (argc != 3 && argc != 4) {
        fprintf(stderr, "usage: %s FIRMWARE.elf OUT.pbm [EXPECTED.pbm]\n", argv[0]);
        return 2;
    }
    memset(&fw, 0, sizeof fw);
    if (elf_read_firmware(argv[1], &fw) != 0) {
        fprintf(stderr, "%s: cannot read the ELF image\n", argv[1]);
        return 2;
    }
    avr = avr_make_mcu_by_name("atmega2560");
    if (!avr) {
        fprintf(stderr, "simavr has no atmega2560\n");
        return 2;
    }
    avr_init(avr);
    avr->frequency = 16000000;
    avr_load_firmware(avr, &fw);
    ssd1306_init(avr, &panel, PANEL_W, PANEL_H);
    ssd1306_connect(&panel, &wiring);

    while (state != cpu_Done && state != cpu_Crashed && avr->cycle < CYCLE_LIMIT)
        state = avr_run(avr);
    verdict = avr->data[GPIOR0_ADDR];
    printf("cycles: %llu\n", (unsigned long long)avr->cycle);
    if (state != cpu_Done) {
        fprintf(stderr, "%s: %s after %llu cycles\n", argv[1],
                state == cpu_Crashed ? "crashed" : "did not finish", (unsigned long long)avr->cycle);
        return 1;
    }

    memset(got, 0, sizeof got);
    for (y = 0; y < PANEL_H; y++)
        for (x = 0; x < PANEL_W; x++)
            if (!(panel.vram[y / 8][x] >> (y % 8) & 1))
                got[y * ROW_BYTES + x / 8] |= (uint8_t)(0x80 >> (x % 8));
    if (write_pbm(argv[2], got) != 0)
        return 2;
    if (verdict != 0) {
        fprintf(stderr, "%s: the firmware reported failure %d (GPIOR0)\n", argv[1], verdict);
        return 1;
    }
    if (argc == 4) {
        if (read_pbm(argv[3], want) != 0)
            return 2;
        for (y = 0; y < PANEL_H; y++)
            for (x = 0; x < PANEL_W; x++)
                diff += ((got[y * ROW_BYTES + x / 8] ^ want[y * ROW_BYTES + x / 8]) >> (7 - x % 8)) & 1;
        if (diff) {
            fprintf(stderr, "%s: %d of %d pixels differ from %s\n", argv[2], diff, PANEL_W * PANEL_H,
                    argv[3]);
            return 1;
        }
        printf("%s: equal to %s, %d pixels\n", argv[2], argv[3], PANEL_W * PANEL_H);
    }
    return 0;
}
