/* SPDX-License-Identifier: MIT */
/*
 * An SSD1306 128x64 on 4-wire SPI through the SPI library (header only: a
 * sketch that includes it links SPI, others do not).  SCK and MOSI of the
 * board (Uno, Nano: 13, 11; Mega: 52, 51) and any three pins for CS#, D/C#
 * and RES#; the clock at 8 MHz (half a 16 MHz AVR's: the datasheet's
 * 100 ns cycle).  16-row band: 256 bytes.
 */
#ifndef STIPPLE_ARDUINO_SSD1306_SPI_H
#define STIPPLE_ARDUINO_SSD1306_SPI_H

#include <Arduino.h>
#include <SPI.h>

#include "StippleSSD1306.h"
#include "stipple/render.h"
#include "stipple_sim.h"

class StippleSSD1306SPI : public StippleSSD1306<StippleSSD1306SPI, 16> {
    friend class StippleSSD1306<StippleSSD1306SPI, 16>;

public:
    StippleSSD1306SPI(uint8_t cs_pin, uint8_t dc_pin, uint8_t reset_pin)
        : cs_(cs_pin), dc_(dc_pin), reset_(reset_pin)
    {
    }

    /* SPI up, the panel reset and initialised.  Returns STP_OK or
     * STP_ERR_PORT. */
    int begin()
    {
        pinMode(cs_, OUTPUT);
        pinMode(dc_, OUTPUT);
        pinMode(reset_, OUTPUT);
        cs_bit_.attach(cs_);
        dc_bit_.attach(dc_);
        digitalWrite(cs_, HIGH);
        digitalWrite(reset_, HIGH);
        SPI.begin();
        return initPanel();
    }

protected:
    int command(const uint8_t *bytes, uint8_t count)
    {
        start(LOW);
        put(bytes, count);
        return dataEnd();
    }

    int dataPut(const uint8_t *bytes, uint8_t count)
    {
        put(bytes, count);
        return 0;
    }

    int dataEnd()
    {
        cs_bit_.write(cs_, HIGH);
        SPI.endTransaction();
        return 0;
    }

    /* the address and the page's data with CS# held low: D/C# switches
     * between them (about 100 cycles a page less than two transfers) */
    int pageStart(const uint8_t *address, uint8_t count)
    {
        start(LOW);
        put(address, count);
        dc_bit_.write(dc_, HIGH);
        return 0;
    }

    void reset(unsigned ms)
    {
        digitalWrite(reset_, LOW);
        wait(ms);
        digitalWrite(reset_, HIGH);
    }

private:
    uint8_t cs_, dc_, reset_;
    /* CS# and D/C#: on an AVR written as port bits (digitalWrite's table
     * lookups cost about 60 cycles a call, 6 calls a page: about 3 k cycles
     * a frame), elsewhere through digitalWrite */
    struct PinBit {
#ifdef __AVR__
        volatile uint8_t *port;
        uint8_t mask;
#endif
        void attach(uint8_t pin)
        {
#ifdef __AVR__
            port = portOutputRegister(digitalPinToPort(pin));
            mask = digitalPinToBitMask(pin);
#else
            (void)pin;
#endif
        }
        void write(uint8_t pin, uint8_t level)
        {
#ifdef __AVR__
            uint8_t sreg = SREG; /* the port may hold an interrupt's pins */
            (void)pin;
            cli();
            if (level)
                *port |= mask;
            else
                *port &= (uint8_t)~mask;
            SREG = sreg;
#else
            digitalWrite(pin, level);
#endif
        }
    } cs_bit_, dc_bit_;

    void start(uint8_t dc)
    {
        SPI.beginTransaction(SPISettings(8000000, MSBFIRST, SPI_MODE0));
        dc_bit_.write(dc_, dc);
        cs_bit_.write(cs_, LOW);
    }

    void put(const uint8_t *bytes, uint8_t count)
    {
        STIPPLE_SIM_BUS(1); /* the bytes' transfer only */
        while (count--)
            SPI.transfer(*bytes++);
        STIPPLE_SIM_BUS(0);
    }
};

#endif
