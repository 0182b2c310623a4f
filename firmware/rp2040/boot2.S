// Boot stage 2 for the Pico's W25Q flash (RP2040 datasheet 2.8.1.3): the boot ROM copies these 256
// bytes to SRAM at 0x20041F00, checks the CRC32 in the last four (scripts/rp2040_boot2.py puts it
// there) and runs them. It reads the flash's 64-bit unique id (W25Q command 0x4B), leaves it below
// itself for the firmware's USB serial string, sets the SSI up for execute-in-place with the plain
// 0x03 read (every W25Q has it; no quad mode to enable, no status register to write), then enters the
// firmware through its vector table at 0x10000100 — or returns, when the caller gave a return address.
    .syntax unified
    .cpu cortex-m0plus
    .thumb
    .section .text
    .global _stage2_boot
    .type _stage2_boot, %function
    .thumb_func
_stage2_boot:
    push {lr}
    ldr r3, =0x18000000         // XIP_SSI
    movs r0, #0
    str r0, [r3, #0x08]         // SSIENR: off while it is set up
    movs r0, #4
    str r0, [r3, #0x14]         // BAUDR: clk_sys / 4
    ldr r0, =0x00070000         // CTRLR0: standard SPI, 8-bit frames, transmit and receive
    str r0, [r3, #0x00]
    movs r0, #1
    str r0, [r3, #0x10]         // SER: the flash
    str r0, [r3, #0x08]         // SSIENR: on
    // 0x4B, four dummy bytes, then eight bytes of id: all thirteen pushed at once, as the chip select
    // rises when the transmit FIFO (16 deep) runs empty.
    movs r0, #0x4B
    str r0, [r3, #0x60]         // DR0
    movs r1, #12
    movs r0, #0
1:  str r0, [r3, #0x60]
    subs r1, #1
    bne 1b
    ldr r2, =0x20041EF0         // the id's place (the firmware leaves this SRAM alone)
    movs r1, #0
2:  ldr r0, [r3, #0x28]         // SR
    movs r4, #0x08              // RFNE: a byte received
    tst r0, r4
    beq 2b
    ldr r0, [r3, #0x60]
    cmp r1, #5
    blt 3f
    subs r4, r1, #5
    strb r0, [r2, r4]
3:  adds r1, #1
    cmp r1, #13
    bne 2b
    ldr r0, =0x44494C46         // "FLID": the id below is the flash's
    str r0, [r2, #8]
    // Execute in place: the SSI sends 0x03 and a 24-bit address, then reads 32-bit words.
    movs r0, #0
    str r0, [r3, #0x08]
    ldr r0, =0x001F0300         // CTRLR0: standard SPI, 32-bit frames, EEPROM read mode
    str r0, [r3, #0x00]
    movs r0, #0
    str r0, [r3, #0x04]         // CTRLR1: one frame a read
    ldr r0, =0x03000218         // SPI_CTRLR0: command 0x03, 8-bit instruction, 24-bit address
    ldr r1, =0x180000F4
    str r0, [r1]
    movs r0, #1
    str r0, [r3, #0x08]
    pop {r0}
    cmp r0, #0
    beq 4f
    bx r0
4:  ldr r0, =0x10000100         // the firmware's vector table
    ldr r1, =0xE000ED08         // VTOR
    str r0, [r1]
    ldmia r0, {r0, r1}
    msr msp, r0
    bx r1
    .ltorg
