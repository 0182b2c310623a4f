// The report of tape restore, as text for people and as JSON (schema "tape-restore/2", in tape(1)); the
// JSON is also the doubts file written beside the image (tape/restore_doubts.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli/inputs.hpp"
#include "tape/restore.hpp"

namespace cli {

struct RestoreReportInput {
    std::vector<std::string> names;  ///< the reads, as given
    std::vector<std::size_t> sizes;  ///< their frames
    std::vector<bool> blank;         ///< per read: no punched frame (blank tape, or empty)
    const tape::RestoreResult* result = nullptr;
    std::optional<tape::FrameCode> code;
    std::string code_text;     ///< "ISO with even parity", or "none"
    std::string image_name;    ///< the image written ("-": standard output)
    std::string image_bytes;   ///< the image file as written, for its fingerprint
    std::string tape_picture;  ///< the HTML page's link to the whole tape drawn ("tape.svg"), with #fN; "": none
};

/// A stretch to read again: frames (1-based, inclusive) and their distance from the first feed hole.
struct RereadRange {
    std::uint64_t from, to;
};
/// The frames in doubt (contested, unstable, unresolved, guessed, missing), close ones merged, with a
/// few frames around each.
std::vector<RereadRange> reread_list(const tape::RestoreResult& r);

/// Why read i was left out: no punched frame, or a read of another tape (too damaged to align).
std::string left_out_text(const RestoreReportInput& in, std::size_t i);

std::string restore_report_text(const RestoreReportInput& in);
std::string restore_report_json(const RestoreReportInput& in);

/// The code reads are in: iso, eia (with parity for iso: empty is even), none; or auto: ISO when a parity
/// is given, else the code most reads fit (tape::detect_code_of_reads, said with -v), none for a tape in no character
/// code (a binary tape). name: how the report says it.
std::optional<tape::FrameCode> code_for_reads(const std::string& code, const std::string& parity,
                                              const std::vector<TapeInput>& reads, std::string& name);

/// "|o oo.   | '+'", or "|o oo.   | parity error": a frame as the report shows it.
std::string frame_text(const std::optional<tape::FrameCode>& code, tape::Frame f);

/// "frame 12", or "after frame 11" for a frame not written.
std::string problem_place(const tape::RestoreProblem& p);

}  // namespace cli
