// What the vote could not settle by the reads alone, decided by the program's rules where one choice
// breaks them and the other does not (repair.hpp): how many times a run's frame is punched ("X-0040000"
// read with a zero more, where X words on this tape have seven digits, is decided by the word format,
// not by the odds of a lost or a doubled frame), and whether a frame the reads disagree on stands at all
// ("X-504.645 768.74" without the Y two reads lost is no block).
#include <algorithm>
#include <cctype>

#include "repair.hpp"
#include "repair_world.hpp"

namespace tape::detail {
namespace {

// The image as the verdicts make it, and where each column's frame stands (or would stand) in it.
struct Draft {
    std::vector<Frame> frames;
    std::vector<std::size_t> place;  // per column: its frame's index, or the index it would take
    std::vector<std::size_t> doubtful;
};

Draft draft(const VoteResult& vote) {
    Draft d;
    d.place.reserve(vote.verdicts.size());
    for (const auto& v : vote.verdicts) {
        d.place.push_back(d.frames.size());
        // A frame left out in doubt (a run's copy not written) puts its line in doubt as much as one
        // written: what the rules learn must not take the vote's choice for the tape's own way.
        if (v.status != FrameStatus::clean && (v.write || d.doubtful.empty() || d.doubtful.back() != d.frames.size()))
            d.doubtful.push_back(d.frames.size());
        if (v.write) d.frames.push_back(v.written);
    }
    return d;
}

// Decides, in tape order, the runs and the contested frames the rules can, keeping the draft image true
// to the verdicts as they change.
class RuleDecider {
public:
    RuleDecider(const VoteContext& v, VoteResult& vote, const RestoreOptions& o, Draft img, RepairWorld& world)
        : v_(v), vote_(vote), o_(o), img_(std::move(img)), world_(world) {}

    void run(std::size_t r);
    void presence(std::size_t c);

private:
    // Which of two counts of copies of value at the image's frame `first` (holding `written`) the
    // rules leave: 1 for the first, 2 for the second, 0 for neither or both; breaks: what the other broke.
    int choose(std::size_t first, std::size_t written, std::size_t one, std::size_t two, Frame value, Breaks& breaks);
    void resize(std::size_t first, std::ptrdiff_t delta, Frame value);
    bool habit_too_weak(std::size_t first, const Breaks& breaks, double odds) const;
    bool is_letter(Frame f) const;

    const VoteContext& v_;
    VoteResult& vote_;
    const RestoreOptions& o_;
    Draft img_;
    RepairWorld& world_;
    std::ptrdiff_t shift_ = 0;  // frames the decisions so far added (+) or took out (-)
};

int RuleDecider::choose(std::size_t first, std::size_t written, std::size_t one, std::size_t two, Frame value,
                        Breaks& breaks) {
    auto range = block_around(*v_.code, img_.frames, std::min(first, img_.frames.size() - 1));
    if (!range || first + written > range->second) return 0;
    // The frames in question; where none is written, the frame after the gap, whose word stands there.
    std::vector<std::size_t> places;
    for (std::size_t k = 0; k < std::max<std::size_t>(written, 1); ++k) places.push_back(first + k);
    BlockJudge judge(world_.setup, img_.frames, range->first, range->second, world_.line_of(first), places);
    std::size_t local = first - range->first;
    Breaks a = judge.judge(with_copies(judge.frames(), local, written, one, value));
    Breaks b = judge.judge(with_copies(judge.frames(), local, written, two, value));
    // The arc rule decides only where one of the two closes the arc.
    bool closes = std::erase(a, std::string(arc_closes)) + std::erase(b, std::string(arc_closes)) > 0;
    if (!closes) std::erase(a, std::string("arc")), std::erase(b, std::string("arc"));
    if (a.empty() == b.empty()) return 0;
    breaks = a.empty() ? b : a;
    return a.empty() ? 1 : 2;
}

// Where the likeliest length breaks only how the tape writes the word (its format: a habit, which a
// program may break once), the habit must rest on more words than the likeliest length is likelier: 110
// X words of six decimals do not overturn two reads of three that read one word with five.
bool RuleDecider::habit_too_weak(std::size_t first, const Breaks& breaks, double odds) const {
    if (breaks.size() != 1 || breaks.front() != "word-format" || !world_.rules) return false;
    std::size_t at = first;
    while (at > 0 && !is_letter(img_.frames[at - 1])) --at;
    if (at == 0) return false;
    char address = static_cast<char>(std::toupper(static_cast<unsigned char>(v_.code->character(img_.frames[at - 1]))));
    if (address == '\n') return false;  // no word's letter before the run in its block: no habit to weigh
    if (address == ':') address = 'N';  // an ISO main block's number is an N word
    return static_cast<double>(world_.rules->words_of(address)) < odds;
}

// A word's address letter, a main block's ':', or the end of the block before.
bool RuleDecider::is_letter(Frame f) const {
    if (v_.code->kind(f) != FrameKind::character) return false;
    char c = v_.code->character(f);
    return std::isalpha(static_cast<unsigned char>(c)) || c == '\n' || c == ':';
}

void RuleDecider::resize(std::size_t first, std::ptrdiff_t delta, Frame value) {
    auto at = img_.frames.begin() + static_cast<std::ptrdiff_t>(first);
    if (delta > 0)
        img_.frames.insert(at, static_cast<std::size_t>(delta), value);
    else
        img_.frames.erase(at, at - delta);
    for (auto& b : world_.block_starts)
        if (b > first) b = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(b) + delta);
    shift_ += delta;
}

void RuleDecider::run(std::size_t r) {
    RunDecision& d = vote_.runs[r];
    std::size_t first = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(img_.place[d.first]) + shift_);
    Breaks breaks;
    int chosen = choose(first, d.length, d.length, d.alternative, d.value, breaks);
    if (chosen == 0) return;
    if (chosen == 2 && habit_too_weak(first, breaks, d.odds)) {
        // Too weak to overturn the reads, not to doubt them.
        d.doubt =
            joined(breaks) + ", a habit of the tape's too seldom seen to overturn the reads, so it stays in doubt";
        return revote_run(v_, o_, vote_, r);
    }
    if (chosen == 2) {
        std::swap(d.length, d.alternative);
        resize(first, static_cast<std::ptrdiff_t>(d.length) - static_cast<std::ptrdiff_t>(d.alternative), d.value);
    }
    d.rule = joined(breaks);
    revote_run(v_, o_, vote_, r);
}

