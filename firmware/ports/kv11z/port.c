/* KV11Z port: register-level HAL for one motor module, main loop and interrupt handlers.
 * Board wiring (illustrative; adjust to the module schematic in board_* tables below):
 *   RS-485: UART0 (system clock), driver-enable PTD7 (GPIO, high = transmit)
 *   PWM:    FTM0 CH0..3, 8-bit duty (MOD 254, ~283 kHz at 72 MHz; prescale to taste);
 *           bridge drivers with integrated Hall commutation take PWM + DIR + EN per motor
 *   DIR:    PTE16..19, EN: PTE20,21,24,25 (GPIO)
 *   Halls:  3 consecutive GPIO pins per motor (board_hall table)
 *   ADC0:   one current and one pot channel per motor, 12-bit, software triggered
 *   FRAM:   SPI0 (PTD1 SCK, PTD2 MOSI, PTD3 MISO), CS PTD0 (GPIO); FM25-style opcodes
 *   Timer:  SysTick at RCFW_CONTROL_RATE_HZ runs the control tick.
 * Untested on silicon: register addresses and bits follow the KV11Z reference manual
 * (KV11P64M75RM); this port is built and size-checked in CI, run only under review. */
#include <stddef.h>
#include <stdint.h>

#include "kv11z.h"
#include "rcfw/hal.h"
#include "rcfw/module.h"

#define MOTORS 4u
#define RX_RING 256u

struct rcfw_port {
    volatile uint32_t ticks;
    volatile uint32_t rx_end_us;
    volatile uint8_t rx_ring[RX_RING];
    volatile uint16_t rx_head; /* written by the UART ISR */
    uint16_t rx_tail;          /* main loop */
    const uint8_t *tx;
    uint16_t tx_len;
    uint32_t tx_delay_us;
    uint32_t uart_clk;
};

static struct rcfw_port port;
static rcfw_module module;

static const uint8_t board_adc_current[MOTORS] = {0, 1, 2, 3};
static const uint8_t board_adc_pot[MOTORS] = {4, 5, 6, 7};
static const struct {
    uint32_t gpio;
    uint8_t first_pin;
} board_hall[MOTORS] = {{GPIOB_BASE, 0}, {GPIOB_BASE, 16}, {GPIOC_BASE, 8}, {GPIOA_BASE, 12}};
static const uint8_t board_dir_pin[MOTORS] = {16, 17, 18, 19};
static const uint8_t board_en_pin[MOTORS] = {20, 21, 24, 25};
#define DE_PIN 7u
#define FRAM_CS_PIN 0u

static inline void irq_disable(void) { __asm volatile("cpsid i" ::: "memory"); }

/* Mask only the control tick (the UART keeps receiving). A tick that falls due while masked
 * is run late on unmask (COUNTFLAG), not lost. */
static void tick_lock(void) { SYST_CSR = 5u; }
static void tick_unlock(void)
{
    if (SYST_CSR & (1u << 16)) { /* reading clears COUNTFLAG */
        port.ticks++;
        rcfw_module_tick(&module);
    }
    SYST_CSR = 7u;
}

void rcfw_assert_failed(int line)
{
    (void)line;
    irq_disable();
    for (uint8_t i = 0; i < MOTORS; i++) {
        GPIO_PCOR(GPIOE_BASE) = 1u << board_en_pin[i]; /* bridges off */
    }
    SCB_AIRCR = 0x05FA0004u; /* system reset; RCM reports a software reset */
    for (;;) {
    }
}

void HardFault_Handler(void) { rcfw_assert_failed(-1); }

static uint32_t now_us(void)
{
    uint32_t t, cvr;
    do {
        t = port.ticks;
        cvr = SYST_CVR;
    } while (t != port.ticks);
    return t * (1000000u / RCFW_CONTROL_RATE_HZ) + (SYST_RVR - cvr) / (CORE_HZ / 1000000u);
}

/* ---- HAL ---- */
void rcfw_hal_pwm_set(struct rcfw_port *p, uint8_t motor, int16_t pwm)
{
    (void)p;
    uint32_t mag = (uint32_t)(pwm < 0 ? -pwm : pwm);
    if (pwm < 0) {
        GPIO_PSOR(GPIOE_BASE) = 1u << board_dir_pin[motor];
    } else {
        GPIO_PCOR(GPIOE_BASE) = 1u << board_dir_pin[motor];
    }
    FTM0_CnV(motor) = mag; /* 0..255 with MOD 254: 255 = 100 % */
}

void rcfw_hal_bridge_enable(struct rcfw_port *p, uint8_t motor, bool on)
{
    (void)p;
    if (on) {
        GPIO_PSOR(GPIOE_BASE) = 1u << board_en_pin[motor];
    } else {
        GPIO_PCOR(GPIOE_BASE) = 1u << board_en_pin[motor];
    }
}

