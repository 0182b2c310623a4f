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

/// --code (with auto for reading; with the 5-track codes where the command handles them), --parity, --charset.
void add_code_options(CLI::App* sub, CodeChoice& choice, bool with_auto, bool five_track = false);

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
