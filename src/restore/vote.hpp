// Restoration's vote (restore.cpp): what it knows of the reads besides the alignment, and its verdict
// on each column.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tape/restore.hpp"

namespace tape::detail {

using Reads = std::span<const std::span<const Frame>>;

/// A read's chances per frame to lose a frame and to read one twice, as the reads show them.
struct SlipRates {
    double drop = 0, twice = 0;
};

/// What the vote knows besides the alignment, made once by make_vote_context.
struct VoteContext {
    const ReadAlignment& a;
    Reads reads;
    std::optional<FrameCode> code;
    /// Per column and read: the read garbled this stretch (a stain or splice read as other frames), so
    /// it is not heard there.
    std::vector<std::uint8_t> garbled;
    /// Per column: more than one read slipped in the stretch of disagreement it stands in.
    std::vector<bool> tangled;
    /// Per column and read: the read doubts its frame there (empty: no read doubts anything).
    std::vector<std::uint8_t> doubted;
    /// The columns of data: from the first to one past the last column most reads punched.
    std::size_t data_from = 0, data_to = 0;
    std::vector<SlipRates> rates;
    /// Per column: the one read that has a frame there, or ReadAlignment::none.
    std::vector<std::int32_t> alone;

    bool heard(std::size_t c, std::size_t r) const { return !garbled[c * a.reads() + r]; }
    bool doubts(std::size_t c, std::size_t r) const { return !doubted.empty() && doubted[c * a.reads() + r]; }
    bool in_data(std::size_t c) const { return c >= data_from && c < data_to; }
    /// A frame that holds the code's parity and is one of its characters (any frame with no code).
    bool good(Frame f) const { return !code || !is_bad_frame(code->kind(f)); }
};

VoteContext make_vote_context(const ReadAlignment& a, Reads reads, const RestoreOptions& o);

/// True when the frame a read has at index i is also its neighbour in that read: a frame read twice
/// looks so, and so does a frame punched twice.
inline bool repeated(std::span<const Frame> read, std::size_t i) {
    return (i > 0 && read[i - 1] == read[i]) || (i + 1 < read.size() && read[i + 1] == read[i]);
}

/// garbled and tangled of VoteContext.
std::vector<std::uint8_t> garbled_stretches(const ReadAlignment& a, Reads reads, const std::optional<FrameCode>& code);
std::vector<bool> slips_in_several_reads(const ReadAlignment& a, Reads reads);

/// The vote's verdict on one column.
struct Verdict {
    Frame written = blank_frame;
    FrameStatus status = FrameStatus::clean;
    bool write = true;  ///< false: left out (extra, or contested and most reads lack it)
    /// Whether a frame stands here at all is contested: some reads have one, others none, and neither
    /// side decides (the program's rules may: decide_runs_by_rules).
    bool presence = false;
    std::int32_t problem = -1;  ///< its entry in the problems, or -1 when clean
};

/// A run of equal frames whose length the reads disagree on, and the length decided.
struct RunDecision {
    std::size_t first = 0, end = 0;  ///< its columns
    Frame value = blank_frame;
    std::size_t length = 0;       ///< copies written
    std::size_t alternative = 0;  ///< the next likeliest length
    double odds = 0;              ///< how much likelier length is than alternative
    std::size_t readers = 0;      ///< reads that cover the whole run and were heard on it
    bool blank_end = false;       ///< leader or trailer: its length is nobody's concern, never in doubt
    std::string how;              ///< the counts: "2 of 3 reads have 3 copies, 1 has 2"
    std::string rule;             ///< the program's rule the other length breaks, when rules decided it
    /// The tape's habit the written length breaks, held by too few words to overturn the reads: in doubt.
    std::string doubt;

    /// Decided without a doubt: by the rules, or by odds of at least `odds_to_decide`, and no habit
    /// of the tape's against it.
    bool decided(double odds_to_decide) const { return doubt.empty() && (!rule.empty() || odds >= odds_to_decide); }
};

/// The runs of the alignment whose length the reads disagree on, each decided: leader and trailer
/// follow the majority (the median), other runs go by likelihood.
std::vector<RunDecision> decide_runs(const VoteContext& v);

/// The probability that a read with the given slip rates reads `seen` copies of a frame punched
/// `punched` times (each copy lost, read twice, or read once).
double copies_likelihood(std::size_t seen, std::size_t punched, const SlipRates& rates);

/// The whole vote: a verdict for every column, the problems (with column, seen, covered, written,
/// reason, status; frame and after are set when the image is made), counts and run decisions.
struct VoteResult {
    std::vector<Verdict> verdicts;
    std::vector<RestoreProblem> problems;
    std::vector<RunDecision> runs;
};
VoteResult vote(const VoteContext& v, const RestoreOptions& o);

/// Votes again the columns of run `run` of out.runs, after its decision changed.
void revote_run(const VoteContext& v, const RestoreOptions& o, VoteResult& out, std::size_t run);

/// The final check: a stretch of columns none of which is written, where most reads covering it hold
/// copies that agree, is written as one of them has it, contested (the alignment set it apart).
void keep_stretches_most_reads_hold(const VoteContext& v, VoteResult& out);

/// True when some read went past the tape's start (or end): it has a frame of at most one hole (blank
/// tape, or a leader of one track) before its first (after its last) punched frame that another read
/// backs.
bool read_past_end(const VoteContext& v, bool start);

}  // namespace tape::detail
