// Checks of a loaded tape against ГОСТ 20999-83, and optionally against a controller format.
#pragma once

#include <vector>

#include "tape/format_spec.hpp"
#include "tape/program.hpp"

namespace tape {

struct LintOptions {
    const FormatSpec* spec = nullptr;  ///< also check every word against this controller format
};

/// Every finding: the loader's syntax findings and the rules below, in tape order.
/// Rules: no-program, program-start, program-end, after-end (info), repeated-dimension, g-group,
/// word-order (warning), sign-not-allowed, block-number-order (warning), and with a spec
/// spec-address, spec-sign, spec-point, spec-digits, spec-main, spec-skip.
std::vector<Finding> lint(const LoadedTape& tape, const LintOptions& options = {});

/// True when any word of the program writes an explicit decimal point (§3.1.4).
bool uses_explicit_points(const Program& program);

}  // namespace tape
