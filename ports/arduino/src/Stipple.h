/* SPDX-License-Identifier: MIT */
/*
 * stipple for Arduino: lit, halftoned 3D on 1-bit panels.
 *   stipple/direct.h          direct drawing (immediate mode): a mesh
 *                             spun, shaded and drawn band by band
 *   stipple/playback_spans.h  pictures made on the host (stipple compile
 *                             --spans), played from flash
 *   StippleSSD1306.h          an SSD1306 128x64 OLED, drawn band by band;
 *                             its bus: #include <StippleSSD1306I2C.h>
 *                             (Wire) or <StippleSSD1306SPI.h> (SPI)
 *   StippleMesh.h             a mesh from `stipple compile --mesh`, out
 *                             of flash where the core reads it
 *   stipple_spin.h            the examples' camera, light and turn
 *   stipple_u8g2.h            drawing into a u8g2 page buffer
 * See examples/ and docs/arduino.md.
 */
#ifndef STIPPLE_ARDUINO_H
#define STIPPLE_ARDUINO_H

#include "stipple/direct.h"
#include "stipple/playback_spans.h"
#include "stipple/render.h"
#include "StippleMesh.h"
#include "StippleSSD1306.h"
#include "stipple_spin.h"
#include "stipple_u8g2.h"

#endif
