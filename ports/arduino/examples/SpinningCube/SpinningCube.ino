// SPDX-License-Identifier: MIT
// A lit, dithered cube spinning on an SSD1306 128x64 OLED over I2C, for an
// Uno or a Nano (or any board): VCC to 5V (or 3.3V), GND, SDA to A4, SCL to
// A5 (the board's SDA and SCL pins), the panel at address 0x3C.  The bus
// runs at 400 kHz.  cube_mesh.h comes from `stipple compile cube.obj --mesh
// --name cube`: another model, another header.
#include <Stipple.h>
#include <StippleSSD1306I2C.h>

#include "cube_mesh.h"

static StippleSSD1306I2C panel;
static StippleMesh<CUBE_VERTEX_COUNT, CUBE_TRIANGLE_COUNT> mesh;
static stp_direct_point points[CUBE_VERTEX_COUNT];
static uint16_t faces[CUBE_TRIANGLE_COUNT];
static stipple_spin spin;
static uint16_t frame;

void setup()
{
    pinMode(LED_BUILTIN, OUTPUT);
    if (panel.begin(0x3C) != STP_OK ||
        stipple_spin_begin(&spin, mesh.load(&cube_mesh), points, faces) != STP_OK)
        for (;;)
            digitalWrite(LED_BUILTIN, HIGH); // no panel: the LED says so
}

void loop()
{
    if (stipple_spin_frame(&spin, frame++) == STP_OK)
        panel.drawFrame(spin.frame);
}
