/* SPDX-License-Identifier: MIT */
/* Polled I2C master for the Stellaris parts: see stellaris_i2c.h. */
#include "stellaris_i2c.h"
#include "stellaris.h"

#define I2C_MSA(b) STP_REG((b) + 0x000u)  /* slave address, bit 0: 1 = receive */
#define I2C_MCS(b) STP_REG((b) + 0x004u)  /* control (write) / status (read) */
#define I2C_MDR(b) STP_REG((b) + 0x008u)  /* data */
#define I2C_MTPR(b) STP_REG((b) + 0x00Cu) /* timer period: the SCL rate */
#define I2C_MCR(b) STP_REG((b) + 0x020u)  /* configuration */

#define MCR_MFE 0x10u /* master function enable */

/* MCS written */
#define MCS_RUN 0x01u
#define MCS_START 0x02u
#define MCS_STOP 0x04u
/* MCS read */
#define MCS_BUSY 0x01u
#define MCS_ERROR 0x02u
#define MCS_ARBLST 0x10u

#define GPIO_ODR(port) STP_REG((port) + 0x50Cu) /* open drain select */
#define PIN_SCL 0x04u                           /* PB2 */
#define PIN_SDA 0x08u                           /* PB3 */

/* SCL period = 2 (1 + TPR) (6 low + 4 high) system clocks */
#define I2C_RATE_HZ 100000u
#define I2C_TPR (STP_I2C_SYSCLK_HZ / (20u * I2C_RATE_HZ) - 1u)

void stp_stellaris_i2c0_setup(stp_stellaris_i2c *bus)
{
    bus->base = STP_I2C0_BASE;
    bus->holding = 0;
    bus->started = 0;
    bus->status = 0;
    STP_SYSCTL_RCGC1 |= 1u << 12;            /* I2C0 */
    STP_SYSCTL_RCGC2 |= 1u << 1;             /* GPIO B */
    STP_GPIO_AFSEL(STP_GPIO_B) |= PIN_SCL | PIN_SDA;
    GPIO_ODR(STP_GPIO_B) |= PIN_SDA;
    STP_GPIO_DEN(STP_GPIO_B) |= PIN_SCL | PIN_SDA;
    I2C_MCR(bus->base) = MCR_MFE;
    I2C_MTPR(bus->base) = I2C_TPR;
}

void stp_stellaris_i2c_begin(stp_stellaris_i2c *bus, uint8_t address)
{
    I2C_MSA(bus->base) = (uint32_t)address << 1; /* write */
    bus->holding = 0;
    bus->started = 0;
    bus->status = 0;
}

/* Send one byte with the control bits and wait for the controller. */
static void send(stp_stellaris_i2c *bus, uint8_t byte, uint32_t control)
{
    uint32_t mcs;
    if (bus->status != 0)
        return;
    I2C_MDR(bus->base) = byte;
    I2C_MCS(bus->base) = control;
    bus->started = 1;
    /* a real controller raises BUSY at once and clears it when the byte is
     * out (QEMU never sets it) */
    while ((mcs = I2C_MCS(bus->base)) & MCS_BUSY)
        ;
    if (mcs & (MCS_ERROR | MCS_ARBLST)) {
        bus->status = -1;
        /* unacknowledged: release the bus (after lost arbitration the
         * other master owns it) */
        if (!(control & MCS_STOP) && !(mcs & MCS_ARBLST)) {
            I2C_MCS(bus->base) = MCS_STOP;
            while (I2C_MCS(bus->base) & MCS_BUSY)
                ;
        }
    }
}

int stp_stellaris_i2c_put(stp_stellaris_i2c *bus, uint8_t byte)
{
    if (bus->holding)
        send(bus, bus->held, bus->started ? MCS_RUN : MCS_START | MCS_RUN);
    bus->held = byte;
    bus->holding = 1;
    return bus->status;
}

int stp_stellaris_i2c_end(stp_stellaris_i2c *bus)
{
    int status;
    if (bus->holding)
        send(bus, bus->held, (bus->started ? MCS_RUN : MCS_START | MCS_RUN) | MCS_STOP);
    status = bus->status;
    bus->holding = 0;
    bus->started = 0;
    bus->status = 0;
    return status;
}
