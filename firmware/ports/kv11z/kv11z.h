/* Minimal KV11Z register definitions (KV11P64M75RM reference manual). Only what the port uses. */
#ifndef KV11Z_H
#define KV11Z_H
#include <stdint.h>
#define REG32(a) (*(volatile uint32_t *)(a))
#define REG8(a) (*(volatile uint8_t *)(a))

/* SIM: clock gating and dividers */
#define SIM_SCGC4 REG32(0x40048034u)
#define SIM_SCGC5 REG32(0x40048038u)
#define SIM_SCGC6 REG32(0x4004803Cu)
#define SIM_CLKDIV1 REG32(0x40048044u)
#define SIM_COPC REG32(0x40048100u)
#define SIM_SCGC4_UART0 (1u << 10)
#define SIM_SCGC5_PORTA (1u << 9)
#define SIM_SCGC5_PORTB (1u << 10)
#define SIM_SCGC5_PORTC (1u << 11)
#define SIM_SCGC5_PORTD (1u << 12)
#define SIM_SCGC5_PORTE (1u << 13)
#define SIM_SCGC6_SPI0 (1u << 12)
#define SIM_SCGC6_FTM0 (1u << 24)
#define SIM_SCGC6_ADC0 (1u << 27)

/* MCG: FLL engaged internal, DCO range mid + DMX32 -> 2197 x 32.768 kHz = 71.99 MHz */
#define MCG_C4 REG8(0x40064003u)
#define MCG_C4_DMX32 (1u << 7)
#define MCG_C4_DRST_DRS_MASK (3u << 5)
#define MCG_C4_DRST_DRS_MID (2u << 5)

/* Port control (pin mux) */
#define PORT_PCR(port_base, pin) REG32((port_base) + 4u * (pin))
#define PORTA_BASE 0x40049000u
#define PORTB_BASE 0x4004A000u
#define PORTC_BASE 0x4004B000u
#define PORTD_BASE 0x4004C000u
#define PORTE_BASE 0x4004D000u
#define PORT_PCR_MUX(x) ((uint32_t)(x) << 8)

/* GPIO */
#define GPIO_PDOR(b) REG32((b) + 0x00u)
#define GPIO_PSOR(b) REG32((b) + 0x04u)
#define GPIO_PCOR(b) REG32((b) + 0x08u)
#define GPIO_PDIR(b) REG32((b) + 0x10u)
#define GPIO_PDDR(b) REG32((b) + 0x14u)
#define GPIOA_BASE 0x400FF000u
#define GPIOB_BASE 0x400FF040u
#define GPIOC_BASE 0x400FF080u
#define GPIOD_BASE 0x400FF0C0u
#define GPIOE_BASE 0x400FF100u

/* UART0 */
#define UART0_BDH REG8(0x4006A000u)
#define UART0_BDL REG8(0x4006A001u)
#define UART0_C1 REG8(0x4006A002u)
#define UART0_C2 REG8(0x4006A003u)
#define UART0_S1 REG8(0x4006A004u)
#define UART0_D REG8(0x4006A007u)
#define UART0_C4 REG8(0x4006A00Au)
#define UART_C2_RIE (1u << 5)
#define UART_C2_TE (1u << 3)
#define UART_C2_RE (1u << 2)
#define UART_S1_TDRE (1u << 7)
#define UART_S1_TC (1u << 6)
#define UART_S1_RDRF (1u << 5)
#define UART_S1_OR (1u << 3)

/* FTM0: edge-aligned PWM, 8-bit duty (MOD = 254) */
#define FTM0_SC REG32(0x40038000u)
#define FTM0_CNT REG32(0x40038004u)
#define FTM0_MOD REG32(0x40038008u)
#define FTM0_CnSC(n) REG32(0x4003800Cu + 8u * (n))
#define FTM0_CnV(n) REG32(0x40038010u + 8u * (n))
#define FTM_SC_CLKS_SYS (1u << 3)
#define FTM_CnSC_EDGE_HIGH ((1u << 5) | (1u << 3)) /* MSB | ELSB */

/* ADC0 (16-bit SAR, software triggered, 12-bit mode) */
#define ADC0_SC1A REG32(0x4003B000u)
#define ADC0_CFG1 REG32(0x4003B008u)
#define ADC0_RA REG32(0x4003B010u)
#define ADC_SC1_COCO (1u << 7)
#define ADC_CFG1_MODE_12 (1u << 2)

/* SPI0 (FRAM) */
#define SPI0_C1 REG8(0x40076000u)
#define SPI0_C2 REG8(0x40076001u)
#define SPI0_BR REG8(0x40076002u)
#define SPI0_S REG8(0x40076003u)
#define SPI0_DL REG8(0x40076006u)
#define SPI_C1_SPE (1u << 6)
#define SPI_C1_MSTR (1u << 4)
#define SPI_S_SPRF (1u << 7)
#define SPI_S_SPTEF (1u << 5)

/* RCM: reset cause */
#define RCM_SRS0 REG8(0x4007F000u)
#define RCM_SRS1 REG8(0x4007F001u)
#define RCM_SRS0_LVD (1u << 1)
#define RCM_SRS0_WDOG (1u << 5)
#define RCM_SRS0_PIN (1u << 6)
#define RCM_SRS0_POR (1u << 7)
#define RCM_SRS1_LOCKUP (1u << 1)
#define RCM_SRS1_SW (1u << 2)

/* Cortex-M0+ core */
#define SYST_CSR REG32(0xE000E010u)
#define SYST_RVR REG32(0xE000E014u)
#define SYST_CVR REG32(0xE000E018u)
#define NVIC_ISER REG32(0xE000E100u)
#define SCB_AIRCR REG32(0xE000ED0Cu)
#define IRQ_UART0 12u

#define CORE_HZ 71991296u
#endif
