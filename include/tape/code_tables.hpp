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

struct Block;

/// What a program's blocks say about its machine, fed block by block: a lathe when it moves X and Z
/// and never Y and writes what only lathes take (U W, G50 S, four-digit T0101, G18, G7), a mill when
/// Y moves or it selects G17 or a length offset with H. Undecided (Machine::any) until one side has
/// spoken and the other has not.
class MachineEvidence {
public:
    void block(const Block& b);
    Machine machine() const;

private:
    unsigned lathe_ = 0, mill_ = 0;
};

/// The meaning of each G and M word of block b in dialect d, on the machine given: "G90 outer or inner
/// diameter cutting cycle (G code system A)", both meanings named when the machine is undecided and
/// they differ. Russian names with russian. Codes the table does not name are left out.
std::string explain_codes(const Block& b, Dialect d, Machine machine, bool russian);

}  // namespace tape
