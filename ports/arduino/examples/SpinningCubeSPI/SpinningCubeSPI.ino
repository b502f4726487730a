// SPDX-License-Identifier: MIT
// A lit, dithered cube spinning on an SSD1306 128x64 OLED over SPI (the
// 7-pin modules), for an Uno or a Nano: D0/SCK to 13, D1/MOSI to 11, CS to
// 10, DC to 9, RES to 8 (on a Mega: SCK 52, MOSI 51).  The bus runs at
// 8 MHz (half a 16 MHz clock).  cube_mesh.h comes from `stipple compile
// cube.obj --mesh --name cube`.
#include <Stipple.h>
#include <StippleSSD1306SPI.h>

#include "cube_mesh.h"

static StippleSSD1306SPI panel(10, 9, 8); // CS, DC, RES
static StippleMesh<CUBE_VERTEX_COUNT, CUBE_TRIANGLE_COUNT> mesh;
static stp_direct_point points[CUBE_VERTEX_COUNT];
static uint16_t faces[CUBE_TRIANGLE_COUNT];
static stipple_spin spin;
static uint16_t frame;

void setup()
{
    pinMode(LED_BUILTIN, OUTPUT);
    if (panel.begin() != STP_OK ||
        stipple_spin_begin(&spin, mesh.load(&cube_mesh), points, faces) != STP_OK)
        for (;;)
            digitalWrite(LED_BUILTIN, HIGH);
}

void loop()
{
    if (stipple_spin_frame(&spin, frame++) == STP_OK)
        panel.drawFrame(spin.frame);
}
