// A block's words read as numbers for the interpreter: which letters it holds, their values in the
// program's units, and the G and M codes, in one pass and without allocating.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "tape/dialect.hpp"
#include "tape/format_spec.hpp"
#include "tape/program.hpp"

namespace tape::motion {

/// How a value came out of its word.
enum class ValueState : std::uint8_t {
    absent,    ///< the block has no such word
    ok,        ///< value holds the number
    macro,     ///< a macro value: known only when the program runs
    unscaled,  ///< no decimal point and no rule says where the implied point stands
    bad,       ///< no digits, or too many to be a value any control reads
};

/// How words without a decimal point are read (MotionOptions::spec, the dialect, the program so far).
struct NumberRules {
    Dialect dialect = Dialect::gost;
    const FormatSpec* spec = nullptr;
    bool program_points = false;  ///< the program has written a decimal point in some word (§3.1.4)
    bool inch = false;            ///< Fanuc's least input increment is 0.0001 inch in G20
    std::uint32_t letters = ~0u;  ///< the letters to read (bit 0 = 'A'); the others are left absent
};

/// The words of one block: letters as 'A'..'Z' indexes.
struct BlockWords {
    std::array<ValueState, 26> state{};
    std::array<double, 26> value{};
    std::array<const Word*, 26> word{};
    std::array<bool, 26> implied{};  ///< a non-zero value read with Fanuc's least input increment (no point)
    static constexpr int max_codes = 8;
    int g[max_codes] = {};  ///< G codes ×10 (G90.1 → 901) in block order
    int g_count = 0;
    int m[max_codes] = {};
    int m_count = 0;
    const Word* odd_code = nullptr;  ///< a G or M word that is no plain code (macro, too many, no digits)

    bool has(char a) const { return state[static_cast<std::size_t>(a - 'A')] != ValueState::absent; }
    bool ok(char a) const { return state[static_cast<std::size_t>(a - 'A')] == ValueState::ok; }
    ValueState at(char a) const { return state[static_cast<std::size_t>(a - 'A')]; }
    double get(char a) const { return value[static_cast<std::size_t>(a - 'A')]; }
    bool scaled(char a) const { return implied[static_cast<std::size_t>(a - 'A')]; }
    /// The letter's word in this block, or nullptr (word[] keeps an earlier block's pointers: not cleared).
    const Word* word_of(char a) const { return has(a) ? word[static_cast<std::size_t>(a - 'A')] : nullptr; }
    bool has_g(int code10) const;
    bool has_m(int code) const;
};

/// Reads block's words. A letter written twice keeps its last value (the controls that allow it do so).
void read_words(const Block& block, const NumberRules& rules, BlockWords& out);

/// True when some word of the block writes a decimal point.
bool block_has_points(const Block& block);

}  // namespace tape::motion
