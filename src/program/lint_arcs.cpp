#include "program/lint_arcs.hpp"

namespace tape::lint_detail {

MotionOptions ArcChecks::options_for(Dialect dialect, const LintOptions& options) {
    MotionOptions o = motion_options(dialect);
    o.spec = options.spec;
    o.lathe_unknown = true;  // lint is not told the machine: a lathe's arcs are not judged as a mill's
    o.findings_only = true;
    if (options.arc_tolerance_mm) {
        o.arc_tolerance_mm = *options.arc_tolerance_mm;
        o.arc_tolerance_relative = 0;
        o.arc_tolerance_either = false;
    }
    return o;
}

ArcChecks::ArcChecks(Dialect dialect, const LintOptions& options, std::function<void(Finding)> sink)
    : sink_(std::move(sink)), in_(*this, options_for(dialect, options)) {
    in_.dialect(DialectChoice{dialect, {}, {}});
}

}  // namespace tape::lint_detail
