/* SPDX-License-Identifier: MIT */
/*
 * Runs an AVR firmware image under simavr at 16 MHz with an SSD1306 128x64
 * panel (simavr's own part, libsimavrparts) until the firmware sleeps with
 * interrupts off, then writes the panel's RAM as a PBM (row y is page y/8,
 * bit y%8 of each column byte; a lit pixel is white, PBM 0, as in
 * stipple's own PBM of a MONO1 frame) and compares it with an expected PBM
 * pixel for pixel.
 *
 *   avr_ssd1306_sim [-m MCU] [-b spi|i2c] [-p CS,DC,RES] [-s HEAP_START]
 *                   FIRMWARE.elf OUT.pbm [EXPECTED.pbm]
 *
 * MCU: atmega2560 (default) or atmega328p.  The panel on SPI (default;
 * CS#, D/C# and RES# as port letter and bit, default B4,B5,B6 as
 * ports/avr/avr_ssd1306_spi.h wires them) or on the TWI at address 0x3C.
 * HEAP_START (the image's __bss_end, data space: the end of .data and
 * .bss): the RAM above it is filled with a pattern before the run, and the
 * lowest byte the stack changed gives the peak RAM (static + stack).
 *
 * The firmware's verdict is GPIOR0 at the end (0 = it rendered, else the
 * step that failed).  Exit 0 only when the firmware reported 0 and the
 * picture equals EXPECTED; 1 otherwise; 2 for a usage or file error.
 * Prints the emulated cycle count and, for a firmware that marks them
 * (ports/arduino/src/stipple_sim.h: GPIOR1 written at each frame's end,
 * GPIOR2 1 while the bus transfers), the cycles of each frame with and
 * without the bus.  simavr's SPI takes ~1600 cycles a byte whatever the
 * clock divider (a real part: 16 at f/2), so the cycles "without the bus"
 * are the ones to add the real transfer time to.
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
#define GPIOR1_ADDR 0x4A /* I/O 0x2A */
#define GPIOR2_ADDR 0x4B /* I/O 0x2B */
#define MAX_FRAMES 256
#define PAINT 0xA5 /* free RAM before the run */
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

/* Frame and bus marks (stipple_sim.h) */
typedef struct marks {
    uint64_t bus_since, bus_total;
    uint64_t frame_end[MAX_FRAMES], frame_bus[MAX_FRAMES];
    int frames, bus_on;
} marks;

static void on_bus(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
    marks *m = param;
    avr->data[addr] = v;
    if (v && !m->bus_on)
        m->bus_since = avr->cycle;
    if (!v && m->bus_on)
        m->bus_total += avr->cycle - m->bus_since;
    m->bus_on = v != 0;
}

static void on_frame(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
    marks *m = param;
    avr->data[addr] = v;
    if (m->frames < MAX_FRAMES) {
        m->frame_end[m->frames] = avr->cycle;
        m->frame_bus[m->frames] = m->bus_total;
        m->frames++;
    }
}

/* Frames 1.. (frame 0 holds the set-up): each frame's cycles, without the
 * bus, and the largest. */
static void print_frames(const marks *m)
{
    uint64_t worst = 0, sum = 0;
    int k;
    for (k = 1; k < m->frames; k++) {
        uint64_t all = m->frame_end[k] - m->frame_end[k - 1];
        uint64_t bus = m->frame_bus[k] - m->frame_bus[k - 1];
        printf("frame %d: %llu cycles, %llu without the bus\n", k, (unsigned long long)all,
               (unsigned long long)(all - bus));
        worst = all - bus > worst ? all - bus : worst;
        sum += all - bus;
    }
    if (m->frames > 1)
        printf("compute cycles per frame (bus left out): mean %llu, max %llu\n",
               (unsigned long long)(sum / (uint64_t)(m->frames - 1)), (unsigned long long)worst);
}

