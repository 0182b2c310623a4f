// The vote per aligned column (vote.hpp): what the heard reads have there, weighed; runs of equal frames
// whose length the reads disagree on are decided as a whole (run_length.cpp).
#include "vote.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tape::detail {
namespace {

// A frame the reader itself doubts weighs this much against a sure one.
constexpr double doubted_weight = 0.5;

struct Tally {
    Frame value;
    double weight;
    int count;
    bool good;
};

// What the reads say in one column.
struct Heard {
    std::vector<Tally> tally;  // good first, heaviest first
    std::size_t present = 0, covering = 0, lost = 0, unheard = 0;
    std::size_t present_good = 0, good_values = 0;
    std::size_t repeats = 0;           // reads that have their frame here next to an equal one
    std::optional<Frame> first_bad{};  // the first reading that fails parity (or a blank among punched frames)
};

void count_reading(Heard& h, Frame f, bool good, double weight) {
    auto t = std::find_if(h.tally.begin(), h.tally.end(), [&](const Tally& x) { return x.value == f; });
    if (t == h.tally.end())
        h.tally.push_back({f, weight, 1, good});
    else
        t->weight += weight, ++t->count;
}

Heard hear(const VoteContext& v, std::size_t c) {
    Heard h;
    bool punched_here = false;  // a heard read has a frame of holes here
    for (std::size_t r = 0; r < v.a.reads(); ++r) {
        if (!v.a.covers(r, c)) continue;
        ++h.covering;
        std::int32_t i = v.a.frame(c, r);
        bool heard = v.heard(c, r);
        if (i == ReadAlignment::none || !heard) {
            ++(heard ? h.lost : h.unheard);
            continue;
        }
        ++h.present;
        Frame f = v.reads[r][static_cast<std::size_t>(i)];
        punched_here |= f != blank_frame;
        h.repeats += repeated(v.reads[r], static_cast<std::size_t>(i));
        count_reading(h, f, v.good(f), v.doubts(c, r) ? doubted_weight : 1.0);
        if (!v.good(f) && !h.first_bad) h.first_bad = f;
    }
    // A blank frame inside data where the reads that have holes all fail parity is no good reading of a
    // character: it is a character that may have lost its holes. Only a majority of two or more blank
    // readings outweighs the holes.
    if (punched_here && v.in_data(c)) {
        int blanks = 0, bad_punched = 0;
        bool good_punched = false;
        for (const auto& t : h.tally) {
            if (t.value == blank_frame)
                blanks += t.count;
            else if (t.good)
                good_punched = true;
            else
                bad_punched += t.count;
        }
        if (!good_punched && (blanks < 2 || blanks <= bad_punched))
            for (auto& t : h.tally)
                if (t.value == blank_frame) t.good = false;
    }
    for (const auto& t : h.tally) {
        h.present_good += t.good ? static_cast<std::size_t>(t.count) : 0;
        h.good_values += t.good;
        if (!t.good && t.value != blank_frame && !h.first_bad) h.first_bad = t.value;
    }
    std::sort(h.tally.begin(), h.tally.end(),
              [](const Tally& x, const Tally& y) { return x.good != y.good ? x.good : x.weight > y.weight; });
    return h;
}

// Among good readings tied at the top of the tally: the one that a reading failing parity is one hole
// from, when that is true of just one.
std::optional<Frame> leaning(const std::vector<Tally>& tally) {
    std::optional<Frame> out;
    for (const auto& t : tally) {
        if (!t.good || t.weight != tally.front().weight) continue;
        bool near = std::any_of(tally.begin(), tally.end(),
                                [&](const Tally& bad) { return !bad.good && hole_count(bad.value ^ t.value) == 1; });
        if (!near) continue;
        if (out) return std::nullopt;
        out = t.value;
    }
    return out;
}

std::string of_reads(std::size_t k, std::size_t n, const char* what) {
    return std::to_string(k) + " of " + std::to_string(n) + " reads " + what;
}

// Reads heard well at a place with no frame there, enough that they did not all lose the same frame.
constexpr std::size_t enough_lacking = 3;

// Builds the problems and verdicts as the vote goes.
class Voter {
public:
    Voter(const VoteContext& v, const RestoreOptions& o, VoteResult& out) : v_(v), o_(o), out_(out) {}

