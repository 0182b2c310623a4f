// What a restored tape holds, as tape archive keeps it in a bag: the decoded text of a program tape, or the
// memory image and checksums of a DEC loader tape (tape/binary_tape.hpp).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tape/code.hpp"
#include "tape/frame.hpp"

namespace cli {

/// A file of a bag's payload: its path under data/ and its bytes.
struct PayloadFile {
    std::string path, bytes;
};

/// The files of folder (under data/) for frames: for a loader tape recognised beyond doubt, memory.txt
/// (every loaded location in octal, eight a line) and checksums.txt (the format, each block and its
/// checksum); else, with a code, text.txt (the decoded text, a frame that cannot be read marked U+FFFD)
/// and, on a tape of several programs, one file per program (NUMBER.txt, or program-K.txt for the K-th
/// where its number can be no file name or is taken); else nothing. what says in words what the files are
/// ("", when none).
std::vector<PayloadFile> tape_contents(std::span<const tape::Frame> frames, const std::optional<tape::FrameCode>& code,
                                       const std::string& folder, std::string& what);

}  // namespace cli
