// The report of tape restore as one self-contained HTML page (--html): no scripts, nothing fetched.
#pragma once

#include <string>

#include "restore_report.hpp"

namespace cli {

/// The page: the summary, the restored tape drawn to scale (tape/render.hpp) with every problem frame
/// marked, and a table of the problem frames (what each read saw, what was written, why), each row
/// linked to its frame on the tape (#fN) and each mark back to its row (#pN).
std::string restore_report_html(const RestoreReportInput& in);

}  // namespace cli
