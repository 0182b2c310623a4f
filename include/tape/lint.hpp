// Checks of a loaded tape against ГОСТ 20999-83, and optionally against a controller format.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "tape/format_spec.hpp"
#include "tape/program.hpp"

namespace tape {

namespace lint_detail {
/// Whether a G or M word is outside the dialect's code tables, asked once per code: by value for the
/// plain codes below 1000 (G01 and G1 alike, no string made), by the text as written for the rest.
struct CodeVerdicts {
    enum : std::uint8_t { unasked, known, unknown };
    std::array<std::uint8_t, 2000> plain{};  // G0..G999, then M0..M999
    std::unordered_map<std::string, bool> written;
    void clear() {
        plain.fill(unasked);
        written.clear();
    }
};
class BlockTargets;
class ArcChecks;
class TravelChecks;
}  // namespace lint_detail
struct MachineProfile;
class MachineFormat;

struct LintOptions {
    const FormatSpec* spec = nullptr;  ///< also check every word against this controller format
    std::size_t max_per_rule = 0;  ///< list the first this many findings of a rule by position, count the rest (0: all)
    bool strict = false;           ///< blank tape inside a block is an error, not a warning
    /// Also check the program against this machine: its word format as its format-changing codes set
    /// it (in place of spec), its feed and speed codes (tape/machine_checks.hpp).
    const MachineProfile* machine = nullptr;
    /// Arcs are checked to this tolerance in mm (--arc-tolerance); unset: the dialect's controls'
    /// (motion_options in tape/motion.hpp).
    std::optional<double> arc_tolerance_mm{};
    /// Arcs are checked on their circles (the motion interpreter runs alongside). The dialect guess
    /// turns it off: a program's geometry is no evidence of its dialect.
    bool arcs = true;
};

/// Every finding: the loader's syntax findings and the rules of tape/rules.hpp that apply to the
/// tape's dialect, in tape order.
std::vector<Finding> lint(const LoadedTape& tape, const LintOptions& options = {});

/// The same checks fed by the loader as it streams (ProgramLoader, load_each): the loader's findings
/// and the rules, in bounded memory. A program's blocks are held only with a controller format or a machine, whose
/// checks must first know whether the program writes decimal points anywhere.
class LintVisitor : public ProgramVisitor {
public:
    explicit LintVisitor(const LintOptions& options = {});
    ~LintVisitor() override;
    void dialect(const DialectChoice& choice) override;
    void program_start(const Program& header) override;
    void block(const Block& block) override;
    void after_end(std::string_view text, const Location& where) override;
    void finding(const Finding& finding) override;
    void end(const Location& where) override;
    /// Every finding so far (the first max_per_rule of each rule by position), sorted by position.
    std::vector<Finding> findings() const;
    /// Findings beyond max_per_rule, by rule; each severity's total, listed or not.
    const std::map<std::string_view, std::uint64_t>& unlisted() const { return unlisted_; }
    std::uint64_t count(Severity s) const { return counts_[static_cast<int>(s)]; }
    /// Every finding made, listed or not, by rule.
    const std::map<std::string_view, std::uint64_t>& by_rule() const { return by_rule_; }
    Dialect dialect() const { return dialect_; }
    /// The runner-up when two dialects were close (DialectChoice::close).
    std::optional<Dialect> close() const { return close_; }
    /// The programs seen.
    std::uint64_t programs() const { return programs_; }

private:
    void close_program();
    void machine_program_checks();
    void keep(Finding f);
    void motion_checks(const Block& b);
    void flow_checks(const Block& b);
    struct Open;
    bool close_to(const std::string& label, std::string_view keyword);
    void report_unclosed(const Open& o);

    LintOptions options_;
    std::function<void(Finding)> sink_;  // keep(), for the checks shared with lint()
    struct Kept {                        // a finding listed, and when it came: equal positions keep their order
        Finding finding;
        std::uint64_t arrived;
        bool operator<(const Kept& o) const;  // by position on the tape or in the text
    };
    std::map<std::string_view, std::vector<Kept>> kept_;  // by rule: a heap, the last by position on top
    std::map<std::string_view, std::uint64_t> unlisted_, by_rule_;
    std::uint64_t arrived_ = 0, programs_ = 0;
    Dialect dialect_ = Dialect::gost;
    std::optional<Dialect> close_{};  // the runner-up: only the rules both have are checked
    lint_detail::CodeVerdicts unknown_codes_;
    std::uint64_t counts_[3] = {};
    bool any_program_ = false, in_program_ = false, program_points_ = false;
    bool quiet_ = false;  // checking a damaged block: its findings are not made
    Location program_start_{};
    std::uint64_t program_blocks_ = 0;
    std::optional<long long> last_number_{};
    std::optional<Location> after_end_at_{};  // the first text after the end that is not blank
    std::vector<Block> held_;                 // with a controller format or a machine: the program's blocks
    int motion_ = -1;                         // the G code of group a in effect (0-3), or -1
    bool feed_given_ = false, no_feed_said_ = false;
    bool subprogram_ = false;           // the program ends with M99: it runs at its caller's feed
    std::optional<Finding> no_feed_{};  // held to the program's end
    struct Open {                       // a loop or o-word block waiting for its end
        std::string label;
        std::string keyword;
        Location where;
        std::uint64_t block;
    };
    std::vector<Open> open_;
    std::unique_ptr<lint_detail::BlockTargets> targets_;  // Fanuc: the blocks its GOTOs, cycles and calls name
    std::unique_ptr<lint_detail::ArcChecks> arcs_;        // the interpreter, for arcs on their circles
    std::unique_ptr<lint_detail::TravelChecks> travel_;   // with a machine's travel: the interpreter again
    std::unique_ptr<MachineFormat> machine_format_;       // with a machine: the word format block by block
};

/// True when any word of the program writes an explicit decimal point (§3.1.4).
bool uses_explicit_points(const Program& program);

}  // namespace tape
