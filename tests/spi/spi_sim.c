/* SPDX-License-Identifier: MIT */
/* The emulated SPI panels (see spi_sim.h). */
#include "spi_sim.h"

#include <errno.h>
#include <stddef.h>
#include <string.h>
#include <time.h>

#include <linux/spi/spidev.h>
#include <sys/ioctl.h>

enum { SH_MODE, SH_ADDR, SH_DATA, SH_LINE_TRAILER, SH_TAIL, SH_HOLD };

static void violation(spi_sim *sim, const char *fmt, ...) G_GNUC_PRINTF(2, 3);
static void violation(spi_sim *sim, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    if (sim->violations->len < 50)
        g_ptr_array_add(sim->violations, g_strdup_vprintf(fmt, ap));
    va_end(ap);
}

static guint32 noise(guint32 *state)
{
    *state = *state * 1664525u + 1013904223u;
    return *state >> 24;
}

static int busy(spi_sim *sim)
{
    return sim->busy_stuck || g_get_monotonic_time() < sim->busy_until;
}

static void set_busy(spi_sim *sim, guint ms)
{
    sim->busy_until = g_get_monotonic_time() + (gint64)ms * 1000;
}

static void glass_set(spi_sim *sim, guint x, guint y, int on)
{
    guint8 *b = sim->glass + (gsize)y * sim->stride + x / 8;
    if (on)
        *b = (guint8)(*b | (0x80u >> (x % 8)));
    else
        *b = (guint8)(*b & ~(0x80u >> (x % 8)));
}

/* ---------------------------------------------------------------- SSD1306 */

static void oled_defaults(spi_sim *sim)
{
    /* the datasheet's reset values */
    sim->oled.mode = 2;
    sim->oled.col = sim->oled.page = 0;
    sim->oled.col_start = 0;
    sim->oled.col_end = 127;
    sim->oled.page_start = 0;
    sim->oled.page_end = 7;
    sim->oled.display_on = 0;
    sim->oled.charge_pump = 0;
    sim->oled.remap = sim->oled.com_reverse = sim->oled.inverse = sim->oled.all_on = 0;
    sim->oled.start_line = sim->oled.offset = 0;
    sim->oled.mux = 63;
    sim->oled.cmd_len = sim->oled.cmd_need = 0;
}

/* Parameter bytes after a command byte, or -1 for one the emulation does not know. */
static int oled_params(guint8 c)
{
    if (c <= 0x1F || (c >= 0x40 && c <= 0x7F) || (c >= 0xB0 && c <= 0xB7))
        return 0;
    switch (c) {
    case 0x20: case 0x81: case 0x8D: case 0xA8: case 0xD3: case 0xD5: case 0xD9: case 0xDA:
    case 0xDB:
        return 1;
    case 0x21: case 0x22: case 0xA3:
        return 2;
    case 0x26: case 0x27:
        return 6;
    case 0x29: case 0x2A:
        return 5;
    case 0x2E: case 0x2F: case 0xA0: case 0xA1: case 0xA4: case 0xA5: case 0xA6: case 0xA7:
    case 0xAE: case 0xAF: case 0xC0: case 0xC8: case 0xE3:
        return 0;
    }
    return -1;
}

static void oled_execute(spi_sim *sim)
{
    const guint8 *p = sim->oled.cmd;
    guint8 c = p[0];
    if (c <= 0x0F) {
        sim->oled.col = (sim->oled.col & 0xF0u) | c;
    } else if (c <= 0x1F) {
        sim->oled.col = (sim->oled.col & 0x0Fu) | (guint)(c & 0x0F) << 4;
        if (sim->oled.col > 127)
            violation(sim, "SSD1306: column %u past 127", sim->oled.col);
    } else if (c >= 0x40 && c <= 0x7F) {
        sim->oled.start_line = c & 63u;
    } else if (c >= 0xB0 && c <= 0xB7) {
        sim->oled.page = c & 7u;
    } else {
        switch (c) {
        case 0x20:
            if ((p[1] & 3u) == 3u)
                violation(sim, "SSD1306: addressing mode 3 is invalid");
            sim->oled.mode = p[1] & 3u;
            break;
        case 0x21:
            sim->oled.col_start = p[1] & 127u;
            sim->oled.col_end = p[2] & 127u;
            sim->oled.col = sim->oled.col_start;
            break;
        case 0x22:
            sim->oled.page_start = p[1] & 7u;
            sim->oled.page_end = p[2] & 7u;
            sim->oled.page = sim->oled.page_start;
            break;
        case 0x8D:
            sim->oled.charge_pump = (p[1] & 0x04u) != 0;
            break;
        case 0xA0: case 0xA1:
            sim->oled.remap = c & 1;
            break;
        case 0xA4: case 0xA5:
            sim->oled.all_on = c & 1;
            break;
        case 0xA6: case 0xA7:
            sim->oled.inverse = c & 1;
            break;
        case 0xA8:
            sim->oled.mux = p[1] & 63u;
            break;
        case 0xAE: case 0xAF:
            sim->oled.display_on = c & 1;
            break;
        case 0xC0: case 0xC8:
            sim->oled.com_reverse = (c & 8) != 0;
            break;
        case 0xD3:
            sim->oled.offset = p[1] & 63u;
            break;
        case 0x26: case 0x27: case 0x29: case 0x2A: case 0x2F: case 0xA3:
            violation(sim, "SSD1306: scrolling (0x%02X) is not modelled", c);
            break;
        default: /* timing, contrast, pins: no effect on the picture here */
            break;
        }
    }
}

