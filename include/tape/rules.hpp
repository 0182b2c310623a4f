// The rules of the loader and of lint: each with a stable id, one severity, the dialects it applies
// to, and the reference it comes from. `tape lint --explain RULE` prints a row.
#pragma once

#include <span>
#include <string_view>

#include "tape/dialect.hpp"
#include "tape/error.hpp"

namespace tape {

struct Rule {
    std::string_view id;
    Severity severity;
    std::string_view dialects;   ///< "gost fanuc linuxcnc", or a subset
    std::string_view reference;  ///< § of ГОСТ 20999-83 or the dialect's manual section
    std::string_view checks;     ///< what the rule checks
    std::string_view why;        ///< why a machinist cares
};

/// Every rule, in the order tape(1) lists them.
std::span<const Rule> all_rules();
/// The rule with this id, or nullptr.
const Rule* find_rule(std::string_view id);
/// True when the rule is checked for programs of dialect d.
bool rule_applies(const Rule& rule, Dialect d);

}  // namespace tape
