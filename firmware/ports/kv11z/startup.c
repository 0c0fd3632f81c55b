/* KV11Z startup: vector table, flash configuration field, .data/.bss init. */
#include <stdint.h>

extern uint32_t _data_start, _data_end, _data_load, _bss_start, _bss_end, _stack_top;
int main(void);
void Reset_Handler(void);
void Default_Handler(void);
void SysTick_Handler(void);
void UART0_IRQHandler(void);
void HardFault_Handler(void);

void Default_Handler(void)
{
    for (;;) {
    }
}

void Reset_Handler(void)
{
    uint32_t *s = &_data_load, *d = &_data_start;
    while (d < &_data_end) {
        *d++ = *s++;
    }
    for (d = &_bss_start; d < &_bss_end;) {
        *d++ = 0;
    }
    (void)main();
    for (;;) {
    }
}

typedef void (*vector_t)(void);
__attribute__((section(".vectors"), used)) const vector_t vector_table[16 + 32] = {
    (vector_t)(uintptr_t)&_stack_top, Reset_Handler, Default_Handler /* NMI */, HardFault_Handler,
    0, 0, 0, 0, 0, 0, 0, Default_Handler /* SVC */, 0, 0, Default_Handler /* PendSV */, SysTick_Handler,
    /* IRQ 0..31 */
    Default_Handler, Default_Handler, Default_Handler, Default_Handler, Default_Handler, Default_Handler,
    Default_Handler, Default_Handler, Default_Handler, Default_Handler, Default_Handler, Default_Handler,
    UART0_IRQHandler /* 12 */, Default_Handler, Default_Handler, Default_Handler, Default_Handler,
    Default_Handler, Default_Handler, Default_Handler, Default_Handler, Default_Handler, Default_Handler,
    Default_Handler, Default_Handler, Default_Handler, Default_Handler, Default_Handler, Default_Handler,
    Default_Handler, Default_Handler, Default_Handler};

/* Flash configuration field at 0x400: backdoor key, protection off, FSEC unsecured (0xFE),
 * FOPT default. */
__attribute__((section(".flash_config"), used)) const uint8_t flash_config[16] = {
    0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFE, 0xFF, 0xFF, 0xFF};
