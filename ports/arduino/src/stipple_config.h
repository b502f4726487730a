/* SPDX-License-Identifier: MIT */
/*
 * The Arduino library's configuration of the core (include/stipple/config.h
 * includes this file when ARDUINO is defined: the Arduino builder gives a
 * library no -D of its own).  The examples draw with direct drawing and
 * span playback, which shade ambient + diffuse with one light: the
 * specular term is compiled out, which takes 8 KB of flash off an AVR
 * image, and the face shader keeps one light (124 bytes of flash and 143
 * of stack off the Uno's SpinningCube), on the face shader's compact
 * route (16-bit directions, a quotient per light: about 1 500 bytes off the Uno's
 * SpinningCube; error against the double reference within 5e-4 below a
 * light gain of 20, include/stipple/config.h).  A sketch using the full
 * renderer with specular surfaces or several lights sets them back here.
 */
#ifndef STIPPLE_ARDUINO_CONFIG_H
#define STIPPLE_ARDUINO_CONFIG_H

#define STP_WITH_SPECULAR 0
#define STP_MAX_LIGHTS 1
#define STP_SHADE_COMPACT 1
#define STP_DIRECT_COMPACT 1

#endif
