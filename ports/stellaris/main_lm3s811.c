/* SPDX-License-Identifier: MIT */
/*
 * stipple firmware for the lm3s811evb: render the compiled scene in bands
 * onto the SSD0303 96x16 OLED (I2C), report instruction counts over
 * semihosting, exit.
 *
 * The LM3S811 has 8 KB of SRAM, 2 KB of it kept for the stack by the linker
 * script.  RAM: the renderer object (static, STP_RENDERER_BYTES of the
 * scene's minimal configuration), the scene's display file (in the generated
 * source), STP_FW_BAND_ROWS rows of MONO1 pixels and their Z-buffer rows,
 * and one 8-row page on its way to the panel.  The full library's renderer
 * alone is larger than this part's RAM: build over the scene's configuration.
 */
#include "lm3s811_oled.h"
#include "stellaris.h"
#include "stp_panel.h"
#include "stp_scene_data.h"
#include "stipple/stipple.h"

#ifndef STP_FW_BAND_ROWS
#define STP_FW_BAND_ROWS 4
#endif

#define PANEL_W 96u
#define PANEL_H 16u
#define ROW_BYTES (PANEL_W / 8u)
#define PAGE_ROWS 8u

static stp_renderer_storage renderer;

static uint8_t band[STP_FW_BAND_ROWS * ROW_BYTES];
#if STP_WITH_ZBUFFER
static uint16_t zbuf[STP_FW_BAND_ROWS * PANEL_W];
#endif
/* The page being gathered from bands that do not hold it whole (MONO1 rows),
 * and the page packed for the controller: a byte per column. */
static uint8_t page_rows[PAGE_ROWS * ROW_BYTES];
static uint8_t columns[PANEL_W];

static int send_page(uint32_t page, const uint8_t *pixels, size_t stride)
{
    return stp_panel_send_mono_page(&stp_panel_ssd0303, &stp_lm3s811_oled_bus, page, pixels,
                                    stride, PANEL_W, columns);
}

/* The controller takes 8-row pages: a page the band holds whole goes
 * straight from the band, others are gathered row by row until their last
 * row (or the panel's) has come. */
static int panel_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                       size_t stride)
{
    uint32_t r = 0;
    (void)port;
    while (r < rows) {
        uint32_t y = y0 + r;
        uint32_t in_page = y % PAGE_ROWS;
        const uint8_t *src = pixels + (size_t)r * stride;
        uint32_t i;
        if (in_page == 0 && rows - r >= PAGE_ROWS) {
            if (send_page(y / PAGE_ROWS, src, stride) != 0)
                return -1;
            r += PAGE_ROWS;
            continue;
        }
        for (i = 0; i < ROW_BYTES; i++)
            page_rows[in_page * ROW_BYTES + i] = src[i];
        if ((in_page == PAGE_ROWS - 1u || y == PANEL_H - 1u) &&
            send_page(y / PAGE_ROWS, page_rows, ROW_BYTES) != 0)
            return -1;
        r++;
    }
    return 0;
}

static int discard_flush(stp_port *port, uint32_t y0, uint32_t rows, const uint8_t *pixels,
                         size_t stride)
{
    (void)port;
    (void)y0;
    (void)rows;
    (void)pixels;
    (void)stride;
    return 0;
}

/* UART0 (PA0/PA1; a PL011 at 0x4000C000), receive only. */
#define UART0 0x4000C000u
#define UART_DR STP_REG(UART0 + 0x000u)
#define UART_FR STP_REG(UART0 + 0x018u)
#define UART_IBRD STP_REG(UART0 + 0x024u)
#define UART_FBRD STP_REG(UART0 + 0x028u)
#define UART_LCRH STP_REG(UART0 + 0x02Cu)
#define UART_CTL STP_REG(UART0 + 0x030u)
#define UART_FR_RXFE 0x10u

/* Hold the picture until a byte arrives on UART0, then return: a test
 * harness takes its screendump first and then sends the byte, so the
 * firmware's own exit status still ends QEMU.  (QEMU gives this board no
 * keys; the lm3s6965evb's firmware waits for its "up" key instead.) */
