// libFuzzer target: a tape dnc configuration file, as the service reads it (the TOML guard, toml++, every
// key checked). Whatever the text, it is refused with tape::Error or read into settings that keep the
// rules the reader promises: names that can name files, bursts and time-outs in range, distinct flow
// characters.
#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "../../tools/tape/dnc_config.hpp"
#include "common/toml_guard.hpp"
#include "tape/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        tape::reject_bare_non_ascii(text, "fuzz.toml");
    } catch (const tape::Error& e) {
        if (!e.where().line || *e.where().line == 0) __builtin_trap();  // the line is always said
    }
    tape::dnc::ServiceConfig config;
    try {
        config = cli::parse_dnc_config(text, "fuzz.toml");
    } catch (const tape::Error&) {
        return 0;
    }
    if (config.machines.empty() || config.library.programs.empty()) __builtin_trap();
    for (const auto& m : config.machines) {
        bool name_ok = !m.name.empty() && m.name.size() <= 32 && std::all_of(m.name.begin(), m.name.end(), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
        });
        if (!name_ok || m.burst < 1 || m.burst > 256 || m.receive_timeout.count() < 100) __builtin_trap();
        if ((m.xon & 0x7F) == (m.xoff & 0x7F) || m.max_punch_out < 1024) __builtin_trap();
    }
    return 0;
}