static void oled_command_byte(spi_sim *sim, guint8 b)
{
    if (sim->oled.cmd_len == 0) {
        int need = oled_params(b);
        if (need < 0) {
            violation(sim, "SSD1306: unknown command 0x%02X", b);
            return;
        }
        sim->oled.cmd[0] = b;
        sim->oled.cmd_len = 1;
        sim->oled.cmd_need = (guint)need;
    } else {
        sim->oled.cmd[sim->oled.cmd_len++] = b;
    }
    if (sim->oled.cmd_len == sim->oled.cmd_need + 1u) {
        oled_execute(sim);
        sim->oled.cmd_len = 0;
    }
}

static void oled_data_byte(spi_sim *sim, guint8 b)
{
    if (sim->oled.cmd_len != 0) {
        violation(sim, "SSD1306: data while command 0x%02X waits for parameters", sim->oled.cmd[0]);
        sim->oled.cmd_len = 0;
    }
    sim->oled.ram[sim->oled.page][sim->oled.col] = b;
    switch (sim->oled.mode) {
    case 2: /* page: the column wraps, the page stays */
        sim->oled.col = sim->oled.col >= 127 ? 0 : sim->oled.col + 1;
        break;
    case 0: /* horizontal */
        if (sim->oled.col >= sim->oled.col_end) {
            sim->oled.col = sim->oled.col_start;
            sim->oled.page = sim->oled.page >= sim->oled.page_end ? sim->oled.page_start
                                                                  : sim->oled.page + 1;
        } else {
            sim->oled.col++;
        }
        break;
    default: /* vertical */
        if (sim->oled.page >= sim->oled.page_end) {
            sim->oled.page = sim->oled.page_start;
            sim->oled.col = sim->oled.col >= sim->oled.col_end ? sim->oled.col_start
                                                               : sim->oled.col + 1;
        } else {
            sim->oled.page++;
        }
        break;
    }
}

/* What the module shows.  Its wiring: x = 0 is SEG127, y = 0 is COM63. */
static void oled_show(spi_sim *sim)
{
    guint x, y;
    if (sim->oled.start_line || sim->oled.offset || sim->oled.mux != 63)
        violation(sim, "SSD1306: start line %u, offset %u, multiplex %u not modelled",
                  sim->oled.start_line, sim->oled.offset, sim->oled.mux + 1);
    for (y = 0; y < 64; y++)
        for (x = 0; x < 128; x++) {
            guint com = 63 - y, seg = 127 - x;
            guint row = sim->oled.com_reverse ? 63 - com : com;
            guint col = sim->oled.remap ? 127 - seg : seg;
            int bit = (sim->oled.ram[row / 8][col] >> (row % 8)) & 1;
            int lit = sim->oled.display_on && sim->oled.charge_pump &&
                      (sim->oled.all_on || (bit ^ sim->oled.inverse));
            glass_set(sim, x, y, lit);
        }
}

/* ---------------------------------------------------------------- Sharp */

static void sharp_frame_begin(spi_sim *sim)
{
    sim->sharp.state = SH_MODE;
    sim->sharp.acc = sim->sharp.nbits = 0;
    sim->sharp.lines_in_frame = 0;
    sim->sharp.tail_bits = 0;
}

