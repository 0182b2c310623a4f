// Restoring reads as tape restore does (restore_run.hpp).
#include "restore_run.hpp"

#include <algorithm>

#include "cli/messages.hpp"
#include "cli/restore_inputs.hpp"

namespace cli {

tape::RestoreResult run_restore(const RestoreChoices& c, const ReadsAndDoubts& in, const RestoreReportInput& report) {
    const std::vector<TapeInput>& reads = in.reads;
    std::vector<std::span<const tape::Frame>> spans;
    for (const auto& r : reads) spans.emplace_back(r.frames);
    tape::Dialect dialect = *tape::parse_dialect(c.dialect);
    if (c.machine && c.dialect == "auto") dialect = c.machine->dialect;
    tape::RestoreOptions o{.code = report.code, .dialect = dialect, .spec = c.spec, .machine = c.machine};
    o.guess = c.guess;
    o.align.drop_unrelated = c.drop_unrelated;
    o.doubts = in.doubts;  // a picture's faint holes weigh less than a sure reading
    try {
        return tape::restore(spans, o);
    } catch (const tape::UnrelatedRead& e) {
        bool blank = e.read() < report.blank.size() && report.blank[e.read()];
        fail(display_name(reads[e.read()].name), tape::Errc::bad_image,
             (blank ? "no punched frame (blank tape only): nothing of the tape to restore from"
                    : unrelated_text(e, reads)) +
                 " (--drop-unrelated goes on without it)");
    } catch (const tape::Error& e) {
        fail("", e);
    }
}

void describe_reads(const ReadsAndDoubts& in, RestoreReportInput& report) {
    for (const auto& r : in.reads) {
        report.sizes.push_back(r.frames.size());
        report.blank.push_back(std::all_of(r.frames.begin(), r.frames.end(), [](tape::Frame f) { return f == 0; }));
    }
}

void say_about_reads(const RestoreReportInput& in, const tape::RestoreResult& r) {
    for (std::size_t i = 0; i < in.names.size(); ++i)
        if (!r.related[i]) say(display_name(in.names[i]), left_out_text(in, i));
    if (in.code && r.code_misfit)
        say("", "most frames of the reads fail the code " + in.code_text +
                    ": it is not the tape's, so the reads were only voted, nothing repaired (try --code auto, or "
                    "another --parity)");
}

}  // namespace cli
