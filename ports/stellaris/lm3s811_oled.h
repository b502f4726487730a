/* SPDX-License-Identifier: MIT */
/* The lm3s811evb's SSD0303 OLED bus (I2C0, address 0x3D). */
#ifndef STIPPLE_PORTS_LM3S811_OLED_H
#define STIPPLE_PORTS_LM3S811_OLED_H

#include "stp_panel.h"

#ifdef __cplusplus
extern "C" {
#endif

/* I2C0 set-up; call once before using the bus. */
void stp_lm3s811_oled_setup(void);

extern const stp_panel_bus stp_lm3s811_oled_bus;

#ifdef __cplusplus
}
#endif

#endif