static void sharp_bit(spi_sim *sim, int bit)
{
    switch (sim->sharp.state) {
    case SH_MODE:
        sim->sharp.acc |= (guint)bit << sim->sharp.nbits; /* M0 first */
        if (++sim->sharp.nbits < 8)
            return;
        sim->sharp.m0 = sim->sharp.acc & 1;
        sim->sharp.m1 = (sim->sharp.acc >> 1) & 1;
        sim->sharp.m2 = (sim->sharp.acc >> 2) & 1;
        sim->sharp.acc = sim->sharp.nbits = 0;
        if (!sim->extmode) {
            if (sim->last_m1 >= 0 && sim->sharp.m1 != sim->last_m1)
                sim->m1_changes++;
            sim->last_m1 = sim->sharp.m1;
        }
        if (sim->sharp.m0 && sim->sharp.m2) {
            violation(sim, "LS013B7DH03: M0 and M2 both set");
            sim->sharp.state = SH_HOLD;
        } else if (sim->sharp.m2) {
            memset(sim->sharp.mem, 0xFF, sizeof sim->sharp.mem); /* all clear: white */
            sim->sharp.state = SH_HOLD;
        } else if (sim->sharp.m0) {
            sim->sharp.state = SH_ADDR;
        } else {
            sim->vcom_commands++;
            sim->sharp.state = SH_HOLD;
        }
        return;
    case SH_ADDR:
        sim->sharp.acc |= (guint)bit << sim->sharp.nbits; /* AG0 first */
        if (++sim->sharp.nbits < 8)
            return;
        sim->sharp.address = sim->sharp.acc;
        sim->sharp.acc = sim->sharp.nbits = 0;
        if (sim->sharp.address == 0) {
            if (sim->sharp.lines_in_frame == 0)
                violation(sim, "LS013B7DH03: a write with no line");
            sim->sharp.state = SH_TAIL;
            sim->sharp.tail_bits = 8;
        } else if (sim->sharp.address > 128) {
            violation(sim, "LS013B7DH03: gate line address %u out of 1..128", sim->sharp.address);
            sim->sharp.state = SH_TAIL;
        } else {
            sim->sharp.state = SH_DATA;
            sim->sharp.data_bits = 0;
            memset(sim->sharp.line, 0, sizeof sim->sharp.line);
        }
        return;
    case SH_DATA: {
        guint x = sim->sharp.data_bits++; /* D1 first: pixel 0 */
        if (bit)
            sim->sharp.line[x / 8] = (guint8)(sim->sharp.line[x / 8] | (0x80u >> (x % 8)));
        if (sim->sharp.data_bits == 128) {
            sim->sharp.state = SH_LINE_TRAILER;
            sim->sharp.nbits = 0;
        }
        return;
    }
    case SH_LINE_TRAILER:
        if (++sim->sharp.nbits < 8)
            return;
        sim->sharp.nbits = 0;
        memcpy(sim->sharp.mem[sim->sharp.address - 1], sim->sharp.line, 16);
        sim->sharp.lines_in_frame++;
        sim->lines_written++;
        sim->sharp.state = SH_ADDR;
        return;
    case SH_TAIL:
    case SH_HOLD:
        sim->sharp.tail_bits++;
        return;
    }
}

static void sharp_frame_end(spi_sim *sim)
{
    switch (sim->sharp.state) {
    case SH_MODE:
        if (sim->sharp.nbits)
            violation(sim, "LS013B7DH03: chip select dropped inside the mode byte");
        break;
    case SH_ADDR:
        violation(sim, "LS013B7DH03: write ends after %u lines without the final 8 dummy bits",
                  sim->sharp.lines_in_frame);
        break;
    case SH_DATA:
    case SH_LINE_TRAILER:
        violation(sim, "LS013B7DH03: chip select dropped inside line %u", sim->sharp.address);
        break;
    case SH_HOLD:
        if (sim->sharp.tail_bits < 8)
            violation(sim, "LS013B7DH03: command without its 8 dummy bits");
        break;
    default:
        break;
    }
    sim->sharp.state = SH_MODE;
}

static void sharp_show(spi_sim *sim)
{
    guint y;
    for (y = 0; y < 128; y++)
        memcpy(sim->glass + (gsize)y * sim->stride, sim->sharp.mem[y], 16);
}

/* ---------------------------------------------------------------- SSD1680 */

static void epd_defaults(spi_sim *sim)
{
    sim->epd.cmd = -1;
    sim->epd.nparam = 0;
    sim->epd.entry = 3;
    sim->epd.xs = 0;
    sim->epd.xe = SIM_EPD_RAM_X - 1;
    sim->epd.ys = 0;
    sim->epd.ye = SIM_EPD_RAM_Y - 1;
    sim->epd.xc = sim->epd.yc = 0;
    sim->epd.gates = SIM_EPD_RAM_Y - 1;
    sim->epd.gate_flags = 0;
    sim->epd.ctrl1a = sim->epd.ctrl1b = 0;
    sim->epd.ctrl2 = 0xFF;
    sim->epd.border = 0xC0;
    sim->epd.deep_sleep = 0;
}

/* Parameter bytes of a command; -2 for RAM writes (any count), -1 unknown. */
static int epd_params(guint8 c)
{
    switch (c) {
    case 0x12: case 0x20:
        return 0;
    case 0x03: case 0x10: case 0x11: case 0x14: case 0x18: case 0x22: case 0x2C: case 0x3C:
    case 0x3F: case 0x4E:
        return 1;
    case 0x1A: case 0x21: case 0x44: case 0x4F:
        return 2;
    case 0x01: case 0x04:
        return 3;
    case 0x0C: case 0x45:
        return 4;
    case 0x24: case 0x26: case 0x32:
        return -2;
    }
    return -1;
}