/* "B4,B5,B6" into the wiring */
static int parse_pins(const char *s, ssd1306_wiring_t *w)
{
    char p[3];
    unsigned b[3];
    if (sscanf(s, "%c%u,%c%u,%c%u", &p[0], &b[0], &p[1], &b[1], &p[2], &b[2]) != 6 || b[0] > 7 ||
        b[1] > 7 || b[2] > 7)
        return -1;
    w->chip_select.port = p[0];
    w->chip_select.pin = (uint8_t)b[0];
    w->data_instruction.port = p[1];
    w->data_instruction.pin = (uint8_t)b[1];
    w->reset.port = p[2];
    w->reset.pin = (uint8_t)b[2];
    return 0;
}

int main(int argc, char **argv)
{
    static marks m;
    const char *mcu = "atmega2560";
    int i2c = 0;
    unsigned long heap_start = 0;
    elf_firmware_t fw;
    avr_t *avr;
    ssd1306_t panel;
    ssd1306_wiring_t wiring = {{'B', 4}, {'B', 5}, {'B', 6}};
    uint8_t got[ROW_BYTES * PANEL_H], want[ROW_BYTES * PANEL_H];
    int state = cpu_Running, x, y, diff = 0, verdict;

    while (argc > 2 && argv[1][0] == '-') {
        if (!strcmp(argv[1], "-m"))
            mcu = argv[2];
        else if (!strcmp(argv[1], "-b") && (!strcmp(argv[2], "spi") || !strcmp(argv[2], "i2c")))
            i2c = !strcmp(argv[2], "i2c");
        else if (!strcmp(argv[1], "-p") && parse_pins(argv[2], &wiring) == 0)
            ;
        else if (!strcmp(argv[1], "-s"))
            heap_start = strtoul(argv[2], 0, 0) & 0xFFFFul;
        else
            break;
        argc -= 2;
        argv += 2;
    }
    if (argc != 3 && argc != 4) {
        fprintf(stderr, "usage: avr_ssd1306_sim [-m MCU] [-b spi|i2c] [-p CS,DC,RES] FIRMWARE.elf "
                        "OUT.pbm [EXPECTED.pbm]\n");
        return 2;
    }
    memset(&fw, 0, sizeof fw);
    if (elf_read_firmware(argv[1], &fw) != 0) {
        fprintf(stderr, "%s: cannot read the ELF image\n", argv[1]);
        return 2;
    }
    avr = avr_make_mcu_by_name(mcu);
    if (!avr) {
        fprintf(stderr, "simavr has no %s\n", mcu);
        return 2;
    }
    avr_init(avr);
    avr->frequency = 16000000;
    avr_load_firmware(avr, &fw);
    ssd1306_init(avr, &panel, PANEL_W, PANEL_H);
    if (i2c)
        ssd1306_connect_twi(&panel, &wiring);
    else
        ssd1306_connect(&panel, &wiring);
    if (heap_start > avr->ioend && heap_start <= avr->ramend)
        memset(avr->data + heap_start, PAINT, avr->ramend + 1u - heap_start);
    avr_register_io_write(avr, GPIOR1_ADDR, on_frame, &m);
    avr_register_io_write(avr, GPIOR2_ADDR, on_bus, &m);

    while (state != cpu_Done && state != cpu_Crashed && avr->cycle < CYCLE_LIMIT)
        state = avr_run(avr);
    verdict = avr->data[GPIOR0_ADDR];
    printf("cycles: %llu\n", (unsigned long long)avr->cycle);
    print_frames(&m);
    if (heap_start > avr->ioend && heap_start <= avr->ramend) {
        unsigned long a = heap_start;
        while (a <= avr->ramend && avr->data[a] == PAINT)
            a++;
        printf("RAM: %lu static (.data + .bss), %lu at the peak with the stack\n",
               heap_start - (avr->ioend + 1ul), (unsigned long)avr->ramend + 1ul - (avr->ioend + 1ul) -
                                                    (a - heap_start));
    }
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
