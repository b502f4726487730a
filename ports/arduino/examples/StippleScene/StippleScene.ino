// SPDX-License-Identifier: MIT
// Draws the scene compiled into scene.c (stipple compile SCENE -s 128x64
// -o scene.c --header stipple_config.h; the header goes to the library's
// src/ folder) on an SSD1306 128x64 OLED: SCK and MOSI on the board's SPI
// pins (Mega 2560: 52, 51), CS# on 10, D/C# on 11, RES# on 12.  The picture
// stays on the panel; the board then sleeps.  GPIOR0 holds the result
// (0: drawn), for a test harness that runs this sketch in a simulator.
#include <avr/interrupt.h>
#include <avr/sleep.h>
#include <Stipple.h>

static StippleSSD1306 panel(10, 11, 12);

void setup()
{
    int status = panel.begin();
    if (status == STP_OK)
        status = panel.draw(stp_compiled_scene);
    GPIOR0 = (uint8_t)(status == STP_OK ? 0 : 1);
    set_sleep_mode(SLEEP_MODE_PWR_DOWN);
    cli();
    sleep_mode();
}

void loop()
{
}