static void epd_show(spi_sim *sim)
{
    guint x, y;
    if (sim->epd.gates + 1u < sim->height)
        violation(sim, "SSD1680: driver output control drives %u gates, the glass has %u",
                  sim->epd.gates + 1u, sim->height);
    for (y = 0; y < sim->height; y++)
        for (x = 0; x < sim->width; x++) {
            guint ry = (sim->epd.gate_flags & 1u) ? sim->epd.gates - y : y;
            int bit = (sim->epd.bw[ry][x / 8] >> (7 - x % 8)) & 1;
            switch (sim->epd.ctrl1a & 0x0Fu) {
            case 0x4: bit = 0; break;
            case 0x8: bit = !bit; break;
            default: break;
            }
            glass_set(sim, x, y, bit);
        }
}

static void epd_execute(spi_sim *sim)
{
    const guint8 *p = sim->epd.param;
    switch (sim->epd.cmd) {
    case 0x01:
        sim->epd.gates = p[0] | (guint)(p[1] & 1u) << 8;
        sim->epd.gate_flags = p[2] & 7u;
        break;
    case 0x10:
        sim->epd.deep_sleep = (p[0] & 3u) != 0;
        break;
    case 0x11:
        sim->epd.entry = p[0] & 7u;
        break;
    case 0x12:
        epd_defaults(sim);
        sim->epd.swresets++;
        set_busy(sim, sim->swreset_busy_ms);
        if (sim->stuck_busy_after == 0x12)
            sim->busy_stuck = 1;
        break;
    case 0x20:
        if (sim->epd.ctrl2 & 0x04u) {
            if ((sim->epd.ctrl2 & 0xD0u) != 0xD0u)
                violation(sim, "SSD1680: display update 0x22 0x%02X without clock, analog "
                          "or waveform load", sim->epd.ctrl2);
            epd_show(sim);
            sim->refreshes++;
        }
        set_busy(sim, sim->refresh_busy_ms);
        if (sim->stuck_busy_after == 0x20)
            sim->busy_stuck = 1;
        break;
    case 0x21:
        sim->epd.ctrl1a = p[0];
        sim->epd.ctrl1b = p[1];
        break;
    case 0x22:
        sim->epd.ctrl2 = p[0];
        break;
    case 0x3C:
        sim->epd.border = p[0];
        break;
    case 0x44:
        sim->epd.xs = p[0] & 0x3Fu;
        sim->epd.xe = p[1] & 0x3Fu;
        break;
    case 0x45:
        sim->epd.ys = p[0] | (guint)(p[1] & 1u) << 8;
        sim->epd.ye = p[2] | (guint)(p[3] & 1u) << 8;
        break;
    case 0x4E:
        sim->epd.xc = p[0] & 0x3Fu;
        break;
    case 0x4F:
        sim->epd.yc = p[0] | (guint)(p[1] & 1u) << 8;
        break;
    default: /* voltages, temperature, LUT: no effect on the picture here */
        break;
    }
}

static void epd_step(guint *counter, guint start, guint end, int increment, int *wrapped)
{
    *wrapped = *counter == end;
    if (*wrapped)
        *counter = start;
    else
        *counter = increment ? *counter + 1 : *counter - 1;
}

static void epd_ram_write(spi_sim *sim, guint8 b)
{
    int wrapped;
    int x_inc = sim->epd.entry & 1u, y_inc = (sim->epd.entry >> 1) & 1u;
    if (sim->epd.xc >= SIM_EPD_RAM_X || sim->epd.yc >= SIM_EPD_RAM_Y) {
        violation(sim, "SSD1680: RAM write at X %u, Y %u, outside the RAM", sim->epd.xc,
                  sim->epd.yc);
        return;
    }
    if (sim->epd.cmd == 0x24)
        sim->epd.bw[sim->epd.yc][sim->epd.xc] = b;
    else
        sim->epd.red[sim->epd.yc][sim->epd.xc] = b;
    if (!(sim->epd.entry & 4u)) { /* X first */
        epd_step(&sim->epd.xc, sim->epd.xs, sim->epd.xe, x_inc, &wrapped);
        if (wrapped)
            epd_step(&sim->epd.yc, sim->epd.ys, sim->epd.ye, y_inc, &wrapped);
    } else {
        epd_step(&sim->epd.yc, sim->epd.ys, sim->epd.ye, y_inc, &wrapped);
        if (wrapped)
            epd_step(&sim->epd.xc, sim->epd.xs, sim->epd.xe, x_inc, &wrapped);
    }
}

