/* SPDX-License-Identifier: MIT */
/*
 * The Arduino library's configuration of the core (include/stipple/config.h
 * includes this file when ARDUINO is defined: the Arduino builder gives a
 * library no -D of its own).  The examples draw with direct drawing and
 * span playback, which shade ambient + diffuse only: the specular term is
 * compiled out, which takes 8 KB of flash off an AVR image.  A sketch
 * using the full renderer with specular surfaces sets it back to 1 here.
 */
#ifndef STIPPLE_ARDUINO_CONFIG_H
#define STIPPLE_ARDUINO_CONFIG_H

#define STP_WITH_SPECULAR 0

#endif
