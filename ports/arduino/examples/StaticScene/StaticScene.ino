// SPDX-License-Identifier: MIT
// A scene rendered on the host and played from flash: scene_spans.c comes
// from `stipple compile teapot-s1.nff -s 128x64 -d bayer4 -l 16 --exposure off
// --spans -o scene_spans.c`
// (the SPD teapot, hidden surfaces, lights and halftone all worked out on
// the host); the board only fills each row's runs from the shades'
// dither patterns, a page at a time.  SSD1306 128x64 over I2C at 0x3C
// (Uno, Nano: SDA A4, SCL A5).  Any scene, any board with the flash for
// its runs (stipple compile prints nothing; the file's size tells).
#include <Stipple.h>
#include <StippleSSD1306I2C.h>

extern "C" const stp_spans stp_compiled_spans;

static StippleSSD1306I2C panel;

void setup()
{
    pinMode(LED_BUILTIN, OUTPUT);
    if (panel.begin(0x3C) != STP_OK || panel.drawSpans(stp_compiled_spans) != STP_OK)
        digitalWrite(LED_BUILTIN, HIGH);
}

void loop()
{
}
