// Lint: the rules of ГОСТ 20999-83 §1.4-§2.7 over loaded programs.
#include <algorithm>
#include <array>

#include "tape/functions.hpp"
#include "tape/lint.hpp"

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
    case 'F': return 40;
    case 'S': return 50;
    case 'T': return 60;
    case 'M': return 70;
    default: return -1;
    }
}

bool is_dimension(char a) {
    return dimension_order.find(a) != std::string_view::npos || interpolation_order.find(a) != std::string_view::npos;
}

class Linter {
public:
    Linter(const LoadedTape& t, const LintOptions& o) : t_(t), o_(o) {}

    std::vector<Finding> run() {
        out_ = t_.findings;
        if (t_.programs.empty())
            add("no-program", Severity::error, t_.locate(t_.text.size()), 0, "no '%' program start on the tape (§1.4)");
        for (const auto& p : t_.programs) program(p);
        std::stable_sort(out_.begin(), out_.end(), [](const Finding& a, const Finding& b) { return a.where.byte < b.where.byte; });
        return std::move(out_);
    }

private:
    const LoadedTape& t_;
    const LintOptions& o_;
    std::vector<Finding> out_;

    void add(std::string_view rule, Severity s, const Location& where, std::uint64_t block, std::string message) {
        out_.push_back(program_finding(rule, s, where, block, std::move(message)));
    }

    void program(const Program& p) {
        if (p.blocks.empty())
            add("program-start", Severity::error, p.start, 0, "'%' is not followed by a block (§1.4)");
        if (p.after_end_at && p.after_end.find_first_not_of(" \t\r\n") != std::string::npos)
            add("after-end", Severity::info, *p.after_end_at, 0, "text after M02/M30 is not part of the program (§1.9)");
        bool points = uses_explicit_points(p);
        std::optional<long long> last_number;
        for (const auto& b : p.blocks) {
            block(b, points);
            if (b.number) {
                auto n = b.number->integer();
                if (n && last_number && *n <= *last_number)
                    add("block-number-order", Severity::warning, b.number->where, b.ordinal,
                        "block number " + b.number->text + " does not increase (the block before is " + std::to_string(*last_number) + ")");
                if (n) last_number = n;
            }
        }
    }

    void block(const Block& b, bool points) {
        std::array<const Word*, 128> seen{};
        std::array<const Word*, 128> group{};
        int max_rank = -1;
        const Word* max_word = nullptr;
        const Word* previous = nullptr;
        for (const auto& w : b.words) {
            auto a = static_cast<unsigned char>(w.address);
            if (is_dimension(w.address)) {
                if (seen[a])
                    add("repeated-dimension", Severity::error, w.where, b.ordinal,
                        w.text + " repeats " + seen[a]->text + ": a dimension or interpolation word may stand once in a block (§2.4)");
                else seen[a] = &w;
            }
            if (w.address == 'G' && w.integer())
                if (const NcFunction* f = find_nc_function('G', *w.integer()); f && f->group) {
                    auto g = static_cast<unsigned char>(f->group);
                    if (group[g])
                        add("g-group", Severity::error, w.where, b.ordinal,
                            w.text + " and " + group[g]->text + " are both of group " + f->group + " (§2.5, table 4)");
                    else group[g] = &w;
                }
            if (w.sign && unsigned_addresses.find(w.address) != std::string_view::npos)
                add("sign-not-allowed", Severity::error, w.where, b.ordinal, w.text + ": " + w.address + " words have no sign (§3.1.1, §3.3)");
            int rank = order_rank(w.address);
            // A feed that follows the dimension word of its own axis may stand there (§2.2).
            bool axis_feed_before = previous && previous->address == 'F' && max_word == previous;
            if (rank >= 0 && rank < max_rank && !(axis_feed_before && is_dimension(w.address)))
                add("word-order", Severity::warning, w.where, b.ordinal,
                    w.text + " stands after " + max_word->text + "; recommended order G, X Y Z U V W P Q R A B C, I J K, F, S, T, M (§2.2)");
            if (rank > max_rank) {
                max_rank = rank;
                max_word = &w;
            }
            previous = &w;
        }
        if (o_.spec) spec_checks(b, points);
    }

    void spec_checks(const Block& b, bool points) {
        const FormatSpec& s = *o_.spec;
        if (b.main && !s.main_block) add("spec-main", Severity::error, b.where, b.ordinal, "the controller format has no ':' main blocks");
        if (b.skip && !s.block_skip) add("spec-skip", Severity::error, b.where, b.ordinal, "the controller format has no '/' block skip");
        auto check = [&](const Word& w) {
            for (auto& [rule, message] : check_word(w, s, points)) add(rule, Severity::error, w.where, b.ordinal, message);
        };
        if (b.number) check(*b.number);
        for (const auto& w : b.words) check(w);
    }
};

}  // namespace

bool uses_explicit_points(const Program& program) {
    for (const auto& b : program.blocks)
        for (const auto& w : b.words)
            if (w.has_point()) return true;
    return false;
}

std::vector<Finding> lint(const LoadedTape& tape, const LintOptions& options) { return Linter(tape, options).run(); }

}  // namespace tape
