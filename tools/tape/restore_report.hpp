// The report of tape restore, as text for people and as JSON (schema "tape-restore/1", in tape(1)).
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
    const tape::RestoreResult* result = nullptr;
    std::optional<tape::FrameCode> code;
    std::string code_text;  ///< "iso", "eia", or "none"
};

/// A stretch to read again: frames (1-based, inclusive) and their distance from the first feed hole.
struct RereadRange {
    std::uint64_t from, to;
};
/// The contested, unstable, unresolved and missing frames, close ones merged, with a few frames
/// around each.
std::vector<RereadRange> reread_list(const tape::RestoreResult& r);

std::string restore_report_text(const RestoreReportInput& in);
std::string restore_report_json(const RestoreReportInput& in);

/// The code reads are in: iso, eia (with parity for iso), none; or auto: the code of the longest read
/// (said with -v), none for a tape in no character code (a binary tape). name: how the report says it.
std::optional<tape::FrameCode> code_for_reads(const std::string& code, const std::string& parity,
                                              const std::vector<TapeInput>& reads, std::string& name);

/// "|o oo.   | '+'", or "|o oo.   | parity error": a frame as the report shows it.
std::string frame_text(const std::optional<tape::FrameCode>& code, tape::Frame f);

}  // namespace cli
