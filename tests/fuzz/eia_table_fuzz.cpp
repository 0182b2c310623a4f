// libFuzzer target: any bytes as an EIA code table (tape::CodeTable::parse, the --eia-table file).
// A table that parses must be a one-to-one map with odd parity, and the frame code built from it
// must encode and decode each of its characters back to itself.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "tape/code.hpp"
#include "tape/error.hpp"
#include "tape/frame.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    tape::CodeTable table;
    try {
        table = tape::CodeTable::parse(text);
    } catch (const tape::Error& e) {
        if (e.code() != tape::Errc::bad_table) __builtin_trap();
        return 0;
    }
    if (!table.frame_for('\n')) __builtin_trap();
    tape::FrameCode code = tape::FrameCode::eia(table);
    for (int c = 1; c < 128; ++c) {
        auto f = table.frame_for(static_cast<char>(c));
        if (!f) continue;
        if (*f == 0 || tape::hole_count(*f) % 2 == 0) __builtin_trap();
        if (table.char_for(*f) != static_cast<char>(c)) __builtin_trap();
        if (code.frame_for(static_cast<unsigned char>(c)) != f) __builtin_trap();
        if (c != 0x7F && (code.kind(*f) != tape::FrameKind::character || code.character(*f) != static_cast<char>(c)))
            __builtin_trap();
        code.label(*f);
    }
    return 0;
}
