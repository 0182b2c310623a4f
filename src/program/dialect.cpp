// The dialect table and the choice of a dialect from a program's text.
#include "tape/dialect.hpp"

#include <array>
#include <cctype>
#include <cstdint>
#include <initializer_list>
#include <utility>

namespace tape {
namespace {

// Columns: needs_percent lowercase semicolon_ends_block semicolon_comment macro_b o_words
// o_program_number main_blocks skip_levels closing_percent ordered_words increasing_numbers corner_words.
// none reads what every control has in common loosely enough that nothing of another control's syntax
// is refused: any case, ';' and ( ) comments, '/1'-'/9', M02 and M30 as ends.
constexpr int gost_ends[] = {2, 30, 102, 130}, fanuc_ends[] = {2, 30, 99}, plain_ends[] = {2, 30};
constexpr std::array<DialectRules, 4> table = {{
    {Dialect::gost, true, false, false, false, false, false, false, true, false, false, true, true, false, gost_ends,
     "ГОСТ 20999-83 (ISO 6983)"},
    {Dialect::fanuc, false, false, true, false, true, false, true, false, true, true, false, false, true, fanuc_ends,
     "Fanuc Series 0i/16i/18i/21i/30i operator's manual: program format, Custom Macro B"},
    {Dialect::linuxcnc, false, true, false, true, false, true, false, false, false, true, false, false, false,
     plain_ends, "LinuxCNC G-code reference (RS274NGC): overview, O codes, parameters"},
    {Dialect::none, false, true, false, true, false, false, false, false, true, false, false, false, false, plain_ends,
     "what holds for every control: characters, parity, block structure, comments"},
}};

}  // namespace

std::string_view dialect_name(Dialect d) {
    switch (d) {
        case Dialect::gost:
            return "gost";
        case Dialect::fanuc:
            return "fanuc";
        case Dialect::linuxcnc:
            return "linuxcnc";
        case Dialect::none:
            return "none";
        case Dialect::automatic:
            return "auto";
    }
    return "?";
}

std::optional<Dialect> parse_dialect(std::string_view name) {
    for (Dialect d : {Dialect::gost, Dialect::fanuc, Dialect::linuxcnc, Dialect::none, Dialect::automatic})
        if (dialect_name(d) == name) return d;
    return std::nullopt;
}

const DialectRules& dialect_rules(Dialect d) {
    for (const auto& row : table)
        if (row.dialect == d) return row;
    return table[0];
}

}  // namespace tape
