/* SPDX-License-Identifier: MIT */
/*
 * An SSD1306 128x64 on I2C through the Wire library (header only: a
 * sketch that includes it links Wire, others do not).  SDA and SCL of the
 * board (Uno, Nano: A4, A5; Mega: 20, 21); address 0x3C (0x3D with SA0
 * high); the bus at 400 kHz.  Each transmission is a control byte (0x00
 * commands, 0x40 data) and up to Wire's buffer less one byte (31 on an
 * AVR).  8-row band: 128 bytes.
 */
#ifndef STIPPLE_ARDUINO_SSD1306_I2C_H
#define STIPPLE_ARDUINO_SSD1306_I2C_H

#include <Arduino.h>
#include <Wire.h>

#include "StippleSSD1306.h"
#include "stipple/render.h"
#include "stipple_sim.h"

class StippleSSD1306I2C : public StippleSSD1306<StippleSSD1306I2C, 8> {
    friend class StippleSSD1306<StippleSSD1306I2C, 8>;

public:
    StippleSSD1306I2C() : address_(0x3C) {}

    /* Wire up, the panel initialised.  Returns STP_OK or STP_ERR_PORT (no
     * acknowledge). */
    int begin(uint8_t address = 0x3C, uint32_t clock_hz = 400000ul)
    {
        address_ = address;
        Wire.begin();
        Wire.setClock(clock_hz);
        return initPanel();
    }

protected:
#if defined(BUFFER_LENGTH) && BUFFER_LENGTH > 1
    static const uint8_t chunk = BUFFER_LENGTH - 1;
#else
    static const uint8_t chunk = 16;
#endif

    /* count bytes after the control byte (0x00: commands, 0x40: data;
     * Co 0), in transmissions of up to chunk bytes each (Wire's buffer
     * less the control byte): a page's 128 bytes as 31, 31, 31, 31 and 4;
     * no state kept between calls */
    int transmit(uint8_t control, const uint8_t *bytes, uint8_t count)
    {
        int status = 0;
        STIPPLE_SIM_BUS(1);
        while (count != 0 && status == 0) {
            uint8_t n = count < chunk ? count : chunk;
            Wire.beginTransmission(address_);
            Wire.write(control);
            Wire.write(bytes, n);
            status = Wire.endTransmission() == 0 ? 0 : -1;
            bytes += n;
            count = (uint8_t)(count - n);
        }
        STIPPLE_SIM_BUS(0);
        return status;
    }

    int command(const uint8_t *bytes, uint8_t count) { return transmit(0x00, bytes, count); }

    int pageStart(const uint8_t *address, uint8_t count) { return command(address, count); }

    int dataPut(const uint8_t *bytes, uint8_t count) { return transmit(0x40, bytes, count); }

    int dataEnd() { return 0; }

    void reset(unsigned ms) { (void)ms; /* I2C modules tie RES# to a power-on reset */ }

private:
    uint8_t address_;
};

#endif
