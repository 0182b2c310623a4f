// guess_dialect: the text read in each known dialect, its clues weighed, and an answer that may be
// "none fits" or "these two were close".
#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <string>

#include "program/dialect_evidence.hpp"
#include "tape/dialect.hpp"
#include "tape/lint.hpp"

namespace tape {
namespace {

using detection::Evidence, detection::Side;

constexpr std::array<Dialect, 3> known = {Dialect::gost, Dialect::fanuc, Dialect::linuxcnc};
constexpr std::int64_t misfit_weight = 4;  // a line one reading refuses and another takes: one strong clue
constexpr std::int64_t margin = 4;         // a winner must lead by one strong clue, else the two are close

// A line of label text that reads as a block ("G00 X13.5", "N10 M3"): ГОСТ would never run it.
bool reads_as_block(std::string_view line) {
    std::size_t i = line.find_first_not_of(" \t\r");
    if (i == std::string_view::npos || i + 1 >= line.size()) return false;
    char c = line[i], d = line[i + 1];
    bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
    return letter && ((d >= '0' && d <= '9') || d == '-' || d == '+' || d == '.' || d == '#' || d == '[');
}

// One dialect's reading of the text, linted: the lines it finds errors in (its label's lines that
// read as blocks among them, for ГОСТ), and how many blocks it saw.
class Trial : public LintVisitor {
public:
    Trial() : LintVisitor(LintOptions{.arcs = false}) {}
    void label(std::string_view text) override {
        for (char c : text) {
            if (c != '\n') {
                pending_ += c;
                continue;
            }
            ++label_lines_;
            if (reads_as_block(pending_)) misfits_.insert(label_lines_);
            pending_.clear();
        }
    }
    void block(const Block& b) override {
        ++blocks_;
        LintVisitor::block(b);
    }
    // The loader's findings: lines this dialect cannot read at all (lint's are of lines it reads).
    void finding(const Finding& f) override {
        if (f.severity == Severity::error && f.where.line) unread_.insert(*f.where.line);
        LintVisitor::finding(f);
    }
    const std::set<std::uint64_t>& unread_lines() const { return unread_; }
    std::set<std::uint64_t> misfit_lines() {
        for (const auto& f : findings())
            if (f.severity == Severity::error && f.where.line) misfits_.insert(*f.where.line);
        return misfits_;
    }
    std::uint64_t blocks() const { return blocks_; }

private:
    std::string pending_;
    std::uint64_t label_lines_ = 0, blocks_ = 0;
    std::set<std::uint64_t> misfits_, unread_;
};

struct Reading {
    Dialect dialect;
    std::set<std::uint64_t> misfits, unread;
    std::uint64_t own = 0;  // misfit lines that some other reading takes
    std::int64_t support = 0, score = 0;
};

std::array<Reading, 3> read_in_each(std::string_view text, const Evidence& e, std::uint64_t& blocks) {
    std::array<Reading, 3> r;
    for (std::size_t k = 0; k < known.size(); ++k) {
        Trial trial;
        load_each(text, {}, trial, LoadOptions{known[k]});
        r[k].dialect = known[k];
        r[k].misfits = trial.misfit_lines();
        r[k].unread = trial.unread_lines();
        r[k].support = static_cast<std::int64_t>(e.support(known[k]));
        blocks = std::max(blocks, trial.blocks());
    }
    for (auto& x : r) {
        for (std::uint64_t line : x.misfits)
            x.own += std::any_of(r.begin(), r.end(), [&](const Reading& o) { return !o.misfits.count(line); });
        x.score = x.support - misfit_weight * static_cast<std::int64_t>(x.own);
    }
    return r;
}

// Lines no reading can read: a text mostly of these is no program of a known dialect.
std::uint64_t unread_by_all(const std::array<Reading, 3>& r) {
    std::uint64_t n = 0;
    for (std::uint64_t line : r[0].unread) n += r[1].unread.count(line) && r[2].unread.count(line);
    return n;
}

Side side_of(Dialect d) {
    return d == Dialect::fanuc ? Side::fanuc : d == Dialect::linuxcnc ? Side::linuxcnc : Side::gost;
}

// "fanuc finds errors in 57 lines (first line 4)", for the readings that do.
std::string misfit_text(const std::array<Reading, 3>& r) {
    std::string out;
    for (const auto& x : r)
        if (!x.misfits.empty())
            out += (out.empty() ? "" : ", ") + std::string(dialect_name(x.dialect)) + " finds errors in " +
                   std::to_string(x.misfits.size()) + " line(s) (first line " + std::to_string(*x.misfits.begin()) +
                   ")";
    return out;
}

DialectChoice none_fits(const Evidence& e, const std::array<Reading, 3>& r) {
    std::string why = e.describe(Side::foreign);
    std::string misfits = misfit_text(r);
    return {Dialect::none, "no known dialect fits: " + (why.empty() ? std::string() : why + "; ") +
                               (misfits.empty() ? "nothing points to gost, fanuc or linuxcnc" : misfits) +
                               "; only what holds for every control is checked"};
}

// No clue for any dialect: ГОСТ when the text starts with '%' and ГОСТ reads it, else the first that
// reads it with no error another does not make.
DialectChoice no_clue(const Evidence& e, const std::array<Reading, 3>& r) {
    if (e.starts_with_percent() && r[0].own == 0) return {Dialect::gost, "nothing in the text needs another dialect"};
    if (r[2].own == 0)
        return {Dialect::linuxcnc, e.starts_with_percent()
                                       ? "nothing in the text points to a dialect, and ГОСТ finds errors LinuxCNC "
                                         "does not: " +
                                             misfit_text(r)
                                       : "no '%' before the program, so no ГОСТ tape program; nothing else decides"};
    const Reading& best =
        *std::max_element(r.begin(), r.end(), [](const Reading& a, const Reading& b) { return a.score < b.score; });
    return {best.dialect, "nothing in the text points to a dialect; it reads best in " +
                              std::string(dialect_name(best.dialect)) + ": " + misfit_text(r)};
}

}  // namespace

std::string_view dialect_sample(std::string_view text) {
    if (text.size() <= dialect_sample_bytes) return text;
    auto nl = text.rfind('\n', dialect_sample_bytes - 1);
    return text.substr(0, nl == std::string_view::npos ? dialect_sample_bytes : nl + 1);
}

DialectChoice guess_dialect(std::string_view text) {
    text = dialect_sample(text);
    Evidence e;
    e.scan(text);
    std::uint64_t blocks = 0;
    std::array<Reading, 3> r = read_in_each(text, e, blocks);
    std::array<const Reading*, 3> order = {&r[0], &r[1], &r[2]};
    std::stable_sort(order.begin(), order.end(),
                     [](const Reading* a, const Reading* b) { return a->score > b->score; });
    const Reading& best = *order[0];
    auto foreign = static_cast<std::int64_t>(e.foreign());
    // Another control's syntax outweighs the best reading's clues, or most of the text reads in none.
    std::uint64_t unread = unread_by_all(r);
    if ((foreign && misfit_weight * foreign >= best.score) || (unread >= 4 && unread * 2 > blocks))
        return none_fits(e, r);
    if (best.support == 0) return no_clue(e, r);
    DialectChoice choice{best.dialect, e.describe(side_of(best.dialect))};
    const Reading& second = *order[1];
    if (second.score > 0 && best.score - second.score < margin) {
        choice.close = second.dialect;
        choice.reason += "; close to " + std::string(dialect_name(second.dialect)) + " (" +
                         e.describe(side_of(second.dialect)) + "): only what both readings find is reported";
    }
    std::string misfits = misfit_text(r);
    if (!misfits.empty()) choice.reason += "; " + misfits;
    return choice;
}

}  // namespace tape