void RuleDecider::presence(std::size_t c) {
    Verdict& d = vote_.verdicts[c];
    std::size_t first = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(img_.place[c]) + shift_);
    if (!d.write && first >= img_.frames.size()) return;
    Breaks breaks;
    int chosen = choose(first, d.write ? 1 : 0, 1, 0, d.written, breaks);
    if (chosen == 0) return;
    // The rules settle whether a frame stands here, not which: the one read that has it may have misread
    // it (a stain), so it stays in doubt.
    bool write = chosen == 1;
    if (write != d.write) resize(first, write ? 1 : -1, d.written);
    d.write = write;
    d.presence = false;
    RestoreProblem& p = vote_.problems[static_cast<std::size_t>(d.problem)];
    if (write && d.status == FrameStatus::extra) d.status = p.status = FrameStatus::contested;
    p.reason += "; the program's rules decide that it stands " + std::string(write ? "here" : "nowhere") + " (" +
                std::string(write ? "without" : "with") + " it the block breaks " + joined(breaks) + ")" +
                (write ? ": written" : ": not written");
}

// A frame whose presence is contested, alone: a stretch one read lacks (torn, or slipped) is decided as a
// whole by the vote, not a frame at a time.
bool lone_presence(const VoteResult& vote, std::size_t c) {
    const auto& v = vote.verdicts;
    return v[c].presence && v[c].problem >= 0 && (c == 0 || !v[c - 1].presence) &&
           (c + 1 == v.size() || !v[c + 1].presence);
}

}  // namespace

std::unique_ptr<RepairWorld> decide_runs_by_rules(const VoteContext& v, VoteResult& vote, const RestoreOptions& o) {
    // A length a million times likelier than the next (most runs, with five reads) is not held against
    // the rules: they would confirm it, or, where the program breaks its own habit, overturn the reads.
    constexpr double beyond_rules = 1e6;
    auto open = [&](const RunDecision& d) {
        return !d.blank_end && d.length != d.alternative && d.length > 0 && d.odds < beyond_rules;
    };
    bool any_presence =
        std::any_of(vote.verdicts.begin(), vote.verdicts.end(), [](const Verdict& d) { return d.presence; });
    if (!any_presence && std::none_of(vote.runs.begin(), vote.runs.end(), open)) return nullptr;
    Draft img = draft(vote);
    if (code_does_not_fit(img.frames, *v.code)) return nullptr;
    auto world = learn_world(img.frames, img.doubtful, *v.code, o);
    if (!world->setup.nc) return world;
    RuleDecider decide(v, vote, o, std::move(img), *world);
    std::size_t r = 0;
    for (std::size_t c = 0; c < vote.verdicts.size(); ++c) {
        for (; r < vote.runs.size() && vote.runs[r].first <= c; ++r)
            if (open(vote.runs[r])) decide.run(r);
        if (lone_presence(vote, c)) decide.presence(c);
    }
    for (; r < vote.runs.size(); ++r)
        if (open(vote.runs[r])) decide.run(r);
    return world;
}

}  // namespace tape::detail
