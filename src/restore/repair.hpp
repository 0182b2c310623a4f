// Restoration's repair (restore.cpp): what the vote left open, decided by the program's own rules where
// exactly one way fits, and the report's line numbers.
#pragma once

#include <memory>

#include "tape/restore.hpp"
#include "vote.hpp"

namespace tape::detail {

struct RepairWorld;

/// The unresolved problems of out (tape order): the single-hole changes of what the reads saw that
/// fit the code and the block (its grammar, the tape's word formats, block numbers, codes, values and
/// arcs; a format spec when given), the damaged frames of a block tried together. A frame that every
/// fitting choice gives one value is inferred, its reason naming the rules that ruled the others out;
/// with options.guess the likeliest of several is guessed; the others stay as read, the values that fit
/// listed. Good readings that disagree (contested, unstable) are held against the block too: the one
/// that alone fits is voted. A program no NC grammar fits (MACRO source, SIR text) gets none.
/// world: what decide_runs_by_rules learned of the image, if it did (made here otherwise).
void repair_unresolved(RestoreResult& out, const FrameCode& code, const RestoreOptions& options,
                       std::unique_ptr<RepairWorld> world);

/// The runs whose length the reads disagree on, held against the block they stand in: where one length
/// breaks the program's rules and the other does not, the rules decide. Returns what it learned of the
/// image (null when nothing was to be decided), kept true to the image the verdicts now make.
std::unique_ptr<RepairWorld> decide_runs_by_rules(const VoteContext& v, VoteResult& vote,
                                                  const RestoreOptions& options);

/// Sets each written problem's line in the restored text.
void number_lines(RestoreResult& out, const FrameCode& code);

/// True when most frames of the data fail the code: the reads are in another code (or parity).
bool code_does_not_fit(std::span<const Frame> frames, const FrameCode& code);

}  // namespace tape::detail
