// libFuzzer target: any text as a telecode table (src/codec/telecode_table.cpp). It is read or refused
// with a bad_table error; a table read keeps its promises: every character's frame has even parity and
// means that character again.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "tape/error.hpp"
#include "tape/telecode.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        auto table = tape::TelecodeTable::parse(text);
        for (int f = 0; f < 256; ++f) {
            const auto& e = table.entry(static_cast<tape::Frame>(f));
            if (e.kind == tape::TelecodeTable::Kind::none) continue;
            if (tape::hole_count(static_cast<tape::Frame>(f)) % 2) __builtin_trap();
            if (table.frame_of_value(e.value) != f) __builtin_trap();
        }
    } catch (const tape::Error& e) {
        if (e.code() != tape::Errc::bad_table) __builtin_trap();
    }
    return 0;
}