static uint16_t adc_read(uint8_t channel)
{
    ADC0_SC1A = channel;
    while (!(ADC0_SC1A & ADC_SC1_COCO)) {
    }
    return (uint16_t)ADC0_RA;
}

uint16_t rcfw_hal_adc_current(struct rcfw_port *p, uint8_t motor)
{
    (void)p;
    return adc_read(board_adc_current[motor]);
}

uint16_t rcfw_hal_adc_pot(struct rcfw_port *p, uint8_t motor)
{
    (void)p;
    return adc_read(board_adc_pot[motor]);
}

uint8_t rcfw_hal_hall_read(struct rcfw_port *p, uint8_t motor)
{
    (void)p;
    return (uint8_t)((GPIO_PDIR(board_hall[motor].gpio) >> board_hall[motor].first_pin) & 7u);
}

void rcfw_hal_uart_set_baud(struct rcfw_port *p, uint32_t bps)
{
    /* wait for a transmission in progress, then SBR + 1/32 fine adjust */
    while (!(UART0_S1 & UART_S1_TC)) {
    }
    uint32_t sbr32 = (p->uart_clk * 2u + bps / 2u) / bps;
    UART0_C2 = 0;
    UART0_BDH = (uint8_t)((sbr32 >> 13) & 0x1Fu);
    UART0_BDL = (uint8_t)(sbr32 >> 5);
    UART0_C4 = (uint8_t)(sbr32 & 0x1Fu);
    UART0_C2 = UART_C2_RE | UART_C2_TE | UART_C2_RIE;
}

void rcfw_hal_uart_send(struct rcfw_port *p, const uint8_t *buf, uint16_t len, uint32_t delay_us)
{
    p->tx = buf;
    p->tx_delay_us = delay_us;
    p->tx_len = len; /* sent by the main loop after the delay */
}

static uint8_t spi_xfer(uint8_t b)
{
    while (!(SPI0_S & SPI_S_SPTEF)) {
    }
    SPI0_DL = b;
    while (!(SPI0_S & SPI_S_SPRF)) {
    }
    return SPI0_DL;
}

bool rcfw_hal_fram_read(struct rcfw_port *p, uint16_t addr, uint8_t *buf, uint16_t len)
{
    (void)p;
    GPIO_PCOR(GPIOD_BASE) = 1u << FRAM_CS_PIN;
    spi_xfer(0x03); /* READ */
    spi_xfer((uint8_t)(addr >> 8));
    spi_xfer((uint8_t)addr);
    for (uint16_t i = 0; i < len; i++) {
        buf[i] = spi_xfer(0);
    }
    GPIO_PSOR(GPIOD_BASE) = 1u << FRAM_CS_PIN;
    return true;
}

bool rcfw_hal_fram_write(struct rcfw_port *p, uint16_t addr, const uint8_t *buf, uint16_t len)
{
    (void)p;
    GPIO_PCOR(GPIOD_BASE) = 1u << FRAM_CS_PIN;
    spi_xfer(0x06); /* WREN */
    GPIO_PSOR(GPIOD_BASE) = 1u << FRAM_CS_PIN;
    GPIO_PCOR(GPIOD_BASE) = 1u << FRAM_CS_PIN;
    spi_xfer(0x02); /* WRITE: no page or erase cycle, data is non-volatile per byte */
    spi_xfer((uint8_t)(addr >> 8));
    spi_xfer((uint8_t)addr);
    for (uint16_t i = 0; i < len; i++) {
        (void)spi_xfer(buf[i]);
    }
    GPIO_PSOR(GPIOD_BASE) = 1u << FRAM_CS_PIN;
    return true;
}

/* ---- interrupts ---- */
void SysTick_Handler(void)
{
    port.ticks++;
    rcfw_module_tick(&module);
}

void UART0_IRQHandler(void)
{
    uint8_t s = UART0_S1;
    if (s & (UART_S1_RDRF | UART_S1_OR)) {
        uint8_t b = UART0_D; /* reading S1 then D clears RDRF/OR */
        uint16_t h = port.rx_head;
        uint16_t n = (uint16_t)((h + 1u) % RX_RING);
        if (n != port.rx_tail) {
            port.rx_ring[h] = b;
            port.rx_head = n;
        }
        port.rx_end_us = now_us();
    }
}

/* ---- start-up ---- */
static uint8_t reset_cause(void)
{
    uint8_t s0 = RCM_SRS0, s1 = RCM_SRS1;
    if (s0 & RCM_SRS0_POR) {
        return RCFW_CAUSE_POWER_ON;
    }
    if (s0 & RCM_SRS0_LVD) {
        return RCFW_CAUSE_BROWN_OUT;
    }
    if (s0 & RCM_SRS0_WDOG) {
        return RCFW_CAUSE_WATCHDOG;
    }
    if (s1 & RCM_SRS1_SW) {
        return RCFW_CAUSE_SOFTWARE;
    }
    if (s1 & RCM_SRS1_LOCKUP) {
        return RCFW_CAUSE_LOCKUP;
    }
    return RCFW_CAUSE_PIN;
}

