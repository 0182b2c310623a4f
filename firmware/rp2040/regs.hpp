// The RP2040 registers this firmware touches, from the RP2040 datasheet (chapter and section in each
// comment). Only addresses and bit positions: no vendor header is packaged for Debian.
#pragma once

#include <cstdint>

namespace rp {

inline volatile std::uint32_t& reg(std::uint32_t address) {
    return *reinterpret_cast<volatile std::uint32_t*>(address);
}
// Atomic set and clear aliases of an APB/AHB register (2.1.2): +0x2000 sets, +0x3000 clears the bits written.
inline void set_bits(std::uint32_t address, std::uint32_t bits) { reg(address + 0x2000) = bits; }
inline void clear_bits(std::uint32_t address, std::uint32_t bits) { reg(address + 0x3000) = bits; }

// 2.14 Subsystem resets.
namespace resets {
inline constexpr std::uint32_t base = 0x4000C000, reset = base + 0x0, done = base + 0x8;
inline constexpr std::uint32_t io_bank0 = 1u << 5, pads_bank0 = 1u << 8, pll_sys = 1u << 12, pll_usb = 1u << 13,
                               timer = 1u << 21, usbctrl = 1u << 24;
}  // namespace resets

// 2.16 Crystal oscillator.
namespace xosc {
inline constexpr std::uint32_t base = 0x40024000, ctrl = base + 0x0, status = base + 0x4, startup = base + 0xC;
inline constexpr std::uint32_t range_1_15mhz = 0xAA0, enable = 0xFAB << 12, stable = 1u << 31;
}  // namespace xosc

// 2.18 PLL (PLL_SYS and PLL_USB have the same layout).
namespace pll {
inline constexpr std::uint32_t sys = 0x40028000, usb = 0x4002C000;
inline constexpr std::uint32_t cs = 0x0, pwr = 0x4, fbdiv = 0x8, prim = 0xC;
inline constexpr std::uint32_t lock = 1u << 31, pd = 1u << 0, postdivpd = 1u << 3, vcopd = 1u << 5;
}  // namespace pll

// 2.15 Clocks: each generator has CTRL, DIV (integer part in bits 31:8) and SELECTED.
namespace clocks {
inline constexpr std::uint32_t base = 0x40008000;
inline constexpr std::uint32_t ref_ctrl = base + 0x30, ref_div = base + 0x34, ref_selected = base + 0x38;
inline constexpr std::uint32_t sys_ctrl = base + 0x3C, sys_div = base + 0x40, sys_selected = base + 0x44;
inline constexpr std::uint32_t peri_ctrl = base + 0x48;
inline constexpr std::uint32_t usb_ctrl = base + 0x54, usb_div = base + 0x58;
inline constexpr std::uint32_t resus_ctrl = base + 0x78;
inline constexpr std::uint32_t enable = 1u << 11;
inline constexpr std::uint32_t ref_src_xosc = 2, sys_src_aux = 1, sys_aux_pll_sys = 0 << 5;
inline constexpr std::uint32_t peri_aux_pll_usb = 2 << 5, usb_aux_pll_usb = 0 << 5;
}  // namespace clocks

// 4.7 Watchdog: its tick generator makes the timer's 1 µs from clk_ref.
namespace watchdog {
inline constexpr std::uint32_t tick = 0x40058000 + 0x2C, tick_enable = 1u << 9;
}

// 4.6 Timer: a 64-bit microsecond counter and four alarms on the low word.
namespace timer {
inline constexpr std::uint32_t base = 0x40054000;
inline constexpr std::uint32_t alarm0 = base + 0x10, armed = base + 0x20, rawl = base + 0x28;
inline constexpr std::uint32_t intr = base + 0x34, inte = base + 0x38;
}  // namespace timer

// 2.19 GPIO: IO_BANK0 (function select, interrupts), PADS_BANK0, and SIO for the levels.
namespace io {
inline constexpr std::uint32_t base = 0x40014000;
inline constexpr std::uint32_t ctrl(unsigned gpio) { return base + 0x004 + 8 * gpio; }
inline constexpr std::uint32_t intr(unsigned gpio) { return base + 0x0F0 + 4 * (gpio / 8); }
inline constexpr std::uint32_t proc0_inte(unsigned gpio) { return base + 0x100 + 4 * (gpio / 8); }
inline constexpr std::uint32_t proc0_ints(unsigned gpio) { return base + 0x120 + 4 * (gpio / 8); }
/// The 4-bit event field of gpio in INTR/INTE/INTS: level low, level high, edge low, edge high.
inline constexpr std::uint32_t edge_low(unsigned gpio) { return 1u << (4 * (gpio % 8) + 2); }
inline constexpr std::uint32_t edge_high(unsigned gpio) { return 1u << (4 * (gpio % 8) + 3); }
inline constexpr std::uint32_t funcsel_sio = 5;
}  // namespace io
namespace pads {
inline constexpr std::uint32_t gpio(unsigned n) { return 0x4001C000 + 0x04 + 4 * n; }
inline constexpr std::uint32_t ie = 1u << 6, pue = 1u << 3, pde = 1u << 2, schmitt = 1u << 1;
}  // namespace pads
namespace sio {
inline constexpr std::uint32_t base = 0xD0000000;
inline constexpr std::uint32_t in = base + 0x004, out_set = base + 0x014, out_clr = base + 0x018;
inline constexpr std::uint32_t oe_set = base + 0x024, oe_clr = base + 0x028;
}  // namespace sio

// 2.3.2 / ARMv6-M: the NVIC and the vector table offset.
namespace nvic {
inline constexpr std::uint32_t iser = 0xE000E100, icpr = 0xE000E280, vtor = 0xE000ED08;
inline constexpr unsigned irq_timer0 = 0, irq_timer1 = 1, irq_timer2 = 2, irq_timer3 = 3, irq_usbctrl = 5,
                          irq_io_bank0 = 13;
}  // namespace nvic

// 4.1 USB controller: registers, and the dual-port RAM holding the device's endpoint tables.
namespace usb {
inline constexpr std::uint32_t regs = 0x50110000;
inline constexpr std::uint32_t addr_endp = regs + 0x00, main_ctrl = regs + 0x40, sie_ctrl = regs + 0x4C,
                               sie_status = regs + 0x50, buff_status = regs + 0x58, ep_stall_arm = regs + 0x68,
                               muxing = regs + 0x74, pwr = regs + 0x78, inte = regs + 0x90, ints = regs + 0x98;
inline constexpr std::uint32_t main_controller_en = 1u << 0;
inline constexpr std::uint32_t sie_pullup_en = 1u << 16, sie_ep0_int_1buf = 1u << 29;
inline constexpr std::uint32_t status_setup_rec = 1u << 17, status_bus_reset = 1u << 19;
inline constexpr std::uint32_t muxing_to_phy = 1u << 0, muxing_softcon = 1u << 3;
inline constexpr std::uint32_t pwr_vbus_detect = 1u << 2, pwr_vbus_detect_override = 1u << 3;
inline constexpr std::uint32_t int_buff_status = 1u << 4, int_bus_reset = 1u << 12, int_setup_req = 1u << 16;

inline constexpr std::uint32_t dpram = 0x50100000;
/// Endpoint control of endpoint n (1..15) IN or OUT; buffer control of endpoint n (0..15).
inline constexpr std::uint32_t ep_ctrl(unsigned n, bool in) { return dpram + 8 * n + (in ? 0 : 4); }
inline constexpr std::uint32_t buf_ctrl(unsigned n, bool in) { return dpram + 0x80 + 8 * n + (in ? 0 : 4); }
inline constexpr std::uint32_t ep0_buffer = 0x100;  ///< offset in the DPRAM; IN and OUT share it
inline constexpr std::uint32_t ep_enable = 1u << 31, ep_int_per_buffer = 1u << 29, ep_type_bulk = 2u << 26,
                               ep_type_interrupt = 3u << 26;
inline constexpr std::uint32_t buf_full = 1u << 15, buf_last = 1u << 14, buf_data1 = 1u << 13, buf_stall = 1u << 11,
                               buf_available = 1u << 10, buf_len = 0x3FF;
}  // namespace usb

inline void irq_off() { __asm volatile("cpsid i" ::: "memory"); }
inline void irq_on() { __asm volatile("cpsie i" ::: "memory"); }

}  // namespace rp