static void epd_byte(spi_sim *sim, guint8 b, int data)
{
    if (sim->epd.deep_sleep) {
        violation(sim, "SSD1680: %s 0x%02X in deep sleep (only a hardware reset wakes it)",
                  data ? "data" : "command", b);
        return;
    }
    if (busy(sim)) {
        violation(sim, "SSD1680: %s 0x%02X while BUSY", data ? "data" : "command", b);
        return;
    }
    if (!data) {
        int need = epd_params(b);
        int old = epd_params((guint8)sim->epd.cmd);
        if (sim->epd.cmd >= 0 && old >= 0 && sim->epd.nparam < (guint)old)
            violation(sim, "SSD1680: command 0x%02X got %u of its %d parameters", sim->epd.cmd,
                      sim->epd.nparam, old);
        if (need == -1) {
            violation(sim, "SSD1680: unknown command 0x%02X", b);
            sim->epd.cmd = -1;
            return;
        }
        sim->epd.cmd = b;
        sim->epd.nparam = 0;
        if (need == 0)
            epd_execute(sim);
        return;
    }
    if (sim->epd.cmd < 0) {
        violation(sim, "SSD1680: data 0x%02X with no command", b);
        return;
    }
    if (sim->epd.cmd == 0x24 || sim->epd.cmd == 0x26) {
        epd_ram_write(sim, b);
        return;
    }
    if (sim->epd.cmd == 0x32)
        return; /* a LUT: taken, not modelled */
    if (sim->epd.nparam >= (guint)epd_params((guint8)sim->epd.cmd)) {
        violation(sim, "SSD1680: extra parameter 0x%02X for command 0x%02X", b, sim->epd.cmd);
        return;
    }
    sim->epd.param[sim->epd.nparam++] = b;
    if (sim->epd.nparam == (guint)epd_params((guint8)sim->epd.cmd))
        epd_execute(sim);
}

/* ---------------------------------------------------------------- the bus */

static int cs_active_high_wanted(spi_sim *sim)
{
    return sim->panel == SPI_SIM_SHARP;
}

/* Checks the bus set-up for a message; 0 if the panel can read it. */
static int bus_ok(spi_sim *sim)
{
    guint cpol_cpha = sim->mode & 3u;
    if (((sim->mode & SPI_CS_HIGH) != 0) != cs_active_high_wanted(sim)) {
        violation(sim, "chip select is active %s, the panel's is active %s",
                  (sim->mode & SPI_CS_HIGH) ? "high" : "low",
                  cs_active_high_wanted(sim) ? "high" : "low");
        return -1;
    }
    if (sim->panel == SPI_SIM_SHARP ? cpol_cpha != 0 : (cpol_cpha != 0 && cpol_cpha != 3)) {
        violation(sim, "SPI mode %u: the panel reads data on a rising clock edge", cpol_cpha);
        return -1;
    }
    if (sim->bits != 8 && sim->bits != 0) {
        violation(sim, "%u bits per word", sim->bits);
        return -1;
    }
    return 0;
}

static void frame_begin(spi_sim *sim)
{
    if (sim->panel == SPI_SIM_SHARP)
        sharp_frame_begin(sim);
}

static void frame_end(spi_sim *sim)
{
    if (sim->panel == SPI_SIM_SHARP) {
        sharp_frame_end(sim);
        sharp_show(sim);
    } else if (sim->panel == SPI_SIM_SSD1306) {
        oled_show(sim);
    }
}

static guint8 reverse8(guint8 v)
{
    guint8 r = 0;
    int i;
    for (i = 0; i < 8; i++)
        r = (guint8)(r | (((v >> i) & 1u) << (7 - i)));
    return r;
}

/* One byte as the panel reads it: wire bits first to last. */
static void panel_byte(spi_sim *sim, guint8 memory_byte)
{
    guint8 wire = (sim->mode & SPI_LSB_FIRST) ? reverse8(memory_byte) : memory_byte;
    int i;
    if (sim->reset_low) {
        violation(sim, "SPI byte 0x%02X while RESET is asserted", memory_byte);
        return;
    }
    switch (sim->panel) {
    case SPI_SIM_SSD1306:
        if (sim->dc)
            oled_data_byte(sim, wire);
        else
            oled_command_byte(sim, wire);
        break;
    case SPI_SIM_SSD1680:
        epd_byte(sim, wire, sim->dc);
        break;
    case SPI_SIM_SHARP:
        for (i = 7; i >= 0; i--)
            sharp_bit(sim, (wire >> i) & 1);
        break;
    }
}

