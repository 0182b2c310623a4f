// The report of tape restore as one self-contained HTML page (--html): no scripts, nothing fetched.
#pragma once

#include <string>

#include "restore_report.hpp"

namespace cli {

/// The page: the summary, a table of the problem frames (what each read saw, what was written, why, and
/// the text around it), each row linked to its frame on the tape (#fN), and the tape drawn to scale
/// (tape/render.hpp) around the problems only, every problem frame marked and linked back to its row
/// (#pN). Bounded for any tape: the drawing covers at most most_drawn stretches, and the table at most
/// most_rows problems (the rest counted), so a 10^6-frame tape with a thousand problems makes a page of
/// a few megabytes.
std::string restore_report_html(const RestoreReportInput& in);

inline constexpr std::size_t most_drawn = 300;
inline constexpr std::size_t most_rows = 5000;

}  // namespace cli
