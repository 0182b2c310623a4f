#include "rp2040/clocks.hpp"

#include "rp2040/regs.hpp"

namespace rp2040 {
namespace {

using namespace rp;

void unreset(std::uint32_t blocks) {
    clear_bits(resets::reset, blocks);
    while ((reg(resets::done) & blocks) != blocks) {
    }
}

// 2.18.2: VCO = 12 MHz / refdiv * fbdiv, output = VCO / post1 / post2.
void pll_start(std::uint32_t pll, std::uint32_t fbdiv, std::uint32_t post1, std::uint32_t post2) {
    reg(pll + pll::cs) = 1;  // refdiv 1
    reg(pll + pll::fbdiv) = fbdiv;
    clear_bits(pll + pll::pwr, pll::pd | pll::vcopd);
    while (!(reg(pll + pll::cs) & pll::lock)) {
    }
    reg(pll + pll::prim) = (post1 << 16) | (post2 << 12);
    clear_bits(pll + pll::pwr, pll::postdivpd);
}

}  // namespace

void clocks_init() {
    reg(clocks::resus_ctrl) = 0;
    // The crystal: range 1-15 MHz; start-up delay in units of 256 cycles, about 1 ms.
    reg(xosc::ctrl) = xosc::range_1_15mhz;
    reg(xosc::startup) = 47;
    set_bits(xosc::ctrl, xosc::enable);
    while (!(reg(xosc::status) & xosc::stable)) {
    }
    // Off the PLLs first (the boot ROM may have left clk_sys on one), then restart them.
    clear_bits(clocks::sys_ctrl, clocks::sys_src_aux);
    while (!(reg(clocks::sys_selected) & 1)) {
    }
    reg(clocks::ref_ctrl) = clocks::ref_src_xosc;
    while (!(reg(clocks::ref_selected) & (1u << clocks::ref_src_xosc))) {
    }
    set_bits(resets::reset, resets::pll_sys | resets::pll_usb);
    unreset(resets::pll_sys | resets::pll_usb);
    pll_start(pll::sys, 125, 6, 2);  // 1500 MHz / 12 = 125 MHz
    pll_start(pll::usb, 100, 5, 5);  // 1200 MHz / 25 = 48 MHz
    reg(clocks::sys_div) = 1 << 8;
    reg(clocks::sys_ctrl) = clocks::sys_aux_pll_sys;
    set_bits(clocks::sys_ctrl, clocks::sys_src_aux);
    while (!(reg(clocks::sys_selected) & 2)) {
    }
    reg(clocks::usb_div) = 1 << 8;
    reg(clocks::usb_ctrl) = clocks::enable | clocks::usb_aux_pll_usb;
    reg(clocks::peri_ctrl) = clocks::enable | clocks::peri_aux_pll_usb;
    reg(watchdog::tick) = watchdog::tick_enable | 12;  // 1 µs from the 12 MHz clk_ref
    unreset(resets::io_bank0 | resets::pads_bank0 | resets::timer | resets::usbctrl);
}

}  // namespace rp2040
