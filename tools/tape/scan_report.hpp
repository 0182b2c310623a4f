// What tape scan says about a read: messages, the report, the debug pictures (scan_report.cpp).
#pragma once

#include <string>

#include "tape/scan.hpp"

namespace cli {

/// On stderr: pictures not read and what else was seen, gaps, an undecided direction, the doubtful
/// frames (as doubtful-frame warnings, numbered in the read written to output).
void say_scan_findings(const tape::ScanResult& r, const std::string& output);
/// Each run of doubtful frames as a doubtful-frame warning, as a reader's flagged rows are said.
void say_frame_doubts(const std::string& name, const tape::FrameDoubts& doubts);
/// The report for people: the read, then each picture's strip and its doubtful frames.
std::string scan_report_text(const tape::ScanResult& r);
/// The report as JSON, schema tape-scan/1 (tape(1)).
std::string scan_report_json(const tape::ScanResult& r);
/// scan_debug_svg of each picture to path (several pictures: path's stem with -1, -2, ...).
void write_debug_pictures(const tape::ScanResult& r, const std::string& path, bool force);

}  // namespace cli
