/* SPDX-License-Identifier: MIT */
/* The lm3s6965evb's OLED: an SSD0323 on SSI0 (a PL022 at 0x40008000), data/
 * command on PC7 (high = data), and PD0, which QEMU wires to the panel's
 * chip select, held high. */
#include "lm3s6965_oled.h"
#include "stellaris.h"

#define SSI0 0x40008000u
#define SSI_CR0 STP_REG(SSI0 + 0x00u)
#define SSI_CR1 STP_REG(SSI0 + 0x04u)
#define SSI_DR STP_REG(SSI0 + 0x08u)
#define SSI_SR STP_REG(SSI0 + 0x0Cu)
#define SSI_CPSR STP_REG(SSI0 + 0x10u)
#define SSI_SR_TNF 0x02u /* transmit FIFO not full */
#define SSI_SR_RNE 0x04u /* receive FIFO not empty */

#define PIN_DC 0x80u /* PC7 */
#define PIN_CS 0x01u /* PD0 */

void stp_lm3s6965_oled_setup(void)
{
    /* clocks first: SSI0, GPIO A (the SSI pins), C and D */
    STP_SYSCTL_RCGC1 |= 1u << 4;
    STP_SYSCTL_RCGC2 |= (1u << 0) | (1u << 2) | (1u << 3);
    /* PA2..PA5 (SSI0 CLK, FSS, RX, TX) to the SSI */
    STP_GPIO_AFSEL(STP_GPIO_A) |= 0x3Cu;
    STP_GPIO_DEN(STP_GPIO_A) |= 0x3Cu;
    /* direction before data: a pin still configured as input ignores the
     * write, and QEMU would never see the level */
    STP_GPIO_DIR(STP_GPIO_C) |= PIN_DC;
    STP_GPIO_DEN(STP_GPIO_C) |= PIN_DC;
    STP_GPIO_DIR(STP_GPIO_D) |= PIN_CS;
    STP_GPIO_DEN(STP_GPIO_D) |= PIN_CS;
    STP_GPIO_DATA(STP_GPIO_D, PIN_CS) = PIN_CS;
    STP_GPIO_DATA(STP_GPIO_C, PIN_DC) = 0;
    /* SSI: disabled while configured; master; Freescale SPI frames of 8
     * bits; prescaler 2, SCR 0.  QEMU models neither the rate nor the clock
     * polarity/phase (SPO/SPH 0 here): check both against the panel's
     * datasheet before running on silicon. */
    SSI_CR1 = 0;
    SSI_CPSR = 2;
    SSI_CR0 = 0x07u;
    SSI_CR1 = 0x02u; /* SSE */
}

static void ssi_send(const uint8_t *bytes, size_t count)
{
    size_t i;
    for (i = 0; i < count; i++) {
        while (!(SSI_SR & SSI_SR_TNF))
            ;
        SSI_DR = bytes[i];
        /* drain the received byte now: QEMU's PL022 stops shifting once its
         * 8-entry receive FIFO is full, and a real one would overflow */
        while (!(SSI_SR & SSI_SR_RNE))
            ;
        (void)SSI_DR;
    }
}

static int oled_command(void *ctx, const uint8_t *bytes, size_t count)
{
    (void)ctx;
    STP_GPIO_DATA(STP_GPIO_C, PIN_DC) = 0;
    ssi_send(bytes, count);
    return 0;
}

static int oled_data(void *ctx, const uint8_t *bytes, size_t count)
{
    (void)ctx;
    STP_GPIO_DATA(STP_GPIO_C, PIN_DC) = PIN_DC;
    ssi_send(bytes, count);
    return 0;
}

const stp_panel_bus stp_lm3s6965_oled_bus = {oled_command, oled_data, 0};
