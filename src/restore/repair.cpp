// Repair of frames no read has right, checked against the grammar of the block they stand in.
#include "repair.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "tape/decode.hpp"
#include "tape/lint.hpp"

namespace tape::detail {
namespace {

struct Change {
    std::size_t at;
    Frame with;
};

Frame changed_frame(std::span<const Frame> frames, std::span<const Change> changes, std::size_t i) {
    for (const auto& c : changes)
        if (c.at == i) return c.with;
    return frames[i];
}

// The decoded text of frames [from, to) with the changes made, a bad frame as U+FFFD.
std::string decoded(const FrameCode& code, std::span<const Frame> frames, std::size_t from, std::size_t to,
                    std::span<const Change> changes = {}) {
    std::string s;
    for (std::size_t i = from; i < to; ++i) {
        Frame f = changed_frame(frames, changes, i);
        FrameKind k = code.kind(f);
        if (k == FrameKind::character)
            s += code.character(f);
        else if (is_bad_frame(k))
            s += bad_frame_marker;
    }
    return s;
}

bool is_end_of_block(const FrameCode& code, Frame f) {
    return code.kind(f) == FrameKind::character && code.character(f) == '\n';
}

// The first frame of the line (block) frame at stands in.
std::size_t line_start(const FrameCode& code, std::span<const Frame> frames, std::size_t at) {
    while (at > 0 && !is_end_of_block(code, frames[at - 1])) --at;
    return at;
}

// True when the block (the line) holding the changed frames, all in one line, reads with no error once
// they are changed. The next line is loaded too, as context (a '%' line needs the block after it), but
// only the block's own lines (more, when a change is an end of block) must be free of errors.
bool fits_block(const FrameCode& code, std::span<const Frame> frames, std::span<const Change> changes, Dialect dialect,
                const FormatSpec* spec) {
    std::size_t from = line_start(code, frames, changes.front().at), to = changes.front().at + 1;
    while (to < frames.size() && !is_end_of_block(code, frames[to])) ++to;
    std::size_t next = to + 1;
    while (next < frames.size() && !is_end_of_block(code, frames[next])) ++next;
    std::string block = decoded(code, frames, from, std::min(to, frames.size()), changes);
    std::string context = to + 1 < frames.size() ? decoded(code, frames, to + 1, next) : "";
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

// The single-hole changes of what the reads saw that are program characters: those all reads allow,
// or, where they allow none in common, those any allows.
std::vector<Frame> single_hole_changes(const FrameCode& code, const RestoreProblem& p) {
    std::vector<Frame> shared, any;
    bool first = true;
    for (const auto& seen : p.seen) {
        if (!seen) continue;
        std::vector<Frame> mine;
        for (int bit = 0; bit < 8; ++bit) {
            Frame c = static_cast<Frame>(*seen ^ (1U << bit));
            // Blank tape may stand anywhere (a reader passes over it), so a frame of one hole may be it.
            if (program_character(code, c) || c == blank_frame) mine.push_back(c);
        }
        for (Frame c : mine)
            if (std::find(any.begin(), any.end(), c) == any.end()) any.push_back(c);
        if (first)
            shared = mine;
        else
            std::erase_if(shared, [&](Frame c) { return std::find(mine.begin(), mine.end(), c) == mine.end(); });
        first = false;
    }
    return shared.empty() ? any : shared;
}

void mark_inferred(RestoreResult& out, RestoreProblem& p, Frame f, std::string reason) {
    p.status = FrameStatus::inferred;
    p.written = out.frames[static_cast<std::size_t>(*p.frame - 1)] = f;
    p.reason = std::move(reason);
    --out.counts[static_cast<std::size_t>(FrameStatus::unresolved)];
    ++out.counts[static_cast<std::size_t>(FrameStatus::inferred)];
}

// A frame with one hole (in a read that has it) in blank tape: the leader or trailer (no frame of more
// than one hole before it, or after it), or tape fed between blocks (blank on both sides, past other
// such frames). Blank tape is the grammar that fits there; no reader acts on it.
bool hole_in_blank_tape(const RestoreResult& out, const RestoreProblem& p, std::size_t first_punched,
                        std::size_t last_punched) {
    if (!std::all_of(p.seen.begin(), p.seen.end(),
                     [&](const std::optional<Frame>& f) { return !f || hole_count(*f) == 1; }))
        return false;
    std::size_t at = static_cast<std::size_t>(*p.frame - 1);
    // Leader or trailer, with a blank frame between it and the punched part (the frame next to it may
    // be the program's last end of block, misread).
    auto blank_between = [&](std::size_t from, std::size_t to) {
        return std::find(out.frames.begin() + static_cast<std::ptrdiff_t>(from),
                         out.frames.begin() + static_cast<std::ptrdiff_t>(to),
                         blank_frame) != out.frames.begin() + static_cast<std::ptrdiff_t>(to);
    };
    if (at < first_punched && blank_between(at + 1, first_punched)) return true;
    if (at > last_punched && last_punched < out.frames.size() && blank_between(last_punched + 1, at)) return true;
    std::size_t l = at, r = at + 1;
    while (l > 0 && hole_count(out.frames[l - 1]) == 1) --l;
    while (r < out.frames.size() && hole_count(out.frames[r]) == 1) ++r;
    return (l == 0 || out.frames[l - 1] == blank_frame) && (r == out.frames.size() || out.frames[r] == blank_frame);
}

// The damaged frames of one block, their candidates tried together: every choice that fits adds its
// values to each frame's list. More choices than this are tried one frame at a time.
constexpr std::size_t most_choices = 512;

void repair_block(RestoreResult& out, std::span<RestoreProblem* const> block, const FrameCode& code, Dialect dialect,
                  const FormatSpec* spec) {
    std::vector<std::vector<Frame>> options;
    std::size_t choices = 1;
    for (const RestoreProblem* p : block) {
        options.push_back(single_hole_changes(code, *p));
        choices = std::min(choices * std::max<std::size_t>(options.back().size(), 1), most_choices + 1);
    }
    std::vector<std::vector<Frame>> fitting(block.size());
    auto add = [](std::vector<Frame>& list, Frame f) {
        if (std::find(list.begin(), list.end(), f) == list.end()) list.push_back(f);
    };
    std::vector<Change> changes;
    if (choices <= most_choices) {
        // Frames with no candidate stay as read; the others take every combination of theirs.
        std::vector<std::size_t> pick(block.size(), 0);
        for (std::size_t n = 0; n < choices; ++n) {
            changes.clear();
            for (std::size_t k = 0; k < block.size(); ++k)
                if (!options[k].empty())
                    changes.push_back({static_cast<std::size_t>(*block[k]->frame - 1), options[k][pick[k]]});
            if (!changes.empty() && fits_block(code, out.frames, changes, dialect, spec))
                for (std::size_t k = 0, c = 0; k < block.size(); ++k)
                    if (!options[k].empty()) add(fitting[k], changes[c++].with);
            for (std::size_t k = 0; k < block.size(); ++k) {
                if (options[k].empty()) continue;
                if (++pick[k] < options[k].size()) break;
                pick[k] = 0;
            }
        }
    } else {
        for (std::size_t k = 0; k < block.size(); ++k)
            for (Frame f : options[k]) {
                Change c{static_cast<std::size_t>(*block[k]->frame - 1), f};
                if (fits_block(code, out.frames, std::span(&c, 1), dialect, spec)) add(fitting[k], f);
            }
    }
    for (std::size_t k = 0; k < block.size(); ++k) {
        RestoreProblem& p = *block[k];
        p.candidates = fitting[k];
        if (p.candidates.size() == 1) {
            mark_inferred(out, p, p.candidates.front(),
                          block.size() == 1 ? "the one single-hole change that makes a character fitting its block"
                                            : "the one single-hole change that makes a character fitting its block, "
                                              "with the other damaged frames of the block");
        } else {
            p.reason = p.candidates.empty()
                           ? "no single-hole change makes a character that fits its block"
                           : std::to_string(p.candidates.size()) + " single-hole changes fit its block: not guessed";
        }
    }
}

}  // namespace

void repair_unresolved(RestoreResult& out, std::span<const std::size_t> unresolved, const FrameCode& code,
                       Dialect dialect, const FormatSpec* spec) {
    if (dialect == Dialect::automatic) dialect = guess_dialect(decoded(code, out.frames, 0, out.frames.size())).dialect;
    // The first and last frame of more than one hole: what lies outside is leader and trailer.
    auto punched = [](Frame f) { return hole_count(f) > 1; };
    auto first = std::find_if(out.frames.begin(), out.frames.end(), punched);
    auto last = std::find_if(out.frames.rbegin(), out.frames.rend(), punched);
    const std::size_t first_punched = static_cast<std::size_t>(first - out.frames.begin());
    const std::size_t last_punched = out.frames.size() - 1 - static_cast<std::size_t>(last - out.frames.rbegin());
    std::vector<RestoreProblem*> block;
    std::size_t block_start = SIZE_MAX;
    auto flush = [&] {
        if (!block.empty()) repair_block(out, block, code, dialect, spec);
        block.clear();
    };
    for (std::size_t index : unresolved) {
        RestoreProblem& p = out.problems[index];
        if (hole_in_blank_tape(out, p, first_punched, last_punched)) {
            p.candidates = {blank_frame};
            mark_inferred(out, p, blank_frame, "a hole in blank tape (leader, trailer, or tape fed between blocks)");
            continue;
        }
        std::size_t start = line_start(code, out.frames, static_cast<std::size_t>(*p.frame - 1));
        if (start != block_start) flush();
        block_start = start;
        block.push_back(&p);
    }
    flush();
}

void number_lines(RestoreResult& out, const FrameCode& code) {
    std::uint64_t line = 1;
    std::size_t next = 0;
    for (std::size_t i = 0; i < out.frames.size() && next < out.problems.size(); ++i) {
        while (next < out.problems.size() && (!out.problems[next].frame || *out.problems[next].frame == i + 1)) {
            if (out.problems[next].frame) out.problems[next].line = line;
            ++next;
        }
        if (is_end_of_block(code, out.frames[i])) ++line;
    }
}

}  // namespace tape::detail
