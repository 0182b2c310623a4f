// Restoration: a vote per aligned column, then single-hole repair of what no read has right, checked
// against the grammar of the block it stands in (tape/restore.hpp).
#include "tape/restore.hpp"

#include <algorithm>
#include <array>

#include "tape/decode.hpp"
#include "tape/lint.hpp"

namespace tape {
namespace {

bool good(const std::optional<FrameCode>& code, Frame f) {
    if (!code) return true;
    FrameKind k = code->kind(f);
    return k != FrameKind::parity_error && k != FrameKind::not_in_code;
}

// The decoded text of frames [from, to), a bad frame as U+FFFD, one frame replaced by `with`.
std::string decoded(const FrameCode& code, std::span<const Frame> frames, std::size_t from, std::size_t to,
                    std::size_t at, Frame with) {
    std::string s;
    for (std::size_t i = from; i < to; ++i) {
        Frame f = i == at ? with : frames[i];
        FrameKind k = code.kind(f);
        if (k == FrameKind::character)
            s += code.character(f);
        else if (k == FrameKind::parity_error || k == FrameKind::not_in_code)
            s += bad_frame_marker;
    }
    return s;
}

// True when the block (the line) holding frame at reads with no error once the frame is `with`. The
// next line is loaded too, as context (a '%' line needs the block after it), but only the block's
// own lines (two, when `with` is an end of block) must be free of errors.
bool fits_block(const FrameCode& code, std::span<const Frame> frames, std::size_t at, Frame with, Dialect dialect,
                const FormatSpec* spec) {
    auto is_lf = [&](std::size_t i) {
        return code.kind(frames[i]) == FrameKind::character && code.character(frames[i]) == '\n';
    };
    std::size_t from = at, to = at + 1;
    while (from > 0 && !is_lf(from - 1)) --from;
    while (to < frames.size() && !is_lf(to)) ++to;
    std::size_t next = to + 1;
    while (next < frames.size() && !is_lf(next)) ++next;
    std::string block = decoded(code, frames, from, std::min(to, frames.size()), at, with);
    std::string context = to + 1 < frames.size() ? decoded(code, frames, to + 1, next, SIZE_MAX, 0) : "";
    auto first = block.find_first_not_of(" \t\r");
    bool own_start = first != std::string::npos && block[first] == '%';
    std::uint64_t first_line = own_start ? 1 : 2;
    std::uint64_t lines = 1 + static_cast<std::uint64_t>(std::count(block.begin(), block.end(), '\n'));
    LoadedTape t = load((own_start ? "" : "%\n") + block + "\n" + context + "\n", {}, LoadOptions{dialect});
    for (const auto& f : lint(t, LintOptions{spec})) {
        std::uint64_t line = f.where.line.value_or(0);
        if (f.severity == Severity::error && line >= first_line && line < first_line + lines) return false;
    }
    return true;
}

// A character a part program can hold: printable, or the ends of block and tab. Control characters
// are never taken for a repair (a reader or controller acts on some, and none belongs in a block).
bool program_character(const FrameCode& code, Frame f) {
    if (code.kind(f) != FrameKind::character) return false;
    char c = code.character(f);
    return (c >= 0x20 && c < 0x7F) || c == '\n' || c == '\r' || c == '\t';
}

struct Tally {
    Frame value;
    int count;
    bool good;
};

}  // namespace

std::string_view status_name(FrameStatus s) {
    static constexpr std::array<std::string_view, frame_status_count> names = {
        "clean", "voted", "inferred", "contested", "unstable", "unresolved", "missing", "extra"};
    return names[static_cast<std::size_t>(s)];
}

bool RestoreResult::complete() const {
    return count(FrameStatus::contested) + count(FrameStatus::unstable) + count(FrameStatus::unresolved) +
               count(FrameStatus::missing) ==
           0;
}

double frame_distance_cm(std::uint64_t frame) { return frame == 0 ? 0 : static_cast<double>(frame - 1) * 0.254; }

RestoreResult restore(std::span<const std::span<const Frame>> reads, const RestoreOptions& o) {
    ReadAlignment a = align_reads(reads, o.align);
    RestoreResult out;
    out.reference = a.reference();
    for (std::size_t r = 0; r < a.reads(); ++r) out.shared.push_back(a.shared(r));
    std::vector<std::size_t> unresolved;  // problems to try to repair once the whole image stands
    std::vector<Tally> tally;
    for (std::size_t c = 0; c < a.columns(); ++c) {
        tally.clear();
        std::size_t present = 0, covering = 0;
        for (std::size_t r = 0; r < a.reads(); ++r) {
            covering += a.covers(r, c);
            std::int32_t i = a.frame(c, r);
            if (i == ReadAlignment::none) continue;
            ++present;
            Frame f = reads[r][static_cast<std::size_t>(i)];
            auto t = std::find_if(tally.begin(), tally.end(), [&](const Tally& x) { return x.value == f; });
            if (t == tally.end())
                tally.push_back({f, 1, good(o.code, f)});
            else
                ++t->count;
        }
        std::size_t lost = covering - present;  // reads that cover this place but have no frame here
        // Whether a frame stands here at all is weighed by the good readings: a frame failing parity
        // may be a misread of this frame or garbage a stain put between two (the reads' alignment
        // cannot tell inside a burst), so it counts for neither side.
        std::size_t present_good = 0, good_values = 0;
        for (const auto& t : tally) {
            present_good += t.good ? static_cast<std::size_t>(t.count) : 0;
            good_values += t.good;
        }
        std::sort(tally.begin(), tally.end(),
                  [](const Tally& x, const Tally& y) { return x.good != y.good ? x.good : x.count > y.count; });
        Frame reference_value = 0;
        bool reference_here = a.frame(c, a.reference()) != ReadAlignment::none;
        if (reference_here) reference_value = reads[a.reference()][static_cast<std::size_t>(a.frame(c, a.reference()))];
        auto problem = [&](FrameStatus s, Frame written, std::string reason, bool dropped) {
            RestoreProblem p;
            p.status = s;
            p.column = c;
            p.written = written;
            p.reason = std::move(reason);
            for (std::size_t r = 0; r < a.reads(); ++r) {
                std::int32_t i = a.frame(c, r);
                p.seen.push_back(i == ReadAlignment::none ? std::nullopt
                                                          : std::optional(reads[r][static_cast<std::size_t>(i)]));
                p.covered.push_back(a.covers(r, c));
            }
            if (!dropped) p.frame = out.frames.size() + 1;
            p.after = out.frames.size();
            out.problems.push_back(std::move(p));
        };
        FrameStatus s;
        Frame written = tally.front().value;
        std::string reason;
        // Blank tape past the end of most reads: leader or trailer that one read has longer (a frame
        // read twice there has nothing to align by). The length most reads have is kept.
        bool lone_blank_end = tally.size() == 1 && tally.front().value == blank_frame && covering < a.reads() &&
                              present * 2 <= a.reads() && a.reads() > 1;
        if (lone_blank_end) lost = a.reads() - present;
        if (tally.front().good) present = present_good;
        if (present < lost && (present <= 1 || good_values > 1 || !tally.front().good || lone_blank_end)) {
            s = FrameStatus::extra;
            reason = std::to_string(present) + " of " + std::to_string(covering) +
                     " reads have this frame: read twice or a splice, not written";
        } else if (present < lost) {
            // Two reads or more agree on a frame the others lack: read twice by both, or lost by the
            // others, which is as likely. Written, and said.
            s = FrameStatus::contested;
            reason = std::to_string(present) + " of " + std::to_string(covering) +
                     " reads agree on this frame and the others have none: lost by them, or read twice; not "
                     "written, as most reads have none";
        } else if (!tally.front().good) {
            s = FrameStatus::unresolved;  // repaired below if exactly one change fits
            written = reference_here ? reference_value : written;
            reason = "no read has a good frame here";
        } else if (tally.size() == 1 && lost == 0) {
            s = FrameStatus::clean;
        } else if (present == lost) {
            s = FrameStatus::contested;
            reason = "half the reads that cover this place have a frame here, half do not";
        } else if (tally.size() == 1 || !tally[1].good || tally[0].count > tally[1].count) {
            s = FrameStatus::voted;
            reason = tally.size() > 1 && !tally[1].good && tally[0].count <= tally[1].count
                         ? "the only good reading (the others fail parity)"
                         : std::to_string(tally[0].count) + " of " + std::to_string(covering) + " reads agree";
        } else {
            bool all_differ = present >= 3 && tally.size() == present;
            s = all_differ ? FrameStatus::unstable : FrameStatus::contested;
            if (reference_here && good(o.code, reference_value)) written = reference_value;
            reason = all_differ ? "every read saw something else"
                                : "good readings disagree and nothing decides; the reference read's is written";
        }
        bool dropped = s == FrameStatus::extra || (s == FrameStatus::contested && present < lost);
        ++out.counts[static_cast<std::size_t>(s)];
        if (s != FrameStatus::clean) {
            if (s == FrameStatus::unresolved) unresolved.push_back(out.problems.size());
            problem(s, written, std::move(reason), dropped);
        }
        if (!dropped) out.frames.push_back(written);
    }
    // What no read has right: the single-hole changes of what the reads saw that make a character of
    // the code and fit the block. Exactly one: inferred. Otherwise it stays as read.
    if (o.code) {
        Dialect dialect = o.dialect;
        if (dialect == Dialect::automatic)
            dialect = guess_dialect(decoded(*o.code, out.frames, 0, out.frames.size(), SIZE_MAX, 0)).dialect;
        for (std::size_t index : unresolved) {
            RestoreProblem& p = out.problems[index];
            std::vector<Frame> shared_candidates, any;
            bool first = true;
            for (const auto& seen : p.seen) {
                if (!seen) continue;
                std::vector<Frame> mine;
                for (int bit = 0; bit < 8; ++bit) {
                    Frame c = static_cast<Frame>(*seen ^ (1U << bit));
                    if (program_character(*o.code, c)) mine.push_back(c);
                }
                for (Frame c : mine)
                    if (std::find(any.begin(), any.end(), c) == any.end()) any.push_back(c);
                if (first)
                    shared_candidates = mine;
                else
                    std::erase_if(shared_candidates,
                                  [&](Frame c) { return std::find(mine.begin(), mine.end(), c) == mine.end(); });
                first = false;
            }
            std::size_t at = static_cast<std::size_t>(*p.frame - 1);
            for (Frame c : shared_candidates.empty() ? any : shared_candidates)
                if (fits_block(*o.code, out.frames, at, c, dialect, o.spec)) p.candidates.push_back(c);
            if (p.candidates.size() == 1) {
                p.status = FrameStatus::inferred;
                p.written = out.frames[at] = p.candidates.front();
                p.reason = "the one single-hole change that makes a character fitting its block";
                --out.counts[static_cast<std::size_t>(FrameStatus::unresolved)];
                ++out.counts[static_cast<std::size_t>(FrameStatus::inferred)];
            } else {
                p.reason = p.candidates.empty() ? "no single-hole change makes a character that fits its block"
                                                : std::to_string(p.candidates.size()) +
                                                      " single-hole changes fit its block: not guessed";
            }
        }
        // Lines of the restored text, for the report.
        std::uint64_t line = 1;
        std::size_t next = 0;
        for (std::size_t i = 0; i < out.frames.size() && next < out.problems.size(); ++i) {
            while (next < out.problems.size() && (!out.problems[next].frame || *out.problems[next].frame == i + 1)) {
                if (out.problems[next].frame) out.problems[next].line = line;
                ++next;
            }
            Frame f = out.frames[i];
            if (o.code->kind(f) == FrameKind::character && o.code->character(f) == '\n') ++line;
        }
    }
    // The ends: a tape is punched with blank leader and trailer; where no read has one, its end may
    // be missing (every read started late, or stopped early).
    auto add_missing = [&](bool start) {
        RestoreProblem p;
        p.status = FrameStatus::missing;
        p.frame = start ? 1 : out.frames.size();
        p.column = start ? 0 : a.columns() - 1;
        p.reason = start ? "no read starts with leader: the start of the tape may be missing; read it again "
                           "from before its first punched frame"
                         : "no read ends with trailer: the end of the tape may be missing; read it again to "
                           "past its last punched frame";
        ++out.counts[static_cast<std::size_t>(FrameStatus::missing)];
        if (start)
            out.problems.insert(out.problems.begin(), std::move(p));
        else
            out.problems.push_back(std::move(p));
    };
    // Leader is blank tape, or (DEC binary tapes) a run of one frame, such as track 8 alone.
    auto leader_like = [&](bool start) {
        constexpr std::size_t run = 10;
        if (out.frames.empty()) return true;
        Frame end = start ? out.frames.front() : out.frames.back();
        if (end == blank_frame) return true;
        if (out.frames.size() < run) return false;
        for (std::size_t i = 0; i < run; ++i)
            if ((start ? out.frames[i] : out.frames[out.frames.size() - 1 - i]) != end) return false;
        return true;
    };
    if (!leader_like(true)) {
        out.missing_start = 1;
        add_missing(true);
    }
    if (!leader_like(false)) {
        out.missing_end = 1;
        add_missing(false);
    }
    return out;
}

}  // namespace tape
