// Lint: the rules of ГОСТ 20999-83 §1.4-§2.7 over loaded programs.
#include "tape/lint.hpp"

#include <algorithm>
#include <array>
#include <functional>

#include "tape/functions.hpp"

namespace tape {
namespace {

constexpr std::string_view dimension_order = "XYZUVWPQRABC";
constexpr std::string_view interpolation_order = "IJK";
constexpr std::string_view unsigned_addresses = "NGFSTMEO";

// Recommended order within a block (§2.2): G, X Y Z U V W P Q R A B C, I J K, F, S, T, M.
// Addresses whose place a controller's format decides (D E H L O N) have no rank: -1.
int order_rank(char a) {
    if (a == 'G') return 0;
    if (auto p = dimension_order.find(a); p != std::string_view::npos) return 10 + static_cast<int>(p);
    if (auto p = interpolation_order.find(a); p != std::string_view::npos) return 30 + static_cast<int>(p);
    switch (a) {
        case 'F':
            return 40;
        case 'S':
            return 50;
        case 'T':
            return 60;
        case 'M':
            return 70;
        default:
            return -1;
    }
}

bool is_dimension(char a) {
    return dimension_order.find(a) != std::string_view::npos || interpolation_order.find(a) != std::string_view::npos;
}

using Add = const std::function<void(Finding)>&;

void add(Add out, std::string_view rule, Severity s, const Location& where, std::uint64_t block, std::string message) {
    out(program_finding(rule, s, where, block, std::move(message)));
}

void spec_checks(Add out, const FormatSpec& s, const Block& b, bool points) {
    if (b.main && !s.main_block)
        add(out, "spec-main", Severity::error, b.where, b.ordinal, "the controller format has no ':' main blocks");
    if (b.skip && !s.block_skip)
        add(out, "spec-skip", Severity::error, b.where, b.ordinal, "the controller format has no '/' block skip");
    auto check = [&](const Word& w) {
        for (auto& [rule, message] : check_word(w, s, points))
            add(out, rule, Severity::error, w.where, b.ordinal, message);
    };
    if (b.number) check(*b.number);
    for (const auto& w : b.words) check(w);
}

void word_checks(Add out, const Block& b) {
    std::array<const Word*, 128> seen{};
    std::array<const Word*, 128> group{};
    int max_rank = -1;
    const Word* max_word = nullptr;
    const Word* previous = nullptr;
    for (const auto& w : b.words) {
        auto a = static_cast<unsigned char>(w.address);
        if (is_dimension(w.address)) {
            if (seen[a])
                add(out, "repeated-dimension", Severity::error, w.where, b.ordinal,
                    w.text + " repeats " + seen[a]->text +
                        ": a dimension or interpolation word may stand once in a block (§2.4)");
            else
                seen[a] = &w;
        }
        if (w.address == 'G' && w.integer())
            if (const NcFunction* f = find_nc_function('G', *w.integer()); f && f->group) {
                auto g = static_cast<unsigned char>(f->group);
                if (group[g])
                    add(out, "g-group", Severity::error, w.where, b.ordinal,
                        w.text + " and " + group[g]->text + " are both of group " + f->group + " (§2.5, table 4)");
                else
                    group[g] = &w;
            }
        if (w.sign && unsigned_addresses.find(w.address) != std::string_view::npos)
            add(out, "sign-not-allowed", Severity::error, w.where, b.ordinal,
                w.text + ": " + w.address + " words have no sign (§3.1.1, §3.3)");
        int rank = order_rank(w.address);
        // A feed that follows the dimension word of its own axis may stand there (§2.2).
        bool axis_feed_before = previous && previous->address == 'F' && max_word == previous;
        if (rank >= 0 && rank < max_rank && !(axis_feed_before && is_dimension(w.address)))
            add(out, "word-order", Severity::warning, w.where, b.ordinal,
                w.text + " stands after " + max_word->text +
                    "; recommended order G, X Y Z U V W P Q R A B C, I J K, F, S, T, M (§2.2)");
        if (rank > max_rank) {
            max_rank = rank;
            max_word = &w;
        }
        previous = &w;
    }
}

}  // namespace

bool uses_explicit_points(const Program& program) {
    for (const auto& b : program.blocks)
        for (const auto& w : b.words)
            if (w.has_point()) return true;
    return false;
}

LintVisitor::LintVisitor(const LintOptions& options)
    : options_(options), sink_([this](Finding f) { keep(std::move(f)); }) {}
LintVisitor::~LintVisitor() = default;

void LintVisitor::program_start(const Program& header) {
    close_program();
    any_program_ = in_program_ = true;
    program_points_ = false;
    program_start_ = header.start;
    program_blocks_ = 0;
    last_number_.reset();
    after_end_at_.reset();
}

void LintVisitor::block(const Block& b) {
    ++program_blocks_;
    for (const auto& w : b.words) program_points_ |= w.has_point();
    if (b.number) {
        auto n = b.number->integer();
        if (n && last_number_ && *n <= *last_number_)
            add(sink_, "block-number-order", Severity::warning, b.number->where, b.ordinal,
                "block number " + b.number->text + " does not increase (the block before is " +
                    std::to_string(*last_number_) + ")");
        if (n) last_number_ = n;
    }
    word_checks(sink_, b);
    if (options_.spec) held_.push_back(b);
}

void LintVisitor::after_end(std::string_view text, const Location& where) {
    if (!after_end_at_ && text.find_first_not_of(" \t\r\n") != std::string_view::npos) after_end_at_ = where;
}

void LintVisitor::finding(const Finding& f) { keep(f); }

void LintVisitor::keep(Finding f) {
    ++counts_[static_cast<int>(f.severity)];
    if (options_.max_per_rule && kept_[f.id()] >= options_.max_per_rule) {
        ++unlisted_[f.id()];
        return;
    }
    ++kept_[f.id()];
    out_.push_back(std::move(f));
}

void LintVisitor::end(const Location& where) {
    close_program();
    if (!any_program_) add(sink_, "no-program", Severity::error, where, 0, "no '%' program start on the tape (§1.4)");
}

void LintVisitor::close_program() {
    if (!in_program_) return;
    in_program_ = false;
    if (program_blocks_ == 0)
        add(sink_, "program-start", Severity::error, program_start_, 0, "'%' is not followed by a block (§1.4)");
    if (after_end_at_)
        add(sink_, "after-end", Severity::info, *after_end_at_, 0,
            "text after M02/M30 is not part of the program (§1.9)");
    for (const auto& b : held_) spec_checks(sink_, *options_.spec, b, program_points_);
    held_.clear();
}

std::vector<Finding> LintVisitor::findings() const {
    std::vector<Finding> sorted = out_;
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const Finding& a, const Finding& b) { return a.where.byte < b.where.byte; });
    return sorted;
}

std::vector<Finding> lint(const LoadedTape& tape, const LintOptions& options) {
    // The tape loaded whole is given to the streaming checks as the loader would give it.
    LintVisitor v(options);
    for (const auto& f : tape.findings) v.finding(f);
    for (const auto& p : tape.programs) {
        v.program_start(p);
        for (const auto& b : p.blocks) v.block(b);
        if (p.after_end_at) v.after_end(p.after_end, *p.after_end_at);
    }
    v.end(tape.locate(tape.text.size()));
    return v.findings();
}

}  // namespace tape