static void handle_message(spi_sim *sim, UMockdevIoctlClient *client, UMockdevIoctlData *arg,
                           gulong request)
{
    gsize size = _IOC_SIZE(request), total = 0, i, n;
    UMockdevIoctlData *xd;
    struct spi_ioc_transfer *x;
    GError *error = NULL;
    if (size % sizeof(struct spi_ioc_transfer) != 0) {
        umockdev_ioctl_client_complete(client, -1, EINVAL);
        return;
    }
    n = size / sizeof(struct spi_ioc_transfer);
    if (n == 0) {
        umockdev_ioctl_client_complete(client, 0, 0);
        return;
    }
    xd = umockdev_ioctl_data_resolve(arg, 0, size, &error);
    if (!xd) {
        g_clear_error(&error);
        umockdev_ioctl_client_complete(client, -1, EFAULT);
        return;
    }
    x = (struct spi_ioc_transfer *)xd->data;
    for (i = 0; i < n; i++)
        total += x[i].len;
    if (total > sim->bufsiz) {
        sim->oversize++;
        umockdev_ioctl_client_complete(client, -1, EMSGSIZE);
        g_object_unref(xd);
        return;
    }
    if (sim->fail_after && sim->bytes + total > sim->fail_after) {
        sim->failed++;
        umockdev_ioctl_client_complete(client, -1, EIO);
        g_object_unref(xd);
        return;
    }
    sim->messages++;
    if (total > sim->max_message)
        sim->max_message = (guint)total;
    if (bus_ok(sim) != 0) {
        umockdev_ioctl_client_complete(client, (glong)total, 0);
        g_object_unref(xd);
        return;
    }
    frame_begin(sim);
    for (i = 0; i < n; i++) {
        guint32 speed = x[i].speed_hz ? x[i].speed_hz : sim->max_speed_hz;
        UMockdevIoctlData *tx = NULL;
        gsize k;
        sim->transfers++;
        if (sim->speed_min == 0 || speed < sim->speed_min)
            sim->speed_min = speed;
        if (speed > sim->speed_max)
            sim->speed_max = speed;
        if (x[i].bits_per_word != 0 && x[i].bits_per_word != 8)
            violation(sim, "transfer with %u bits per word", x[i].bits_per_word);
        if (x[i].len == 0)
            continue;
        if (x[i].tx_buf) {
            tx = umockdev_ioctl_data_resolve(xd, i * sizeof(struct spi_ioc_transfer) +
                                                     offsetof(struct spi_ioc_transfer, tx_buf),
                                             x[i].len, &error);
            if (!tx) {
                g_clear_error(&error);
                frame_end(sim);
                umockdev_ioctl_client_complete(client, -1, EFAULT);
                g_object_unref(xd);
                return;
            }
        }
        for (k = 0; k < x[i].len; k++)
            panel_byte(sim, tx ? tx->data[k] : 0);
        if (tx)
            g_object_unref(tx);
        if (x[i].cs_change && i + 1 < n) {
            frame_end(sim);
            frame_begin(sim);
        }
    }
    frame_end(sim);
    sim->bytes += total;
    umockdev_ioctl_client_complete(client, (glong)total, 0);
    g_object_unref(xd);
}

