// How a program of the toolkit ends: its exit statuses, mapped here and nowhere else, and main()'s end.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "tape/error.hpp"

namespace cli {

/// Thrown to end the program with an exit status once the message is printed.
struct Exit {
    int status;
};

/// Exit statuses: mapped here and nowhere else.
enum Status { ok = 0, bad_data = 1, usage = 2, io_failure = 3 };
int status_for(tape::Errc code);

/// Exit status of a run the user interrupted (128 + SIGINT).
inline constexpr int interrupted_status = 130;

/// main()'s end for every program of the toolkit: parses argv and runs what it calls. --help and
/// --version are answered; a usage error is said as "PROGRAM: what" then "PROGRAM: run HELP for the
/// options" (HELP defaults to 'PROGRAM --help'), with status usage; Exit ends with its status. Every
/// other exception ends in a message too: a tape::Error with its status, running out of memory or an
/// internal error with io_failure.
int parse_and_run(CLI::App& app, int argc, char** argv, const std::string& help = "");

}  // namespace cli
