// libFuzzer target: machine profiles (data/machines/README.md) read by the strict toml++ reader. Any
// input either reads or is an Error(usage) whose message names the file and a line; a profile that
// reads is looked through as tape machines show and lint would (modes, codes, tables).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "tape/error.hpp"
#include "tape/machine.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        tape::MachineProfile p = tape::parse_machine_profile(text, "fuzz.toml");
        for (const auto& c : p.codes)
            if (!c.mode.empty() && !p.find_mode(c.mode)) __builtin_trap();  // a code's mode is checked on reading
        if (!p.initial_mode.empty() && !p.find_mode(p.initial_mode)) __builtin_trap();
        for (const auto& m : p.modes)
            for (char a : m.addresses) {
                const tape::WordFormat* w = m.spec.find(a);
                if (!w || w->before != m.digits) __builtin_trap();
            }
    } catch (const tape::Error& e) {
        if (e.code() != tape::Errc::usage) __builtin_trap();
        if (std::string_view(e.what()).rfind("fuzz.toml: line ", 0) != 0) __builtin_trap();
    }
    return 0;
}