static gboolean handle_ioctl(UMockdevIoctlBase *handler, UMockdevIoctlClient *client,
                             gpointer user_data)
{
    spi_sim *sim = user_data;
    gulong request = umockdev_ioctl_client_get_request(client);
    UMockdevIoctlData *arg = umockdev_ioctl_client_get_arg(client);
    UMockdevIoctlData *d = NULL;
    (void)handler;

    g_mutex_lock(&sim->lock);
    if (_IOC_TYPE(request) == SPI_IOC_MAGIC && _IOC_NR(request) == 0 &&
        _IOC_DIR(request) == _IOC_WRITE) {
        handle_message(sim, client, arg, request);
        g_mutex_unlock(&sim->lock);
        return TRUE;
    }
    switch (request) {
    case SPI_IOC_WR_MODE:
    case SPI_IOC_RD_MODE:
    case SPI_IOC_WR_LSB_FIRST:
    case SPI_IOC_RD_LSB_FIRST:
    case SPI_IOC_WR_BITS_PER_WORD:
    case SPI_IOC_RD_BITS_PER_WORD:
        d = umockdev_ioctl_data_resolve(arg, 0, 1, NULL);
        break;
    case SPI_IOC_WR_MODE32:
    case SPI_IOC_RD_MODE32:
    case SPI_IOC_WR_MAX_SPEED_HZ:
    case SPI_IOC_RD_MAX_SPEED_HZ:
        d = umockdev_ioctl_data_resolve(arg, 0, 4, NULL);
        break;
    default:
        sim->unknown_ioctls++;
        umockdev_ioctl_client_complete(client, -1, ENOTTY);
        g_mutex_unlock(&sim->lock);
        return TRUE;
    }
    if (!d) {
        umockdev_ioctl_client_complete(client, -1, EFAULT);
        g_mutex_unlock(&sim->lock);
        return TRUE;
    }
    switch (request) {
    case SPI_IOC_WR_MODE:
        sim->mode = (sim->mode & ~0xFFu) | d->data[0];
        break;
    case SPI_IOC_RD_MODE:
        d->data[0] = (guint8)sim->mode;
        break;
    case SPI_IOC_WR_LSB_FIRST:
        sim->mode = d->data[0] ? sim->mode | SPI_LSB_FIRST : sim->mode & ~(guint32)SPI_LSB_FIRST;
        break;
    case SPI_IOC_RD_LSB_FIRST:
        d->data[0] = (sim->mode & SPI_LSB_FIRST) ? 1 : 0;
        break;
    case SPI_IOC_WR_BITS_PER_WORD:
        sim->bits = d->data[0];
        break;
    case SPI_IOC_RD_BITS_PER_WORD:
        d->data[0] = sim->bits;
        break;
    case SPI_IOC_WR_MODE32:
        memcpy(&sim->mode, d->data, 4);
        break;
    case SPI_IOC_RD_MODE32:
        memcpy(d->data, &sim->mode, 4);
        break;
    case SPI_IOC_WR_MAX_SPEED_HZ:
        memcpy(&sim->max_speed_hz, d->data, 4);
        break;
    case SPI_IOC_RD_MAX_SPEED_HZ:
        memcpy(d->data, &sim->max_speed_hz, 4);
        break;
    }
    umockdev_ioctl_client_complete(client, 0, 0);
    g_object_unref(d);
    g_mutex_unlock(&sim->lock);
    return TRUE;
}

/* ---------------------------------------------------------------- pins */

static void sleep_us(unsigned us)
{
    g_usleep(us);
}

static int line_reset(void *ctx, unsigned assert_us, unsigned settle_us, char *err, size_t errlen)
{
    spi_sim *sim = ctx;
    (void)err;
    (void)errlen;
    g_mutex_lock(&sim->lock);
    sim->reset_low = 1;
    sim->resets++;
    if (assert_us < 3)
        violation(sim, "reset pulse of %u us is too short", assert_us);
    g_mutex_unlock(&sim->lock);
    sleep_us(assert_us);
    g_mutex_lock(&sim->lock);
    sim->reset_low = 0;
    if (sim->panel == SPI_SIM_SSD1306) {
        oled_defaults(sim);
        oled_show(sim);
    } else if (sim->panel == SPI_SIM_SSD1680) {
        epd_defaults(sim);
        sim->busy_stuck = 0;
        set_busy(sim, sim->reset_busy_ms);
    }
    g_mutex_unlock(&sim->lock);
    sleep_us(settle_us);
    return 0;
}

static int line_dc(void *ctx, int data, char *err, size_t errlen)
{
    spi_sim *sim = ctx;
    (void)err;
    (void)errlen;
    g_mutex_lock(&sim->lock);
    sim->dc = data != 0;
    g_mutex_unlock(&sim->lock);
    return 0;
}

/* As stp_gpio_panel_wait_ready: poll every millisecond until the deadline. */
static int line_wait_ready(void *ctx, unsigned timeout_ms, char *err, size_t errlen)
{
    spi_sim *sim = ctx;
    gint64 deadline = g_get_monotonic_time() + (gint64)timeout_ms * 1000;
    for (;;) {
        int b;
        g_mutex_lock(&sim->lock);
        b = busy(sim);
        if (b)
            sim->busy_polls++;
        g_mutex_unlock(&sim->lock);
        if (!b)
            return 0;
        if (g_get_monotonic_time() >= deadline) {
            g_snprintf(err, errlen, "panel still busy after %u ms", timeout_ms);
            return -1;
        }
        g_usleep(1000);
    }
}

static int line_vcom_toggle(void *ctx, char *err, size_t errlen)
{
    spi_sim *sim = ctx;
    int level;
    (void)err;
    (void)errlen;
    g_mutex_lock(&sim->lock);
    sim->extcomin = !sim->extcomin;
    sim->extcomin_edges++;
    level = sim->extcomin;
    g_mutex_unlock(&sim->lock);
    return level;
}

static void line_delay(void *ctx, unsigned us)
{
    (void)ctx;
    g_usleep(us);
}

void spi_sim_lines(spi_sim *sim, int with_vcom, stp_spipanel_lines *lines)
{
    memset(lines, 0, sizeof *lines);
    lines->ctx = sim;
    lines->delay_us = line_delay;
    switch (sim->panel) {
    case SPI_SIM_SSD1306:
        lines->reset = line_reset;
        lines->dc = line_dc;
        break;
    case SPI_SIM_SSD1680:
        lines->reset = line_reset;
        lines->dc = line_dc;
        lines->wait_ready = line_wait_ready;
        break;
    case SPI_SIM_SHARP:
        if (with_vcom)
            lines->vcom_toggle = line_vcom_toggle;
        break;
    }
}

