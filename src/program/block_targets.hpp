// The blocks a Fanuc or Haas program names by number: GOTO n (Custom Macro B), the P and Q of the lathe
// cycles G70-G73 (the first and last block of the profile they cut), and Haas's M97 P (a local
// subprogram: a block of the same program). Checked at the program's end: a target no block has, and
// a target whose number stands on more than one block. M98 P names a program and M99 P a block of the
// caller: neither is in the program, so neither is checked.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "tape/program.hpp"

namespace tape::lint_detail {

class BlockTargets {
public:
    /// The block's number, and the targets it names.
    void block(const Block& b);
    /// The program has ended: its targets' findings, then everything forgotten.
    void close(const std::function<void(Finding)>& out);

private:
    struct Numbered {  // a block number: how often it stands, and where its first few stand
        std::uint64_t count = 0;
        std::vector<Location> where;
        std::uint64_t second_block = 0;  // the block it stands on the second time
    };
    struct Target {
        std::string_view rule;  // goto-target or block-target, when no block has it
        std::string named_by;   // "GOTO 10", "G71 Q58", "M97 P15"
        long long number;
        Location where;
        std::uint64_t block;
    };
    void cycle_targets(const Block& b);
    void missing(const Target& t, const std::function<void(Finding)>& out) const;
    void repeated(const Target& t, const Numbered& n, const std::function<void(Finding)>& out) const;

    struct NumberAt {  // a numbered block: its number, its ordinal, where the number stands
        long long number;
        std::uint64_t block;
        Location where;
    };
    // A record for every numbered block of a long program: a deque grows without copying, so each
    // record's memory is touched once (a vector's doublings cost a quarter of linting 200 000 blocks).
    std::deque<NumberAt> numbered_;
    std::vector<Target> targets_;
};

}  // namespace tape::lint_detail
