/* SPDX-License-Identifier: MIT */
/*
 * Markers for the simulator test (tests/avr): with STIPPLE_SIM_FRAMES
 * defined (the test passes it to the build), a bus transfer sets GPIOR2
 * while it lasts and every frame drawn writes GPIOR1, so the simulator
 * can count the cycles of each frame with and without the bus; after
 * STIPPLE_SIM_FRAMES frames (or at the first error) the board stops:
 * GPIOR0 = 0 (drawn) or 1, interrupts off, sleep.  Without it, nothing.
 */
#ifndef STIPPLE_SIM_H
#define STIPPLE_SIM_H

#if defined(STIPPLE_SIM_FRAMES) && defined(__AVR__)
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>

#define STIPPLE_SIM_BUS(on) (GPIOR2 = (uint8_t)(on))
#define STIPPLE_SIM_FRAME(status)                                                            \
    do {                                                                                     \
        static uint16_t stipple_sim_frames_;                                                 \
        GPIOR1 = (uint8_t)++stipple_sim_frames_;                                             \
        if ((status) != 0 || stipple_sim_frames_ >= (STIPPLE_SIM_FRAMES)) {                  \
            GPIOR0 = (uint8_t)((status) != 0);                                               \
            set_sleep_mode(SLEEP_MODE_PWR_DOWN);                                             \
            cli();                                                                           \
            sleep_mode();                                                                    \
        }                                                                                    \
    } while (0)
#else
#define STIPPLE_SIM_BUS(on) ((void)0)
#define STIPPLE_SIM_FRAME(status) ((void)0)
#endif

#endif
