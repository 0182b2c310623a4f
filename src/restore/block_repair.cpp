// One block's open frames decided together (block_repair.hpp).
#include "block_repair.hpp"

#include <algorithm>
#include <cctype>

namespace tape::detail {
namespace {

// A frame a part program's text can hold: printable, the ends of block and tab, or one a reader skips
// (blank tape, DEL). Other control characters are never taken for a repair.
bool program_frame(const FrameCode& code, Frame f) {
    FrameKind k = code.kind(f);
    if (k == FrameKind::blank || k == FrameKind::rubout) return true;
    if (k != FrameKind::character) return false;
    char c = code.character(f);
    return (c >= 0x20 && c < 0x7F) || c == '\n' || c == '\r' || c == '\t';
}

// The single-hole changes of what the reads saw that are program frames: those all reads allow, or,
// where they allow none in common, those any allows. A blank reading among readings with holes says
// nothing of which character it was (it may have lost its holes), but the frame may be blank tape.
std::vector<Frame> single_hole_changes(const FrameCode& code, const RestoreProblem& p) {
    bool holes = std::any_of(p.seen.begin(), p.seen.end(), [](auto& f) { return f && *f != blank_frame; });
    std::vector<Frame> shared, any;
    bool first = true, blank_seen = false;
    for (const auto& seen : p.seen) {
        if (!seen) continue;
        if (holes && *seen == blank_frame) {
            blank_seen = true;
            continue;
        }
        std::vector<Frame> mine;
        for (int bit = 0; bit < 8; ++bit) {
            Frame c = static_cast<Frame>(*seen ^ (1U << bit));
            if (program_frame(code, c)) mine.push_back(c);
        }
        for (Frame c : mine)
            if (std::find(any.begin(), any.end(), c) == any.end()) any.push_back(c);
        if (first)
            shared = mine;
        else
            std::erase_if(shared, [&](Frame c) { return std::find(mine.begin(), mine.end(), c) == mine.end(); });
        first = false;
    }
    std::vector<Frame> out = shared.empty() ? any : shared;
    if (blank_seen && std::find(out.begin(), out.end(), blank_frame) == out.end()) out.push_back(blank_frame);
    return out;
}

// A letter, a digit, or what a word is written with (sign, point, space, end of block).
bool plain(const FrameCode& code, Frame f) {
    if (code.kind(f) != FrameKind::character) return false;
    char c = code.character(f);
    return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-' || c == ' ' || c == '\n';
}

// A character that gives a block structure: comments, macros, tabs, block skips and the like.
bool structural(const FrameCode& code, Frame f) { return code.kind(f) == FrameKind::character && !plain(code, f); }

// "'1' (the others break unknown-code, block-number)".
std::string ruled_out(const std::vector<std::string>& rules) {
    if (rules.empty()) return "";
    std::string s = ": the others break ";
    for (std::size_t i = 0; i < rules.size(); ++i) s += (i ? ", " : "") + rules[i];
    return s;
}

// The damaged frames of one block, their candidates tried together.
class BlockRepair {
public:
    BlockRepair(const RepairWorld& w, RestoreResult& out, std::vector<RestoreProblem*> block, bool guess)
        : w_(w), out_(out), block_(std::move(block)), guess_(guess) {}

    void run();

private:
    struct Tried {
        std::vector<Frame> choice;  // per damaged frame (as read where it has no candidate)
        Breaks breaks;
    };
    std::size_t at(std::size_t k) const { return static_cast<std::size_t>(*block_[k]->frame - 1); }
    void try_all(const BlockJudge* judge, std::size_t from, std::size_t to);
    void ignore_rules_every_try_breaks();
    double score(const Tried& t) const;
    Frame likeliest(std::size_t k, const std::vector<Frame>& values) const;
    void decide(std::size_t k);
    void decide_tie(std::size_t k, const std::vector<Frame>& fit, bool structural_alone);
    void guess(std::size_t k, const std::vector<Frame>& fit);
    /// Problem k is a disagreement between good readings (its candidates), not a frame no read has right.
    bool tie(std::size_t k) const { return tie_[k]; }

