/* SPDX-License-Identifier: MIT */
/*
 * An SSD1306 on the ATmega2560's hardware SPI, register level (no Arduino
 * core): SCK PB1, MOSI PB2, SS PB0 (an output, so the SPI stays master),
 * CS# PB4, D/C# PB5, RES# PB6 (Arduino Mega pins 52, 51, 53, 10, 11, 12).
 * SPI mode 0, MSB first, f_osc / 2.
 */
#ifndef STIPPLE_PORTS_AVR_SSD1306_SPI_H
#define STIPPLE_PORTS_AVR_SSD1306_SPI_H

#include "stp_panel.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The bus: commands with D/C# low, data with D/C# high, each call one
 * chip-select frame.  Never fails (returns 0). */
extern const stp_panel_bus stp_avr_ssd1306_bus;

/* Pins and the SPI unit set up, CS# and RES# high. */
void stp_avr_ssd1306_setup(void);

/* A step of stp_panel_run (STP_PANEL_STEP_RESET pulses RES#, DELAY waits;
 * arg in ms).  Returns 0, or -1 for a step it does not know. */
int stp_avr_ssd1306_step(void *ctx, unsigned op, unsigned arg);

#ifdef __cplusplus
}
#endif

#endif
