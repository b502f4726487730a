/* SPDX-License-Identifier: MIT */
/*
 * Polled I2C master of the Stellaris parts (LM3S811: I2C0 at 0x40020000,
 * SCL on PB2, SDA on PB3).  Writes only: all the firmware's devices are
 * write-only displays.
 *
 * A write is begin, put for each byte, end.  The controller has to be told,
 * when it sends a byte, whether that byte is the last one (RUN or
 * RUN|STOP), so put holds the newest byte back and sends the one before;
 * end sends the held byte with STOP.  Callers need not count ahead.
 */
#ifndef STIPPLE_PORTS_STELLARIS_I2C_H
#define STIPPLE_PORTS_STELLARIS_I2C_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define STP_I2C0_BASE 0x40020000u

/* System clock the bit rate is derived from: the LM3S811 runs from its main
 * oscillator after reset, the EVB's 6 MHz crystal. */
#ifndef STP_I2C_SYSCLK_HZ
#define STP_I2C_SYSCLK_HZ 6000000u
#endif

typedef struct stp_stellaris_i2c {
    uint32_t base;   /* the controller's registers, e.g. STP_I2C0_BASE */
    uint8_t held;    /* the byte put last, not sent yet */
    uint8_t holding; /* 1 while held is valid */
    uint8_t started; /* 1 once this transfer's START has gone out */
    int8_t status;   /* 0, or -1 after an error until end */
} stp_stellaris_i2c;

/* Clocks, pins (PB2/PB3, SDA open drain) and master mode at 100 kbit/s for
 * I2C0.  Master mode (MFE) is enabled before anything else is written to
 * the controller: QEMU ignores transfer commands until then. */
void stp_stellaris_i2c0_setup(stp_stellaris_i2c *bus);

/* Start a write to the 7-bit address (nothing reaches the bus before the
 * first byte). */
void stp_stellaris_i2c_begin(stp_stellaris_i2c *bus, uint8_t address);

/* Queue one byte of the write.  Returns 0, or -1 once the transfer has
 * failed (no acknowledge, lost arbitration): the rest of it is dropped. */
int stp_stellaris_i2c_put(stp_stellaris_i2c *bus, uint8_t byte);

/* Send the held byte with STOP and end the transfer.  Returns 0 or -1 if
 * any byte of the transfer failed. */
int stp_stellaris_i2c_end(stp_stellaris_i2c *bus);

#ifdef __cplusplus
}
#endif

#endif
