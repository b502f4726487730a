/* SPDX-License-Identifier: MIT */
/*
 * RISC-V (rv32imac) link check: the core and a compiled scene rendered in
 * bands to a port that discards them.  It proves the freestanding build
 * links with no C library and no soft float; it drives no device.
 */
#include <stdint.h>

#include "stp_scene_data.h"
#include "stipple/stipple.h"

#ifndef STP_FW_BAND_ROWS
#define STP_FW_BAND_ROWS 4
#endif
#define MAX_W 128u

extern uint32_t __data_load, __data_start, __data_end, __bss_start, __bss_end;
void _start(void) __attribute__((naked, noreturn, section(".text.start")));
/* used: only the start code's asm jumps here, which link-time optimisation
 * does not see */
void stp_rv32_main(void) __attribute__((noreturn, used));

void _start(void)
{
    /* gp for relaxed addressing, sp at the top of RAM, then C */
    __asm__ volatile(".option push\n\t.option norelax\n\tla gp, __global_pointer$\n\t.option pop\n\t"
                     "la sp, __stack_top\n\tj stp_rv32_main");
}

static stp_renderer_storage renderer; /* sized by STP_RENDERER_BYTES */
static uint8_t band[STP_FW_BAND_ROWS * MAX_W];
static uint16_t zbuf[STP_FW_BAND_ROWS * MAX_W];
volatile int stp_rv32_status; /* for a debugger: the render's result */

static int discard(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                   size_t stride)
{
    (void)port;
    (void)y0;
    (void)rows;
    (void)pixels;
    (void)stride;
    return 0;
}

void stp_rv32_main(void)
{
    const stp_scene_data *s = &stp_compiled_scene;
    volatile uint32_t *dst = &__data_start;
    const uint32_t *src = &__data_load;
    stp_renderer *r;
    stp_port port;
    stp_output out;
    stp_frame_memory mem;
    int status;

    while (dst < &__data_end)
        *dst++ = *src++;
    for (dst = &__bss_start; dst < &__bss_end;)
        *dst++ = 0;

    status = s->width <= MAX_W ? stp_scene_data_enter(s, &renderer, sizeof renderer, &r)
                               : STP_ERR_ARG;
    if (status == STP_OK) {
        stp_scene_data_output(s, &out);
        mem.band = band;
        mem.setup = 0; /* no per-polygon setups kept between bands */
        mem.setup_count = 0;
        mem.band_size = sizeof band;
        mem.band_rows = STP_FW_BAND_ROWS < s->height ? STP_FW_BAND_ROWS : s->height;
        mem.zbuf = zbuf;
        mem.zbuf_count = sizeof zbuf / sizeof zbuf[0];
        mem.sort = s->sort;
        mem.sort_count = s->sort_count;
        port.width = s->width;
        port.height = s->height;
        port.format = STP_PIXEL_MONO1;
        port.flush = discard;
        port.user = 0;
        status = stp_renderer_render(r, &port, &out, &mem);
    }
    stp_rv32_status = status;
    for (;;)
        __asm__ volatile("wfi");
}
