// The report of tape restore as one self-contained HTML page (--html): no scripts, nothing fetched.
#pragma once

#include <string>

#include "restore_report.hpp"

namespace cli {

/// The page: the summary and one legend; then the places in doubt (contested, unstable, unresolved, guessed,
/// missing) first, each with the frame every read has there, the program line it falls in, what was written,
/// the alternatives and the reason it was left open, the tape drawn around it (every problem frame marked
/// and linked back to its place, #pN) and, with in.tape_picture, a link to it on the whole tape; then the
/// places a vote or a repair decided, folded in a table with the tape drawn around them. Bounded for any tape:
/// at most most_drawn drawings (the places in doubt first) and most_rows places of each kind (the rest counted), so a
/// 10^6-frame tape with a thousand problems makes a page of a few megabytes.
std::string restore_report_html(const RestoreReportInput& in);

inline constexpr std::size_t most_drawn = 300;
inline constexpr std::size_t most_rows = 5000;

}  // namespace cli
