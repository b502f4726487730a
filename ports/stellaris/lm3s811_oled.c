/* SPDX-License-Identifier: MIT */
/* The lm3s811evb's OLED: an SSD0303 at I2C address 0x3D on I2C0.
 *
 * Every I2C write to the controller starts with a control byte: 0x80 (Co = 1,
 * D/C# = 0) says one command byte follows and another control byte after
 * it; 0x40 (Co = 0, D/C# = 1) says data bytes follow until STOP.  A command
 * and its parameters go as "80 cmd 80 param" and the write stops there:
 * QEMU 7.2's model takes no further control byte after a parameter. */
#include "lm3s811_oled.h"
#include "stellaris_i2c.h"

#define OLED_ADDRESS 0x3Du
#define CONTROL_COMMAND 0x80u
#define CONTROL_DATA 0x40u

static stp_stellaris_i2c oled_i2c;

void stp_lm3s811_oled_setup(void)
{
    stp_stellaris_i2c0_setup(&oled_i2c);
}

/* One call: one command and its parameters (stp_panel.h), one write. */
static int oled_command(void *ctx, const uint8_t *bytes, size_t count)
{
    stp_stellaris_i2c *bus = ctx;
    size_t i;
    stp_stellaris_i2c_begin(bus, OLED_ADDRESS);
    for (i = 0; i < count; i++) {
        (void)stp_stellaris_i2c_put(bus, CONTROL_COMMAND);
        (void)stp_stellaris_i2c_put(bus, bytes[i]);
    }
    return stp_stellaris_i2c_end(bus);
}

static int oled_data(void *ctx, const uint8_t *bytes, size_t count)
{
    stp_stellaris_i2c *bus = ctx;
    size_t i;
    stp_stellaris_i2c_begin(bus, OLED_ADDRESS);
    (void)stp_stellaris_i2c_put(bus, CONTROL_DATA);
    for (i = 0; i < count; i++)
        (void)stp_stellaris_i2c_put(bus, bytes[i]);
    return stp_stellaris_i2c_end(bus);
}

const stp_panel_bus stp_lm3s811_oled_bus = {oled_command, oled_data, &oled_i2c};
