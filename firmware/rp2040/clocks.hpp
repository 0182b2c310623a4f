// Resets and clocks: the 12 MHz crystal, clk_sys 125 MHz from PLL_SYS, clk_usb and clk_peri 48 MHz
// from PLL_USB, clk_ref from the crystal and the timer's 1 µs tick from clk_ref.
#pragma once

namespace rp2040 {
void clocks_init();
}
