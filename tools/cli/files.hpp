// Which files a run reads and writes, so that no output is written over an input or over another
// output of the same run: compared by device and inode (through symbolic and hard links), and by the
// place a new file would take. "-" is standard input or standard output.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>

namespace cli {

/// Remembers IN as read by this run. A regular file already written by the run is refused (usage, exit 2).
void note_input(const std::string& path);

/// Before OUT is opened for writing: refuses (usage, exit 2) when it is a regular file this run reads,
/// or a file another output of the run went to; then remembers it. Standard output ("-") may be
/// written piece by piece, but not when it is redirected into an input.
void claim_output(const std::string& path);

/// After OUT is written whole and closed: the run may read it (tape archive restores the reads it made).
void release_output(const std::string& path);

/// For a run with several outputs, before any is written: refuses (usage, exit 2) two of them that are
/// the same file. Each is an option's name ("--report") and its path; empty paths are not given.
void check_outputs(std::initializer_list<std::pair<std::string_view, std::string>> outputs);

}  // namespace cli
