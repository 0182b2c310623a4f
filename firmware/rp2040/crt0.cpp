// The firmware's entry: the vector table boot stage 2 jumps through (0x10000100), and the reset
// handler that sets up RAM and C++ before main. Uses no boot ROM routine: the emulated RP2040 in CI
// has no boot ROM image, and a real one needs none of its helpers here.
#include <cstdint>
#include <cstring>

extern "C" {
extern std::uint32_t __stack_top[], __data_start[], __data_end[], __data_load[], __bss_start[], __bss_end[];
extern void (*__init_array_start[])();
extern void (*__init_array_end[])();
int main();
void reset_handler();
void timer0_irq();
void timer1_irq();
void timer2_irq();
void timer3_irq();
void usbctrl_irq();
void io_bank0_irq();
[[noreturn]] void fault_handler() {
    for (;;) __asm volatile("bkpt #0");
}
void ignore_irq() {}
// The C++ runtime's hooks a freestanding image still references.
void __cxa_pure_virtual() { fault_handler(); }
}

namespace {
using Handler = void (*)();
constexpr unsigned irq_count = 32;
struct Vectors {
    std::uint32_t* stack;
    Handler system[15];
    Handler irq[irq_count];
};
}  // namespace

__attribute__((section(".vectors"), used)) const Vectors vectors = {
    __stack_top,
    {reset_handler, fault_handler, fault_handler, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
     ignore_irq, nullptr, nullptr, ignore_irq, ignore_irq},
    {timer0_irq, timer1_irq, timer2_irq, timer3_irq, ignore_irq, usbctrl_irq,  ignore_irq, ignore_irq,
     ignore_irq, ignore_irq, ignore_irq, ignore_irq, ignore_irq, io_bank0_irq, ignore_irq, ignore_irq,
     ignore_irq, ignore_irq, ignore_irq, ignore_irq, ignore_irq, ignore_irq,   ignore_irq, ignore_irq,
     ignore_irq, ignore_irq, ignore_irq, ignore_irq, ignore_irq, ignore_irq,   ignore_irq, ignore_irq},
};

extern "C" void reset_handler() {
    std::memcpy(__data_start, __data_load,
                static_cast<std::size_t>(reinterpret_cast<char*>(__data_end) - reinterpret_cast<char*>(__data_start)));
    std::memset(__bss_start, 0,
                static_cast<std::size_t>(reinterpret_cast<char*>(__bss_end) - reinterpret_cast<char*>(__bss_start)));
    for (auto* f = __init_array_start; f != __init_array_end; ++f) (*f)();
    main();
    fault_handler();
}
