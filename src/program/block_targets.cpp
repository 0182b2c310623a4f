// Block targets of a Fanuc or Haas program (program/block_targets.hpp).
#include "program/block_targets.hpp"

#include <algorithm>

namespace tape::lint_detail {
namespace {

constexpr std::size_t lines_listed = 4;  // of a repeated block number, the lines named

std::optional<long long> code(const Block& b, char address, std::initializer_list<long long> codes) {
    for (const auto& w : b.words)
        if (w.address == address && w.known && !w.macro && w.integer() &&
            std::find(codes.begin(), codes.end(), *w.integer()) != codes.end())
            return w.integer();
    return std::nullopt;
}

const Word* plain(const Block& b, char address) {
    for (const auto& w : b.words)
        if (w.address == address && w.known && !w.macro && !w.sign && w.integer()) return &w;
    return nullptr;
}

std::string lines_of(const std::vector<Location>& where, std::uint64_t count) {
    std::string out;
    for (const auto& l : where) out += (out.empty() ? "" : ", ") + std::to_string(l.line);
    if (count > where.size()) out += " and " + std::to_string(count - where.size()) + " more";
    return out;
}

}  // namespace

void BlockTargets::block(const Block& b) {
    if (b.number)
        if (auto n = b.number->integer()) numbered_.push_back({*n, b.ordinal, b.number->where});
    for (const auto& s : b.statements)
        if ((s.kind == Statement::Kind::if_goto || s.kind == Statement::Kind::go_to) && s.number)
            targets_.push_back({"goto-target", "GOTO " + std::to_string(*s.number), *s.number, s.where, b.ordinal});
    // Both kinds of target are P words: a block without one (most) names none.
    if (std::none_of(b.words.begin(), b.words.end(), [](const Word& w) { return w.address == 'P'; })) return;
    cycle_targets(b);
    if (code(b, 'M', {97}))
        if (const Word* p = plain(b, 'P'))
            targets_.push_back({"block-target", "M97 " + p->text, *p->integer(), p->where, b.ordinal});
}

// G70-G73 with P and Q: the lathe cycles' profile, from block P to block Q. The mill's G73 (peck
// drilling: X Y Z R Q) names no block, nor the cycles' first blocks (G71 U R).
void BlockTargets::cycle_targets(const Block& b) {
    auto g = code(b, 'G', {70, 71, 72, 73});
    const Word* p = plain(b, 'P');
    const Word* q = plain(b, 'Q');
    if (!g || !p || !q) return;
    if (std::any_of(b.words.begin(), b.words.end(), [](const Word& w) {
            return w.address == 'X' || w.address == 'Y' || w.address == 'Z' || w.address == 'R';
        }))
        return;
    std::string cycle = "G" + std::to_string(*g) + " ";
    targets_.push_back({"block-target", cycle + p->text, *p->integer(), p->where, b.ordinal});
    targets_.push_back({"block-target", cycle + q->text, *q->integer(), q->where, b.ordinal});
}

// The numbered blocks are sorted by number only when a target asks: most programs name none, and a
// long one then costs a record a block, not a map's node.
void BlockTargets::close(const std::function<void(Finding)>& out) {
    if (!targets_.empty()) {
        auto by_number = [](const NumberAt& a, const NumberAt& b) { return a.number < b.number; };
        std::stable_sort(numbered_.begin(), numbered_.end(), by_number);  // equal numbers keep their order
        std::vector<long long> said;  // a repeated number is said once, for the first target naming it
        for (const auto& t : targets_) {
            auto [first, last] =
                std::equal_range(numbered_.begin(), numbered_.end(), NumberAt{t.number, 0, {}}, by_number);
            if (first == last) {
                missing(t, out);
            } else if (last - first > 1 && std::find(said.begin(), said.end(), t.number) == said.end()) {
                said.push_back(t.number);
                Numbered n{static_cast<std::uint64_t>(last - first), {}, std::next(first)->block};
                for (auto at = first; at != last && n.where.size() < lines_listed; ++at) n.where.push_back(at->where);
                repeated(t, n, out);
            }
        }
    }
    targets_.clear();
    numbered_.clear();
}

void BlockTargets::missing(const Target& t, const std::function<void(Finding)>& out) const {
    std::string n = "N" + std::to_string(t.number);
    std::string message = t.rule == "goto-target" ? t.named_by + ": no block " + n + " in this program"
                          : t.named_by.starts_with("M97")
                              ? t.named_by + " calls block " + n +
                                    ", which this program does not have (M97 calls a block of the same program): "
                                    "the control stops with an alarm"
                              : t.named_by + " names block " + n +
                                    ", which this program does not have: the cycle's profile runs from its P block to "
                                    "its Q block, and the control stops with an alarm";
    out(program_finding(t.rule, t.where, t.block, std::move(message)));
}

void BlockTargets::repeated(const Target& t, const Numbered& n, const std::function<void(Finding)>& out) const {
    std::string number = "N" + std::to_string(t.number);
    out(program_finding("duplicate-target", n.where[1], n.second_block,
                        number + " stands " + std::to_string(n.count) + " times in this program (lines " +
                            lines_of(n.where, n.count) + ") and " + t.named_by + " (line " +
                            std::to_string(t.where.line) + ") names it: the control goes to the one it finds " +
                            "first, which may not be the one meant"));
}

}  // namespace tape::lint_detail
