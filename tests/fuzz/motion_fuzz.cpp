// libFuzzer target: any bytes as a program, interpreted in every dialect, mill and lathe, with and
// without a format: no undefined behaviour, and no move or arc measure that is not a finite number
// (huge values, zero radii, R shorter than the chord, NaN-producing words).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "tape/motion.hpp"

namespace {

bool finite(const tape::Point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

struct Check : tape::MotionVisitor {
    void move(const tape::Move& m) override {
        if (!finite(m.start) || !finite(m.end) || !finite(m.centre)) __builtin_trap();
        if (!std::isfinite(m.radius) || !std::isfinite(m.end_radius) || !std::isfinite(m.seconds)) __builtin_trap();
        if (!std::isfinite(m.length()) || !std::isfinite(m.sweep()) || m.sweep() < 0) __builtin_trap();
        if (m.kind == tape::MoveKind::not_simulated && m.note.empty()) __builtin_trap();
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);
    constexpr tape::Dialect dialects[] = {tape::Dialect::gost, tape::Dialect::fanuc, tape::Dialect::linuxcnc,
                                          tape::Dialect::none, tape::Dialect::automatic};
    static const tape::FormatSpec spec = tape::parse_format_spec("N03 G02 X+053 Y+053 Z+053 I+053 J+053 K+053 R+053");
    tape::MotionOptions o = tape::motion_options(dialects[size % 5]);
    o.lathe = size % 3 == 0;
    o.lathe_unknown = size % 7 == 0;
    o.spec = size % 2 ? &spec : nullptr;
    Check check;
    tape::interpret_each(text, {}, check, o);
    return 0;
}