static void clocks_and_pins(void)
{
    SIM_COPC = 0; /* COP off during bring-up; see docs/protocol.md (reset behaviour) */
    MCG_C4 = (uint8_t)((MCG_C4 & ~MCG_C4_DRST_DRS_MASK) | MCG_C4_DMX32 | MCG_C4_DRST_DRS_MID);
    SIM_CLKDIV1 = (0u << 28) | (2u << 16); /* core /1, bus+flash /3 */
    SIM_SCGC4 |= SIM_SCGC4_UART0;
    SIM_SCGC5 |= SIM_SCGC5_PORTA | SIM_SCGC5_PORTB | SIM_SCGC5_PORTC | SIM_SCGC5_PORTD | SIM_SCGC5_PORTE;
    SIM_SCGC6 |= SIM_SCGC6_FTM0 | SIM_SCGC6_ADC0 | SIM_SCGC6_SPI0;
    /* pin mux */
    PORT_PCR(PORTB_BASE, 16) = PORT_PCR_MUX(3); /* UART0_RX */
    PORT_PCR(PORTB_BASE, 17) = PORT_PCR_MUX(3); /* UART0_TX */
    PORT_PCR(PORTD_BASE, DE_PIN) = PORT_PCR_MUX(1);
    GPIO_PDDR(GPIOD_BASE) |= (1u << DE_PIN) | (1u << FRAM_CS_PIN);
    GPIO_PCOR(GPIOD_BASE) = 1u << DE_PIN;
    GPIO_PSOR(GPIOD_BASE) = 1u << FRAM_CS_PIN;
    PORT_PCR(PORTD_BASE, FRAM_CS_PIN) = PORT_PCR_MUX(1);
    for (uint8_t i = 1; i <= 3; i++) {
        PORT_PCR(PORTD_BASE, i) = PORT_PCR_MUX(2); /* SPI0 */
    }
    for (uint8_t i = 0; i < MOTORS; i++) {
        PORT_PCR(PORTC_BASE, 1u + i) = PORT_PCR_MUX(4); /* FTM0_CHi */
        PORT_PCR(PORTE_BASE, board_dir_pin[i]) = PORT_PCR_MUX(1);
        PORT_PCR(PORTE_BASE, board_en_pin[i]) = PORT_PCR_MUX(1);
        GPIO_PDDR(GPIOE_BASE) |= (1u << board_dir_pin[i]) | (1u << board_en_pin[i]);
        GPIO_PCOR(GPIOE_BASE) = 1u << board_en_pin[i];
    }
    /* FTM0 edge-aligned PWM */
    FTM0_MOD = 254u;
    for (uint8_t i = 0; i < MOTORS; i++) {
        FTM0_CnSC(i) = FTM_CnSC_EDGE_HIGH;
        FTM0_CnV(i) = 0;
    }
    FTM0_SC = FTM_SC_CLKS_SYS;
    /* ADC 12-bit single-ended */
    ADC0_CFG1 = ADC_CFG1_MODE_12;
    /* SPI0 master, mode 0, bus/2 */
    SPI0_BR = 0;
    SPI0_C1 = SPI_C1_SPE | SPI_C1_MSTR;
    port.uart_clk = CORE_HZ;
}

static void transmit_pending(void)
{
    if (!port.tx_len) {
        return;
    }
    while ((uint32_t)(now_us() - port.rx_end_us) < port.tx_delay_us) {
    }
    GPIO_PSOR(GPIOD_BASE) = 1u << DE_PIN;
    for (uint16_t i = 0; i < port.tx_len; i++) {
        while (!(UART0_S1 & UART_S1_TDRE)) {
        }
        UART0_D = port.tx[i];
    }
    while (!(UART0_S1 & UART_S1_TC)) {
    }
    GPIO_PCOR(GPIOD_BASE) = 1u << DE_PIN;
    port.tx_len = 0;
}

int main(void)
{
    clocks_and_pins();
    uint8_t cause = reset_cause();
    rcfw_module_init(&module, &port, MOTORS, cause);
    NVIC_ISER = 1u << IRQ_UART0;
    SYST_RVR = CORE_HZ / RCFW_CONTROL_RATE_HZ - 1u;
    SYST_CVR = 0;
    SYST_CSR = 7u; /* core clock, interrupt, enable */
    for (;;) {
        while (port.rx_tail != port.rx_head) {
            uint8_t b = port.rx_ring[port.rx_tail];
            port.rx_tail = (uint16_t)((port.rx_tail + 1u) % RX_RING);
            tick_lock(); /* the frame handler and the tick share the module context */
            rcfw_module_rx_byte(&module, b);
            tick_unlock();
            transmit_pending();
        }
        tick_lock();
        rcfw_module_poll(&module);
        tick_unlock();
        if (rcfw_module_take_reboot(&module)) {
            transmit_pending();
            SCB_AIRCR = 0x05FA0004u;
        }
    }
}
