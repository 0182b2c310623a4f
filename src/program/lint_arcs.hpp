// Lint's arc checks: the motion interpreter run alongside, its findings (arc-radius, arc-radius-short,
// arc-full-circle-r) passed on, its moves dropped.
#pragma once

#include <functional>

#include "tape/lint.hpp"
#include "tape/motion.hpp"

namespace tape::lint_detail {

class ArcChecks : public MotionVisitor {
public:
    /// Findings go to sink; tolerance_mm, when given, replaces the dialect's.
    ArcChecks(Dialect dialect, const LintOptions& options, std::function<void(Finding)> sink);
    void start(const Program& header) { in_.program_start(header); }
    void next(const Block& b) { in_.block(b); }

    void move(const Move&) override {}
    void finding(const Finding& f) override { sink_(f); }

private:
    static MotionOptions options_for(Dialect dialect, const LintOptions& options);
    std::function<void(Finding)> sink_;
    Interpreter in_;
};

}  // namespace tape::lint_detail