static void wait_for_byte(void)
{
    STP_SYSCTL_RCGC1 |= 1u << 0; /* UART0 */
    STP_SYSCTL_RCGC2 |= 1u << 0; /* GPIO A */
    STP_GPIO_AFSEL(STP_GPIO_A) |= 0x03u;
    STP_GPIO_DEN(STP_GPIO_A) |= 0x03u;
    UART_CTL = 0;
    /* 115200 8N1 from the 6 MHz system clock: 6e6 / (16 x 115200) = 3 + 16/64 */
    UART_IBRD = 3;
    UART_FBRD = 16;
    UART_LCRH = 0x60u;  /* 8 bits, no FIFO */
    UART_CTL = 0x301u;  /* enable, transmit, receive */
    stp_semihost_write("stipple: frame done; send a byte on UART0 to finish\n");
    while (UART_FR & UART_FR_RXFE)
        ;
    (void)UART_DR;
}

static void report(const char *what, uint64_t count)
{
    char num[12];
    stp_semihost_write("stipple: ");
    stp_semihost_write(what);
    stp_semihost_write(" ");
    stp_semihost_write(stp_utoa(count > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)count, num));
    stp_semihost_write("\n");
}

static int fail(const char *what, int status)
{
    stp_semihost_write("stipple: ");
    stp_semihost_write(what);
    stp_semihost_write(": ");
    stp_semihost_write(stp_status_text(status));
    stp_semihost_write("\n");
    return 1;
}

int main(void)
{
    const stp_scene_data *scene = &stp_compiled_scene;
    stp_renderer *r;
    stp_port port;
    stp_output out;
    stp_frame_memory mem;
    uint64_t t0, t1, t2, t3, t4;
    uint32_t per_tick;
    int status;

    stp_count_start();
    per_tick = stp_count_calibrate();
    if (scene->width != PANEL_W || scene->height != PANEL_H)
        return fail("scene size (compile it with -s 96x16)", STP_ERR_ARG);

    t0 = stp_count_now();
    status = stp_scene_data_enter(scene, &renderer, sizeof renderer, &r);
    t1 = stp_count_now();
    if (status != STP_OK)
        return fail("enter", status);

    stp_scene_data_output(scene, &out);
    mem.band = band;
    mem.band_size = sizeof band;
    mem.band_rows = STP_FW_BAND_ROWS;
#if STP_WITH_ZBUFFER
    mem.zbuf = zbuf;
    mem.zbuf_count = sizeof zbuf / sizeof zbuf[0];
#else
    mem.zbuf = 0;
    mem.zbuf_count = 0;
#endif
    mem.sort = scene->sort;
    mem.sort_count = scene->sort_count;

    port.width = PANEL_W;
    port.height = PANEL_H;
    port.format = STP_PIXEL_MONO1;
    port.user = 0;

    /* the frame through the core alone, the panel's transfer left out */
    port.flush = discard_flush;
    status = stp_renderer_render(r, &port, &out, &mem);
    t2 = stp_count_now();
    if (status != STP_OK)
        return fail("render", status);

    stp_lm3s811_oled_setup();
    if (stp_panel_init(&stp_panel_ssd0303, &stp_lm3s811_oled_bus) != 0)
        return fail("panel", STP_ERR_PORT);
    t3 = stp_count_now();
    port.flush = panel_flush;
    status = stp_renderer_render(r, &port, &out, &mem);
    if (status != STP_OK)
        return fail("render to panel", status);

    t4 = stp_count_now();
    report("instructions per SysTick tick:", per_tick);
    report("instructions to enter the scene:", (t1 - t0) * per_tick);
    report("instructions per frame (core):", (t2 - t1) * per_tick);
    report("instructions per frame (core + panel):", (t4 - t3) * per_tick);
    report("band rows:", STP_FW_BAND_ROWS);
    report("renderer bytes:", stp_renderer_size());
    report("display-file entries:", stp_renderer_display_file_used(r));
    wait_for_byte();
    return 0;
}
