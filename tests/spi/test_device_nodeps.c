/* SPDX-License-Identifier: MIT */
/*
 * stp_device.c compiled as a build without libusb and libgpiod would compile
 * it (no STP_DEVICE_WITH_USB, no STP_DEVICE_WITH_GPIO): USB specs and SPI
 * control lines must fail with "built without ..." naming the piece, while
 * spec checking and the spidev path still work.  No devices are touched.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "stp_device.h"

static void expect_error(const char *spec, const char *message)
{
    char err[512];
    stp_device *d = stp_device_open(spec, NULL, err, sizeof err);
    if (d) {
        stp_device_close(d);
        fail_msg("'%s' opened", spec);
    }
    if (strcmp(err, message) != 0)
        fail_msg("'%s':\n  got      %s\n  expected %s", spec, err, message);
}

static void test_without_libusb(void **state)
{
    (void)state;
    expect_error("usb:0416:5011",
                 "device spec 'usb:0416:5011': built without libusb-1.0: USB printers are not "
                 "available");
    expect_error("usb:class,width=576,cut",
                 "device spec 'usb:class,width=576,cut': built without libusb-1.0: USB printers "
                 "are not available");
    /* a bad spec is still named as such */
    expect_error("usb:zz:1", "device spec 'usb:zz:1': vendor id 'zz' is not 1..4 hex digits");
}

static void test_without_libgpiod(void **state)
{
    (void)state;
    expect_error("spi:/dev/spidev250.250,controller=ssd1306,dc=GPIO25,reset=GPIO24",
                 "device spec 'spi:/dev/spidev250.250,controller=ssd1306,dc=GPIO25,reset=GPIO24': "
                 "built without libgpiod: cannot drive dc=GPIO25");
    expect_error("spi:/dev/spidev250.250,controller=sharp-ls013b7dh03,vcom=GPIO23",
                 "device spec 'spi:/dev/spidev250.250,controller=sharp-ls013b7dh03,vcom=GPIO23': "
                 "built without libgpiod: cannot drive vcom=GPIO23");
    /* a Sharp panel needs no line: on to spidev itself */
    expect_error("spi:/dev/spidev250.250,controller=sharp-ls013b7dh03",
                 "spi /dev/spidev250.250: cannot open: No such file or directory (is SPI "
                 "enabled? Raspberry Pi: dtparam=spi=on)");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_without_libusb),
        cmocka_unit_test(test_without_libgpiod),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
