// SPDX-License-Identifier: MIT
// 3D under u8g2's text: a sketch that drives its SSD1306 with u8g2 (the
// U8g2 library, installed from the Library Manager) draws the spinning cube
// into u8g2's page buffer, then writes on top as usual.  Page mode (_1: one
// 128-byte tile row) keeps RAM low on an Uno; the full-buffer constructors
// (_F) work the same (the whole frame is one "page").
#include <U8g2lib.h>
#include <Wire.h>
#include <Stipple.h>

#include "cube_mesh.h"

static U8G2_SSD1306_128X64_NONAME_1_HW_I2C u8g2(U8G2_R0);
static StippleMesh<CUBE_VERTEX_COUNT, CUBE_TRIANGLE_COUNT> mesh;
static stp_direct_point points[CUBE_VERTEX_COUNT];
static uint16_t faces[CUBE_TRIANGLE_COUNT];
static stipple_spin spin;
static uint8_t scratch[128]; // one tile row in the page layout
static uint16_t frame;

void setup()
{
    u8g2.begin();
    u8g2.setFont(u8g2_font_6x10_tf);
    stipple_spin_begin(&spin, mesh.load(&cube_mesh), points, faces);
}

void loop()
{
    if (stipple_spin_frame(&spin, frame++) != STP_OK)
        return;
    u8g2.firstPage();
    do {
        stipple_u8g2_draw(&spin.frame, u8g2.getBufferPtr(), u8g2.getBufferTileHeight(),
                          u8g2.getBufferCurrTileRow(), scratch);
        u8g2.drawStr(0, 10, "stipple");
    } while (u8g2.nextPage());
}
