// SPDX-License-Identifier: MIT
// The SPD teapot (52 triangles) spinning on an SSD1306 128x64 OLED over
// I2C (400 kHz, address 0x3C), for boards with RAM to spare: a Mega 2560
// (SDA 20, SCL 21), a Cortex-M board (Due, Zero, Nano 33, Pico: their SDA
// and SCL).  On an AVR the mesh is copied out of flash (1.3 KB of RAM).
// Direct drawing paints the triangles in mesh order with back faces
// removed: a model that is not convex (the spout, the handle) may show a
// hidden face through a nearer one.  teapot_mesh.h comes from `stipple
// compile teapot.nff --mesh --name teapot`.
#include <Stipple.h>
#include <StippleSSD1306I2C.h>

#include "teapot_mesh.h"

static StippleSSD1306I2C panel;
static StippleMesh<TEAPOT_VERTEX_COUNT, TEAPOT_TRIANGLE_COUNT> mesh;
static stp_direct_point points[TEAPOT_VERTEX_COUNT];
static uint16_t faces[TEAPOT_TRIANGLE_COUNT];
static stipple_spin spin;
static uint16_t frame;

void setup()
{
    pinMode(LED_BUILTIN, OUTPUT);
    if (panel.begin(0x3C) != STP_OK ||
        stipple_spin_begin(&spin, mesh.load(&teapot_mesh), points, faces) != STP_OK)
        for (;;)
            digitalWrite(LED_BUILTIN, HIGH);
}

void loop()
{
    if (stipple_spin_frame(&spin, frame++) == STP_OK)
        panel.drawFrame(spin.frame);
}
