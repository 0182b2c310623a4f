// One block's open frames decided together (repair.cpp): frames no read has right among the single-hole
// changes of what the reads saw, and good readings that disagree among those readings, each choice held
// against the block's rules (block_judge.hpp) with the others.
#pragma once

#include <string>
#include <vector>

#include "repair_world.hpp"
#include "tape/restore.hpp"

namespace tape::detail {

/// Gives problem p (written at its frame) a new status, frame and reason; the counts follow.
void set_status(RestoreResult& out, RestoreProblem& p, FrameStatus s, Frame f, std::string reason);

/// The open problems of one line, in tape order: unresolved ones, and contested or unstable ones whose
/// good readings disagree (their candidates). Where exactly one choice fits the block, an unresolved
/// frame is inferred and a disagreement voted by the rules, the reason naming the rules that ruled the
/// others out; with guess the likeliest of several is guessed; the others stay as they are.
void repair_block(const RepairWorld& w, RestoreResult& out, std::vector<RestoreProblem*> block, bool guess);

}  // namespace tape::detail
