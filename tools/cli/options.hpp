// Options several subcommands share: the tape code (--code, --parity, --charset), the image formats
// (--format), the dialect, and a controller format (--spec).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "tape/format_spec.hpp"

namespace cli {

/// The code chosen for a decoding run: --code auto detects and explains itself with -v.
struct CodeChoice {
    std::string code = "auto";
    std::string parity = "even";
    std::string charset = "ascii";
};

/// Which tape codes a command's --code offers, in the order of tape::all_codes.
enum class CodeSet {
    five_track,  ///< iso, eia and the 5-track telegraph codes ita2 and mtk2
    all,         ///< every code of the library: the Elliott 900 and 920 telecodes too
};

/// The names --code accepts: auto first when with_auto (reading), then the codes of the set.
std::vector<std::string> code_choices(bool with_auto, CodeSet codes);
/// The help of --code for those codes, saying which of them detection finds.
std::string code_option_help(bool with_auto, CodeSet codes);

/// --code (with auto for reading; iso the default otherwise) for the codes of the set, --parity, --charset.
void add_code_options(CLI::App* sub, CodeChoice& choice, bool with_auto, CodeSet codes);

/// The image formats of the table that can be read (or written): "raw or holes", and a CLI11 check
/// that accepts exactly their ids. The CLI's --format choices come from here, never from a list of its own.
std::string format_choices(bool for_writing);
std::vector<std::string> format_ids(bool for_writing);
CLI::Validator format_check(bool for_writing);

/// --dialect (feed reads programs but not through the loader's listing).
void add_dialect_option(CLI::App* sub, std::string& dialect);

/// SPEC in the notation of ГОСТ 20999-83 §9; a malformed one ends the program (usage, exit 2).
tape::FormatSpec parse_spec_or_fail(const std::string& text);

}  // namespace cli