    const RepairWorld& w_;
    RestoreResult& out_;
    std::vector<RestoreProblem*> block_;
    bool guess_;
    std::vector<std::vector<Frame>> options_;
    std::vector<bool> tie_;
    std::vector<Tried> tried_;
    std::vector<std::string> ruled_out_;
    const Tried* best_ = nullptr;
    bool one_at_a_time_ = false;  // too many choices: each frame tried with the others as read
};

// More choices than this are tried one frame at a time, the others as read.
constexpr std::size_t most_choices = 2048;

void BlockRepair::try_all(const BlockJudge* judge, std::size_t from, std::size_t to) {
    std::size_t choices = 1;
    for (const auto& o : options_) choices = std::min(choices * std::max<std::size_t>(o.size(), 1), most_choices + 1);
    auto one = [&](const std::vector<Frame>& choice) {
        Tried t{choice, {}};
        if (judge) {
            BlockTry bt{std::vector<Frame>(out_.frames.begin() + static_cast<std::ptrdiff_t>(from),
                                           out_.frames.begin() + static_cast<std::ptrdiff_t>(to)),
                        {}};
            for (std::size_t k = 0; k < block_.size(); ++k) {
                bt.frames[at(k) - from] = choice[k];
                bt.decided.push_back(at(k) - from);
            }
            t.breaks = judge->judge(bt);
        }
        tried_.push_back(std::move(t));
    };
    std::vector<Frame> as_read(block_.size());
    for (std::size_t k = 0; k < block_.size(); ++k) as_read[k] = out_.frames[at(k)];
    if (choices > most_choices) {
        one_at_a_time_ = true;
        for (std::size_t k = 0; k < block_.size(); ++k)
            for (Frame f : options_[k]) {
                auto choice = as_read;
                choice[k] = f;
                one(choice);
            }
        return;
    }
    std::vector<std::size_t> pick(block_.size(), 0);
    for (std::size_t n = 0; n < choices; ++n) {
        auto choice = as_read;
        for (std::size_t k = 0; k < block_.size(); ++k)
            if (!options_[k].empty()) choice[k] = options_[k][pick[k]];
        one(choice);
        for (std::size_t k = 0; k < block_.size(); ++k) {
            if (options_[k].empty()) continue;
            if (++pick[k] < options_[k].size()) break;
            pick[k] = 0;
        }
    }
}

// A rule every try breaks decides nothing: the block breaks it whatever the damaged frames were (the
// program's own mistake, or a rule that does not hold for this program). Nor does the arc rule where no
// try closes the arc: a try that only escapes it by making the block no arc is no better.
void BlockRepair::ignore_rules_every_try_breaks() {
    bool some_arc_closes = std::any_of(tried_.begin(), tried_.end(), [](const Tried& t) {
        return std::find(t.breaks.begin(), t.breaks.end(), arc_closes) != t.breaks.end();
    });
    for (auto& t : tried_) {
        std::erase(t.breaks, std::string(arc_closes));
        if (!some_arc_closes) std::erase(t.breaks, std::string("arc"));
    }
    std::vector<std::string> all;
    for (const auto& t : tried_) all.insert(all.end(), t.breaks.begin(), t.breaks.end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    for (const auto& rule : all) {
        bool everywhere = std::all_of(tried_.begin(), tried_.end(), [&](const Tried& t) {
            return std::find(t.breaks.begin(), t.breaks.end(), rule) != t.breaks.end();
        });
        if (everywhere)
            for (auto& t : tried_) std::erase(t.breaks, rule);
        else
            ruled_out_.push_back(rule);
    }
}

// How likely a try's frames are where they stand, by how the tape goes.
double BlockRepair::score(const Tried& t) const {
    auto frame = [&](std::size_t i) {
        for (std::size_t j = 0; j < block_.size(); ++j)
            if (at(j) == i) return t.choice[j];
        return out_.frames[i];
    };
    double sum = 0;
    for (std::size_t k = 0; k < block_.size(); ++k) {
        Frame near[3] = {blank_frame, blank_frame, blank_frame};  // two before, one after
        std::size_t found = 0;
        for (std::size_t i = at(k); i-- > 0 && found < 2;)
            if (frame(i) != blank_frame) near[1 - found++] = frame(i);
        for (std::size_t i = at(k) + 1; i < out_.frames.size(); ++i)
            if (frame(i) != blank_frame) {
                near[2] = frame(i);
                break;
            }
        sum += w_.chars.score(near[0], near[1], t.choice[k], near[2]);
    }
    return sum;
}

// The likeliest of values for damaged frame k alone, the others as the best fitting try has them.
Frame BlockRepair::likeliest(std::size_t k, const std::vector<Frame>& values) const {
    Tried t{best_ ? best_->choice : std::vector<Frame>(block_.size()), {}};
    if (!best_)
        for (std::size_t j = 0; j < block_.size(); ++j) t.choice[j] = out_.frames[at(j)];
    Frame best = values.front();
    double best_score = -1e300;
    for (Frame f : values) {
        t.choice[k] = f;
        if (double sc = score(t); sc > best_score) best_score = sc, best = f;
    }
    return best;
}

// Other reads cover the place but have no frame there: the one reading may be a stain read as a frame,
// which a single-hole change does not undo.
bool lone_reading(const RestoreProblem& p) {
    for (std::size_t r = 0; r < p.seen.size(); ++r)
        if (p.covered[r] && !p.seen[r]) return true;
    return false;
}

void BlockRepair::decide(std::size_t k) {
    RestoreProblem& p = *block_[k];
    std::vector<Frame> fit;
    for (const auto& t : tried_)
        if (t.breaks.empty() && std::find(fit.begin(), fit.end(), t.choice[k]) == fit.end()) fit.push_back(t.choice[k]);
    if (options_[k].empty()) fit.clear();
    // Tried one at a time, a frame is judged beside the others' damage: it may look like it fits alone.
    // A sign of structure (a comment, a macro, a tab) that alone fits where letters and digits could
    // stand makes a block fit by hiding or changing what it is: weighed like any other, it decides nothing.
    bool structural_alone =
        fit.size() == 1 && structural(w_.setup.code, fit.front()) &&
        std::any_of(options_[k].begin(), options_[k].end(), [&](Frame f) { return plain(w_.setup.code, f); });
    if (tie(k)) return decide_tie(k, fit, structural_alone);
    p.candidates = fit;
    std::string with_others = block_.size() > 1 ? ", with the other damaged frames of its block" : "";
    bool lone = lone_reading(p);
    if (fit.size() == 1 && !one_at_a_time_ && !structural_alone && !lone) {
        set_status(out_, p, FrameStatus::inferred, fit.front(),
                   "the one single-hole change that fits its block" + with_others + ruled_out(ruled_out_));
        return;
    }
    if (guess_ && !options_[k].empty()) return guess(k, fit);
    p.reason = one_at_a_time_     ? "too many damaged frames in its block to try them together: not repaired"
               : structural_alone ? "only a character that gives the block another structure fits: not repaired"
               : lone && fit.size() == 1
                   ? "other reads that cover it have no frame here: what the one reading has may be a stain, not a "
                     "frame with a hole lost or gained; not repaired"
               : fit.empty() ? "no single-hole change makes a character that fits its block"
                             : std::to_string(fit.size()) + " single-hole changes fit its block: not guessed";
}

// Good readings that disagree: the one the block's rules leave is voted; else, with --guess, the
// likeliest is guessed (the one a reading failing parity is one hole from, where the vote found one).
void BlockRepair::decide_tie(std::size_t k, const std::vector<Frame>& fit, bool structural_alone) {
    RestoreProblem& p = *block_[k];
    if (fit.size() == 1 && !one_at_a_time_ && !structural_alone) {
        set_status(out_, p, FrameStatus::voted, fit.front(),
                   "good readings disagree; the program's rules leave one" +
                       std::string(block_.size() > 1 ? ", with the other open frames of its block" : "") +
                       ruled_out(ruled_out_));
        return;
    }
    if (guess_) guess(k, fit);
}

void BlockRepair::guess(std::size_t k, const std::vector<Frame>& fit) {
    RestoreProblem& p = *block_[k];
    const std::vector<Frame>& among = fit.empty() ? options_[k] : fit;
    bool leans = tie(k) && p.reason.find("one hole from") != std::string::npos &&
                 std::find(among.begin(), among.end(), p.candidates.front()) != among.end();
    Frame g = leans                                      ? p.candidates.front()
              : !one_at_a_time_ && best_ && !fit.empty() ? best_->choice[k]
                                                         : likeliest(k, among);
    p.candidates = among;
    std::erase(p.candidates, g);
    p.candidates.insert(p.candidates.begin(), g);
    std::string what = tie(k) ? " good readings that disagree" : " single-hole changes";
    set_status(out_, p, FrameStatus::guessed, g,
               "the likeliest of " + std::to_string(among.size()) + what +
                   (fit.empty()                                  ? " (none fits its block)"
                    : tie(k) && fit.size() == options_[k].size() ? ""
                                                                 : " that fit its block") +
                   ", by how the tape goes" + (leans ? " (a reading failing parity is one hole from it)" : ""));
}

void BlockRepair::run() {
    for (RestoreProblem* p : block_) {
        tie_.push_back(p->status != FrameStatus::unresolved);
        if (tie_.back()) {
            options_.push_back(p->candidates);
            continue;
        }
        options_.push_back(single_hole_changes(w_.setup.code, *p));
        // A frame a reader skips stands inside a line only where this tape has such frames inside lines.
        std::erase_if(options_.back(), [&](Frame f) {
            FrameKind k = w_.setup.code.kind(f);
            return (k == FrameKind::rubout && !w_.rubouts) || (k == FrameKind::blank && !w_.blank_inside_lines);
        });
    }
    auto range = block_around(w_.setup.code, out_.frames, at(0));
    if (range && at(block_.size() - 1) >= range->second) range.reset();
    std::optional<BlockJudge> judge;
    if (w_.setup.nc && range) {
        std::vector<std::size_t> damaged;
        for (std::size_t k = 0; k < block_.size(); ++k) damaged.push_back(at(k));
        judge.emplace(w_.setup, out_.frames, range->first, range->second, w_.line_of(at(0)), damaged);
    }
    // A block longer than any block (the ends of block lost) is judged by the code alone.
    try_all(judge ? &*judge : nullptr, range ? range->first : 0, range ? range->second : 0);
    ignore_rules_every_try_breaks();
    double best_score = -1e300;
    for (const auto& t : tried_)
        if (t.breaks.empty() && score(t) > best_score) best_score = score(t), best_ = &t;
    for (std::size_t k = 0; k < block_.size(); ++k) decide(k);
}

}  // namespace

void set_status(RestoreResult& out, RestoreProblem& p, FrameStatus s, Frame f, std::string reason) {
    --out.counts[static_cast<std::size_t>(p.status)];
    ++out.counts[static_cast<std::size_t>(s)];
    p.status = s;
    p.written = out.frames[static_cast<std::size_t>(*p.frame - 1)] = f;
    p.reason = std::move(reason);
}

void repair_block(const RepairWorld& w, RestoreResult& out, std::vector<RestoreProblem*> block, bool guess) {
    BlockRepair(w, out, std::move(block), guess).run();
}

}  // namespace tape::detail
