/* SPDX-License-Identifier: MIT */
/* SSD1306 over the ATmega2560's SPI (avr_ssd1306_spi.h). */
#include <avr/io.h>

#include "avr_ssd1306_spi.h"

#define PIN_SS (1u << PB0)
#define PIN_SCK (1u << PB1)
#define PIN_MOSI (1u << PB2)
#define PIN_CS (1u << PB4)
#define PIN_DC (1u << PB5)
#define PIN_RES (1u << PB6)

void stp_avr_ssd1306_setup(void)
{
    PORTB = (uint8_t)(PORTB | PIN_CS | PIN_RES | PIN_SS);
    DDRB = (uint8_t)(DDRB | PIN_SS | PIN_SCK | PIN_MOSI | PIN_CS | PIN_DC | PIN_RES);
    SPCR = (uint8_t)((1u << SPE) | (1u << MSTR)); /* mode 0, MSB first */
    SPSR = (uint8_t)(1u << SPI2X);                /* f_osc / 2 */
}

static void send(const uint8_t *bytes, size_t count, int data)
{
    if (data)
        PORTB = (uint8_t)(PORTB | PIN_DC);
    else
        PORTB = (uint8_t)(PORTB & ~PIN_DC);
    PORTB = (uint8_t)(PORTB & ~PIN_CS);
    GPIOR2 = 1; /* the simulator's bus mark (tests/avr): the wait left out */
    while (count--) {
        SPDR = *bytes++;
        while (!(SPSR & (1u << SPIF)))
            ;
    }
    GPIOR2 = 0;
    PORTB = (uint8_t)(PORTB | PIN_CS);
}

static int command(void *ctx, const uint8_t *bytes, size_t count)
{
    (void)ctx;
    send(bytes, count, 0);
    return 0;
}

static int data(void *ctx, const uint8_t *bytes, size_t count)
{
    (void)ctx;
    send(bytes, count, 1);
    return 0;
}

const stp_panel_bus stp_avr_ssd1306_bus = {command, data, 0};

/* About a millisecond at 16 MHz: 4 cycles per iteration of the inner loop. */
static void delay_ms(unsigned ms)
{
    while (ms--) {
        volatile uint16_t n = 4000u;
        while (n)
            n--;
    }
}

int stp_avr_ssd1306_step(void *ctx, unsigned op, unsigned arg)
{
    (void)ctx;
    switch (op) {
    case STP_PANEL_STEP_RESET:
        PORTB = (uint8_t)(PORTB & ~PIN_RES);
        delay_ms(arg);
        PORTB = (uint8_t)(PORTB | PIN_RES);
        return 0;
    case STP_PANEL_STEP_DELAY:
        delay_ms(arg);
        return 0;
    default:
        return -1;
    }
}