    void column(std::size_t c, const RunDecision* run, bool run_writes);

private:
    void set(std::size_t c, FrameStatus s, Frame written, std::string reason, bool write, bool run_length = false);
    void only_misreadings(std::size_t c, const Heard& h);
    void run_column(std::size_t c, const RunDecision& d, bool writes, const Heard& h);
    bool presence(std::size_t c, const Heard& h);
    bool lone_frame(std::size_t c, const Heard& h, std::size_t lost);
    bool alone_beside(std::size_t c) const;
    bool gaps_are_lone(std::size_t c) const;
    void half_present(std::size_t c, const Heard& h);
    void values(std::size_t c, const Heard& h);
    bool misreads_beside(std::size_t c, std::size_t r) const;
    std::optional<Frame> from_steady_reads(std::size_t c, const std::vector<Frame>& tied) const;

    const VoteContext& v_;
    const RestoreOptions& o_;
    VoteResult& out_;
};

void Voter::set(std::size_t c, FrameStatus s, Frame written, std::string reason, bool write, bool run_length) {
    Verdict& d = out_.verdicts[c];
    d.status = s, d.written = written, d.write = write;
    if (s == FrameStatus::clean) {
        d.problem = -1;
        return;
    }
    RestoreProblem p;
    p.status = s;
    p.column = c;
    p.written = written;
    p.reason = std::move(reason);
    p.run_length = run_length;
    for (std::size_t r = 0; r < v_.a.reads(); ++r) {
        p.seen.push_back(frame_at(v_.a, v_.reads, c, r));
        p.covered.push_back(v_.a.covers(r, c));
    }
    if (d.problem >= 0) {
        out_.problems[static_cast<std::size_t>(d.problem)] = std::move(p);
        return;
    }
    d.problem = static_cast<std::int32_t>(out_.problems.size());
    out_.problems.push_back(std::move(p));
}

// Only reads that garbled this stretch have a frame here.
void Voter::only_misreadings(std::size_t c, const Heard& h) {
    Frame seen = 0;  // the first read's that has a frame here
    for (std::size_t r = v_.a.reads(); r-- > 0;) seen = frame_at(v_.a, v_.reads, c, r).value_or(seen);
    // Where several reads slipped, the others may have lost a frame that only a misreading shows; but not
    // three reads heard well here and none with a frame.
    if (v_.tangled[c] && h.lost < enough_lacking)
        set(c, FrameStatus::contested, seen,
            "only reads that misread this stretch have a frame here, and more than one read slipped in it: not "
            "written, but nothing decides",
            false);
    else
        set(c, FrameStatus::extra, seen,
            "a misreading: the read that has this frame lacks frames the others have next to it, so it read a "
            "stain or splice as other frames; not written",
            false);
}

// A run of equal frames whose length the reads disagree on: whether this column of it is written was
// decided for the whole run.
void Voter::run_column(std::size_t c, const RunDecision& d, bool writes, const Heard& h) {
    if (d.blank_end) {
        // Leader and trailer are blank tape: a stain some read has there is not written. (A DEC leader
        // of one frame, track 8 alone, is voted as any frame.)
        double blank = 0, most = 0;
        for (const auto& t : h.tally) {
            if (t.value == blank_frame) blank = t.weight;
            most = std::max(most, t.weight);
        }
        if (writes && blank > 0 && blank >= most && h.tally.size() > 1)
            set(c, FrameStatus::voted, blank_frame,
                "blank leader or trailer: what a read has there besides blank tape is a stain", true);
        else if (writes)
            values(c, h);
        else
            set(c, FrameStatus::extra, d.value,
                "blank leader or trailer that some reads have longer than most: not written", false);
        return;
    }
    bool everyone = h.lost == 0 && h.unheard == 0;
    if (writes && everyone) return values(c, h);
    bool decided = d.decided(o_.run_odds);
    char odds[64];
    if (d.odds > 1e6)
        std::snprintf(odds, sizeof odds, "over a million times");
    else
        std::snprintf(odds, sizeof odds, "%.0f times", d.odds);
    std::string likelier = d.alternative == d.length ? "the reads that cover it whole agree"
                                                     : std::to_string(d.length) + " punched is " + odds +
                                                           " likelier than " + std::to_string(d.alternative) +
                                                           ", with the lost and doubled frames these reads show";
    std::string why =
        "a run of " + std::to_string(d.length) + " (" + d.how + "): " +
        (d.rule.empty() ? likelier
                        : "the program's rules decide: " + std::to_string(d.alternative) + " copies break " + d.rule);
    if (decided)
        set(c, writes ? FrameStatus::voted : FrameStatus::extra, d.value,
            why + (writes ? ": written" : ": not written"), writes, true);
    else
        set(c, FrameStatus::contested, d.value,
            why + (d.doubt.empty() ? "; too close to decide: " : "; but it breaks " + d.doubt + ": ") +
                (writes ? "written" : "not written"),
            writes, true);
    if (d.rule.empty() && d.alternative != d.length)
        out_.problems[static_cast<std::size_t>(out_.verdicts[c].problem)].odds = d.odds;
}

// Whether a frame stands in this column at all, where the reads disagree on it and no run decides:
// true when that was settled here (not written, or written in doubt).
// The read alone here is alone in a neighbouring column too.
bool Voter::alone_beside(std::size_t c) const {
    auto al = v_.alone[c];
    return al != ReadAlignment::none &&
           ((c > 0 && v_.alone[c - 1] == al) || (c + 1 < v_.alone.size() && v_.alone[c + 1] == al));
}

// Every read without a frame here has one in both neighbouring columns: a lone gap, not a stretch missing.
bool Voter::gaps_are_lone(std::size_t c) const {
    for (std::size_t r = 0; r < v_.a.reads(); ++r) {
        if (!v_.a.covers(r, c) || v_.a.frame(c, r) != ReadAlignment::none) continue;
        auto gap = [&](std::size_t x) { return v_.a.covers(r, x) && v_.a.frame(x, r) == ReadAlignment::none; };
        if ((c > 0 && gap(c - 1)) || (c + 1 < v_.a.columns() && gap(c + 1))) return false;
    }
    return true;
}

// Half the reads covering column c have a good frame there, half none. A frame like its neighbour may be
// one read twice; one unlike them cannot be. (A read lacking a whole stretch, torn or slipped, is decided
// as one: written.)
void Voter::half_present(std::size_t c, const Heard& h) {
    const auto& front = h.tally.front();
    bool dropped = h.repeats > 0 && !alone_beside(c) && front.value != blank_frame && gaps_are_lone(c);
    out_.verdicts[c].presence = true;
    set(c, FrameStatus::contested, front.value,
        std::string("half the reads that cover this place have a frame here, half do not; ") +
            (dropped         ? "like its neighbour, it may be read twice: not written"
             : h.repeats > 0 ? "the others lack a stretch here: written"
                             : "unlike its neighbours, it cannot be read twice: written"),
        !dropped);
}

// One read has a frame unlike its neighbours (no double), and read well around it, that the others lack:
// written. A good one, in doubt: the others lost it, or a splice put it there. (Several such frames in a
// row are a stretch one read misread.) One failing parity: a frame the others lost, misread; written as
// read, in doubt (repaired where a change fits).
bool Voter::lone_frame(std::size_t c, const Heard& h, std::size_t lost) {
    const auto& front = h.tally.front();
    std::size_t present = front.good ? h.present_good : h.present;
    if (present != 1 || lost < 2 || h.repeats > 0 || front.value == blank_frame || alone_beside(c)) return false;
    // Many reads heard well here and none has it (18 of 20): not three reads lost the same frame, the one
    // that has it misread a stain or splice. Left out, as a frame most reads lack.
    if (lost >= enough_lacking && h.present < lost) return false;
    if (front.good) {
        out_.verdicts[c].presence = true;
        set(c, FrameStatus::contested, front.value,
            of_reads(1, h.covering, "has this frame") +
                ", not as a neighbour read twice: the others lost it, or a splice put it there; written",
            true);
    } else {
        set(c, FrameStatus::unresolved, front.value,
            of_reads(1, h.covering, "has a frame here") +
                ", failing parity and not as a neighbour read twice: the others lost it; written as read",
            true);
    }
    return true;
}

// Reads that have a frame here each have a different good one, next to an equal one in that read, and a
// read heard here has none ("G033 " and "G03  " beside "G03 "): two frames read twice explain it, where
// any one of them standing needs a frame lost by a read that has it and one more slip by the others.
bool doubles_of_their_neighbours(const Heard& h) {
    return h.lost >= 1 && h.present >= 2 && h.repeats == h.present && h.present_good == h.present &&
           h.good_values == h.present;
}

bool Voter::presence(std::size_t c, const Heard& h) {
    const auto& front = h.tally.front();
    const std::size_t reads = v_.a.reads();
    // Blank tape past the end of most reads: frames one read has there (a frame read twice there has
    // nothing to align by) are left out.
    bool lone_blank =
        reads > 1 && h.tally.size() == 1 && front.value == blank_frame && h.covering < reads && h.present * 2 <= reads;
    std::size_t lost = lone_blank ? reads - h.present : h.lost;
    std::size_t present = front.good ? h.present_good : h.present;
    if (lone_blank && present >= lost) return false;
    if (!lone_blank && lone_frame(c, h, lost)) return true;
    if (doubles_of_their_neighbours(h)) {
        set(c, FrameStatus::extra, front.value,
            of_reads(h.present, h.covering, "have a frame here") +
                ", each a different one next to an equal one in its read, and a read has none: each read its "
                "frame twice; not written",
            false);
        return true;
    }
    if (present < lost && (present <= 1 || h.good_values > 1 || !front.good || lone_blank)) {
        // Where several reads slipped in the stretch, a vote won by one read decides nothing.
        bool tangled = v_.tangled[c] && !lone_blank && lost - present <= 1;
        // A good frame unlike its neighbours is no frame read twice: the program's rules may say it stands.
        out_.verdicts[c].presence =
            tangled || (present == 1 && front.good && h.repeats == 0 && front.value != blank_frame);
        set(c, tangled ? FrameStatus::contested : FrameStatus::extra, front.value,
            of_reads(present, h.covering, "have this frame") +
                (tangled ? ", and more than one read slipped in this stretch: not written, but nothing decides"
                         : ": read twice or a splice, not written"),
            false);
        return true;
    }
    if (present < lost) {
        out_.verdicts[c].presence = true;
        set(c, FrameStatus::contested, front.value,
            of_reads(present, h.covering, "agree on this frame") +
                " and the others have none: lost by them, or read twice; not written, as most reads have none",
            false);
        return true;
    }
    if (present == lost && front.good) {
        half_present(c, h);
        return true;
    }
    if (lost > 0 && h.repeats > 0 && h.good_values == 1 && front.good) {
        out_.verdicts[c].presence = true;
        set(c, FrameStatus::contested, front.value,
            of_reads(present, h.covering, "have this frame") +
                " once more than the others, and too few reads cover the run to weigh it: written",
            true);
        return true;
    }
    return false;
}

// Read r has, in a column beside c, a good frame that two reads or more outvote with another good frame:
// it is misreading the stretch (a stain read as frames keeps the tape's length).
bool Voter::misreads_beside(std::size_t c, std::size_t r) const {
    for (std::size_t x : {c - 1, c + 1}) {
        if (x >= v_.a.columns()) continue;  // c - 1 of column 0 wraps past the end
        auto f = frame_at(v_.a, v_.reads, x, r);
        if (!f || !v_.good(*f) || !v_.heard(x, r)) continue;
        Heard beside = hear(v_, x);
        const auto& top = beside.tally.front();
        if (top.good && top.count >= 2 && top.value != *f) return true;
    }
    return false;
}

// Of the tied good readings, the one whose every read reads the frames beside as the others do, where
// each other's reads misread them.
std::optional<Frame> Voter::from_steady_reads(std::size_t c, const std::vector<Frame>& tied) const {
    std::optional<Frame> steady;
    for (Frame value : tied) {
        std::size_t reads = 0, misreading = 0;
        for (std::size_t r = 0; r < v_.a.reads(); ++r) {
            auto f = frame_at(v_.a, v_.reads, c, r);
            if (!f || *f != value || !v_.heard(c, r)) continue;
            ++reads;
            misreading += misreads_beside(c, r);
        }
        if (reads == 0 || misreading == reads) continue;    // only misreading reads have it
        if (misreading > 0 || steady) return std::nullopt;  // reads of one kind and the other, or two steady
        steady = value;
    }
    return steady;
}

// Which frame stands here, where one does.
void Voter::values(std::size_t c, const Heard& h) {
    const auto& t = h.tally;
    if (!t.front().good) {
        // Repaired later, if exactly one change fits; until then, as read.
        set(c, FrameStatus::unresolved, h.first_bad.value_or(t.front().value), "no read has a good frame here", true);
        return;
    }
    if (t.size() == 1 && h.lost == 0 && h.unheard == 0) return set(c, FrameStatus::clean, t.front().value, "", true);
    if (h.unheard > 0 && h.present == 1 && h.lost == 0) {
        out_.verdicts[c].presence = true;
        return set(c, FrameStatus::contested, t.front().value,
                   of_reads(1, h.covering, "has this frame") +
                       " and the others misread this stretch: written, but nothing backs it",
                   true);
    }
    // Several reads slipped in this stretch, and the good readings do not outnumber the reads lacking one.
    const bool tangled = v_.tangled[c] && h.lost > 0 && h.present_good <= h.lost + 1;
    if (t.size() == 1 || !t[1].good || t[0].weight > t[1].weight) {
        bool only_good = t.size() > 1 && !t[1].good && t[0].weight <= t[1].weight;
        std::string reason = only_good ? "the only good reading (the others fail parity or are blank among holes)"
                                       : of_reads(static_cast<std::size_t>(t[0].count), h.covering, "agree");
        if (tangled)
            return set(c, FrameStatus::contested, t[0].value,
                       reason + ", and more than one read slipped in this stretch: written, but nothing decides", true);
        return set(c, FrameStatus::voted, t[0].value, reason, true);
    }
    // Good readings tied: written as read, the reading failing parity where there is one (so that the
    // image says so); the tied readings are the candidates, the one a failing reading is one hole from first.
    bool all_differ = h.present_good >= 3 && t.size() == h.present_good;
    auto lean = leaning(t);
    std::vector<Frame> tied;
    if (lean) tied.push_back(*lean);
    for (const auto& x : t)
        if (x.good && x.weight == t[0].weight && (!lean || x.value != *lean)) tied.push_back(x.value);
    // Not where a reading failing parity leans to another, nor where several reads slipped here.
    auto steady = all_differ || tangled ? std::nullopt : from_steady_reads(c, tied);
    if (steady && (!lean || *lean == *steady))
        return set(c, FrameStatus::voted, *steady,
                   "good readings disagree; the others' reads misread the frames beside this one (outvoted there "
                   "by good readings): written",
                   true);
    std::optional<Frame> reference = frame_at(v_.a, v_.reads, c, v_.a.reference());
    Frame written = h.first_bad                        ? *h.first_bad
                    : lean                             ? *lean
                    : reference && v_.good(*reference) ? *reference
                                                       : t[0].value;
    set(c, all_differ ? FrameStatus::unstable : FrameStatus::contested, written,
        all_differ    ? "every read saw something else"
        : h.first_bad ? "good readings disagree and nothing decides: written as read, failing parity"
        : lean        ? "good readings disagree; a reading failing parity is one hole from this one, which is written"
                      : "good readings disagree and nothing decides; the reference read's is written",
        true);
    out_.problems.back().candidates = std::move(tied);
}

void Voter::column(std::size_t c, const RunDecision* run, bool run_writes) {
    out_.verdicts[c].presence = false;
    Heard h = hear(v_, c);
    if (h.tally.empty()) return only_misreadings(c, h);
    if (run) return run_column(c, *run, run_writes, h);
    if (!presence(c, h)) values(c, h);
}

// Of a run's columns, the `length` with the most frames heard (the first of equals; for the leader,
// the last: the leader ends where the data starts). In leader and trailer only blank tape counts (a
// frame of one hole is blank misread); a stain there is never written.
std::vector<bool> written_columns(const VoteContext& v, const RunDecision& d) {
    std::vector<std::pair<std::size_t, std::size_t>> by;  // (frames, column)
    for (std::size_t c = d.first; c < d.end; ++c) {
        std::size_t n = 0;
        for (std::size_t r = 0; r < v.a.reads(); ++r) {
            auto f = frame_at(v.a, v.reads, c, r);
            n += f && v.heard(c, r) && (!d.blank_end || hole_count(*f) <= 1);
        }
        if (n > 0 || !d.blank_end) by.emplace_back(n, c);
    }
    bool leader = d.blank_end && d.first == 0;
    std::stable_sort(by.begin(), by.end(), [&](const auto& x, const auto& y) {
        return x.first != y.first ? x.first > y.first : leader ? x.second > y.second : x.second < y.second;
    });
    std::vector<bool> out(d.end - d.first, false);
    for (std::size_t k = 0; k < std::min(d.length, by.size()); ++k) out[by[k].second - d.first] = true;
    return out;
}

}  // namespace

void revote_run(const VoteContext& v, const RestoreOptions& o, VoteResult& out, std::size_t run) {
    Voter voter(v, o, out);
    const RunDecision& d = out.runs[run];
    std::vector<bool> writes = written_columns(v, d);
    for (std::size_t c = d.first; c < d.end; ++c) voter.column(c, &d, writes[c - d.first]);
}

VoteResult vote(const VoteContext& v, const RestoreOptions& o) {
    VoteResult out;
    out.verdicts.resize(v.a.columns());
    out.runs = decide_runs(v);
    Voter voter(v, o, out);
    std::size_t next_run = 0;
    std::vector<bool> writes;
    for (std::size_t c = 0; c < v.a.columns(); ++c) {
        while (next_run < out.runs.size() && out.runs[next_run].end <= c) ++next_run;
        const RunDecision* run =
            next_run < out.runs.size() && out.runs[next_run].first <= c ? &out.runs[next_run] : nullptr;
        if (run && c == run->first) writes = written_columns(v, *run);
        voter.column(c, run, run && writes[c - run->first]);
    }
    return out;
}

}  // namespace tape::detail
