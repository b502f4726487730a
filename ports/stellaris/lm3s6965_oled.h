/* SPDX-License-Identifier: MIT */
/* The lm3s6965evb's SSD0323 OLED bus (SSI0, PC7 data/command, PD0 select). */
#ifndef STIPPLE_PORTS_LM3S6965_OLED_H
#define STIPPLE_PORTS_LM3S6965_OLED_H

#include "stp_panel.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Clock, pin and SSI set-up; call once before using the bus. */
void stp_lm3s6965_oled_setup(void);

extern const stp_panel_bus stp_lm3s6965_oled_bus;

#ifdef __cplusplus
}
#endif

#endif
