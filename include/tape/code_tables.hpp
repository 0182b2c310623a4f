// The G and M codes each dialect knows, as data (src/program/code_tables.cpp): ГОСТ 20999-83's two-digit
// G and M functions (tables 4-8), Fanuc's lathe and mill codes (with the Haas controls that follow them)
// and LinuxCNC's. Lint reports a code outside its dialect's table; blocks --explain names codes by it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "tape/dialect.hpp"

namespace tape {

/// The machine a code's meaning is for: some codes mean one thing on a lathe and another on a mill
/// (Fanuc's G90 is a turning cycle on a lathe, absolute dimensions on a mill).
enum class Machine { any, lathe, mill };

/// The value of a G or M word as the tables hold it: leading zeros and the sign-free digits only,
/// trailing zeros of a fraction dropped ("01" -> "1", "012.10" -> "12.1", "1.0" -> "1"); "" when the
/// text is no plain number (a macro value, no digits, a sign).
std::string code_value(std::string_view written);

/// True when dialect d knows the code: letter 'G' or 'M', value as written without leading zeros
/// ("1", "12.1"; code_value() makes one from any writing). ГОСТ 20999-83 knows G00-G99 and M00-M99
/// (those it leaves undefined are the controller's to use, tables 4 and 7, note 1), and M100-M199, the
/// same functions given after the machine's acknowledgement (M102: M02); Fanuc and LinuxCNC their own
/// tables. Other letters, a value that is no plain number and Dialect::automatic answer
/// true: there is nothing to hold them against.
bool code_known(Dialect d, char letter, std::string_view value);

/// One meaning of a code in a dialect's table.
struct CodeMeaning {
    Machine machine = Machine::any;
    std::string en;
    std::string ru;
};

/// What dialect d calls letter+value: one meaning, two where a lathe and a mill differ, none when
/// the table names it not (a code the standard leaves undefined, a machine builder's M code).
std::vector<CodeMeaning> code_meanings(Dialect d, char letter, std::string_view value);

}  // namespace tape