/* ---------------------------------------------------------------- set-up */

void spi_sim_scramble(spi_sim *sim, guint32 seed)
{
    guint32 s = seed ? seed : 1u;
    gsize i;
    g_mutex_lock(&sim->lock);
    for (i = 0; i < sizeof sim->oled.ram; i++)
        ((guint8 *)sim->oled.ram)[i] = (guint8)noise(&s);
    for (i = 0; i < sizeof sim->sharp.mem; i++)
        ((guint8 *)sim->sharp.mem)[i] = (guint8)noise(&s);
    for (i = 0; i < sizeof sim->epd.bw; i++) {
        ((guint8 *)sim->epd.bw)[i] = (guint8)noise(&s);
        ((guint8 *)sim->epd.red)[i] = (guint8)noise(&s);
    }
    for (i = 0; i < (gsize)sim->stride * sim->height; i++)
        sim->glass[i] = (guint8)noise(&s);
    if (sim->panel == SPI_SIM_SSD1306)
        oled_show(sim);
    g_mutex_unlock(&sim->lock);
}

spi_sim *spi_sim_new(spi_sim_panel panel, guint width, guint height, gsize bufsiz)
{
    spi_sim *sim = g_new0(spi_sim, 1);
    GError *error = NULL;
    g_mutex_init(&sim->lock);
    sim->panel = panel;
    sim->width = width;
    sim->height = height;
    sim->stride = (width + 7) / 8;
    sim->glass = g_malloc0((gsize)sim->stride * height);
    sim->violations = g_ptr_array_new_with_free_func(g_free);
    sim->bits = 8;
    sim->max_speed_hz = 500000; /* a board's device-tree default */
    sim->bufsiz = bufsiz ? bufsiz : 4096;
    sim->stuck_busy_after = -1;
    sim->swreset_busy_ms = 30;
    sim->refresh_busy_ms = 40;
    sim->reset_busy_ms = 5;
    sim->last_m1 = -1;
    oled_defaults(sim);
    epd_defaults(sim);
    sharp_frame_begin(sim);
    spi_sim_scramble(sim, 12345u);

    sim->testbed = umockdev_testbed_new();
    sim->handler = umockdev_ioctl_base_new();
    g_signal_connect(sim->handler, "handle-ioctl", G_CALLBACK(handle_ioctl), sim);
    if (!umockdev_testbed_attach_ioctl(sim->testbed, "/dev/spidev0.0", sim->handler, &error))
        g_error("attach_ioctl: %s", error->message);
    if (!umockdev_testbed_add_from_string(sim->testbed,
            "P: /devices/platform/soc/3f204000.spi/spi_master/spi0/spi0.0/spidev/spidev0.0\n"
            "N: spidev0.0\n"
            "E: SUBSYSTEM=spidev\n"
            "E: DEVNAME=/dev/spidev0.0\n"
            "E: MAJOR=153\n"
            "E: MINOR=0\n",
            &error))
        g_error("add spidev: %s", error->message);
    if (bufsiz) {
        gchar *sys = umockdev_testbed_get_sys_dir(sim->testbed);
        gchar *dir = g_build_filename(sys, "module", "spidev", "parameters", NULL);
        gchar *file = g_build_filename(dir, "bufsiz", NULL);
        gchar *text = g_strdup_printf("%" G_GSIZE_FORMAT "\n", bufsiz);
        if (g_mkdir_with_parents(dir, 0755) != 0 || !g_file_set_contents(file, text, -1, &error))
            g_error("bufsiz: %s", error ? error->message : g_strerror(errno));
        g_free(text);
        g_free(file);
        g_free(dir);
        g_free(sys);
    }
    return sim;
}

void spi_sim_free(spi_sim *sim)
{
    if (!sim)
        return;
    g_clear_object(&sim->handler);
    g_clear_object(&sim->testbed);
    g_ptr_array_unref(sim->violations);
    g_free(sim->glass);
    g_mutex_clear(&sim->lock);
    g_free(sim);
}

char *spi_sim_violations(spi_sim *sim)
{
    GString *s = g_string_new("");
    guint i;
    g_mutex_lock(&sim->lock);
    for (i = 0; i < sim->violations->len; i++)
        g_string_append_printf(s, "%s%s", i ? "; " : "",
                               (char *)g_ptr_array_index(sim->violations, i));
    g_mutex_unlock(&sim->lock);
    return g_string_free(s, FALSE);
}
