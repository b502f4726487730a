/* SPDX-License-Identifier: MIT */
/*
 * stipple for Arduino: the core (stipple/stipple.h), a compiled scene
 * (stp_scene_data.h) and an SSD1306 128x64 OLED on the SPI library
 * (StippleSSD1306.h).  See examples/StippleScene.
 */
#ifndef STIPPLE_ARDUINO_H
#define STIPPLE_ARDUINO_H

#include "stipple/stipple.h"
#include "stp_scene_data.h"
#include "StippleSSD1306.h"

#endif
