/* SPDX-License-Identifier: MIT */
/* stp_spipanel_lines onto stp_gpio_panel (libgpiod v2): the real control
 * lines of an SPI panel.  Built only with libgpiod (see stp_spipanel.h). */
#include "stp_spipanel.h"

#include <string.h>

static int gpio_reset(void *ctx, unsigned assert_us, unsigned settle_us, char *err, size_t errlen)
{
    return stp_gpio_panel_reset(ctx, assert_us, settle_us, err, errlen);
}

static int gpio_dc(void *ctx, int data, char *err, size_t errlen)
{
    return stp_gpio_panel_dc(ctx, data, err, errlen);
}

static int gpio_wait_ready(void *ctx, unsigned timeout_ms, char *err, size_t errlen)
{
    return stp_gpio_panel_wait_ready(ctx, timeout_ms, err, errlen);
}

static int gpio_vcom_toggle(void *ctx, char *err, size_t errlen)
{
    return stp_gpio_panel_vcom_toggle(ctx, err, errlen);
}

static int named(const char *spec)
{
    return spec && *spec;
}

void stp_spipanel_lines_from_gpio(stp_gpio_panel *g, const stp_gpio_panel_config *cfg,
                                  stp_spipanel_lines *lines)
{
    memset(lines, 0, sizeof *lines);
    lines->ctx = g;
    if (!g || !cfg)
        return;
    if (named(cfg->reset))
        lines->reset = gpio_reset;
    if (named(cfg->dc))
        lines->dc = gpio_dc;
    if (named(cfg->busy))
        lines->wait_ready = gpio_wait_ready;
    if (named(cfg->vcom))
        lines->vcom_toggle = gpio_vcom_toggle;
}
