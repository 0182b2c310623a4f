// Restoring reads as tape restore does, shared by tape restore and tape archive (which restores the reads
// it packs, and again when it verifies a bag).
#pragma once

#include <optional>
#include <string>

#include "picture_reads.hpp"
#include "restore_report.hpp"
#include "tape/format_spec.hpp"
#include "tape/machine.hpp"
#include "tape/restore.hpp"

namespace cli {

/// What tape restore's options choose beyond the code.
struct RestoreChoices {
    std::string dialect = "auto";
    bool guess = false, drop_unrelated = false;
    const tape::FormatSpec* spec = nullptr;
    const tape::MachineProfile* machine = nullptr;  ///< --machine: its format, feed table and dialect
};

/// Restores in's reads in report.code; a read of another tape (named by its file) or another refusal ends
/// the program.
tape::RestoreResult run_restore(const RestoreChoices& c, const ReadsAndDoubts& in, const RestoreReportInput& report);

/// Each read's size and whether it holds no punched frame, for the report and its messages.
void describe_reads(const ReadsAndDoubts& in, RestoreReportInput& report);

/// What the reads and the code say before the report: reads left out, a code that does not fit.
void say_about_reads(const RestoreReportInput& in, const tape::RestoreResult& r);

}  // namespace cli
