// The tapes restore_bench restores: generated programs, the bundled sample tapes, and real programs and
// tapes from ../shared/data/outside* (Fanuc, LinuxCNC, Haas and other programs encoded in ISO; DEC source
// tapes as they are), skipped with a note where that folder is absent.
#pragma once

#include <string>
#include <vector>

#include "tape/dialect.hpp"
#include "tape/frame.hpp"

namespace bench {

struct CorpusTape {
    std::string name;
    std::vector<tape::Frame> frames;
    /// Per frame: a frame of the program's code (not leader, trailer, or a comment's text).
    std::vector<bool> code;
    bool nc = true;  ///< an NC program (not MACRO or SIR source)
};

/// Blocks as real programs have them, numbers varying with a seed; with_errors: some blocks carry
/// mistakes of the program's own (arcs without a centre, a word the dialect does not know).
CorpusTape generated_tape(std::size_t chars, std::uint64_t seed, bool with_errors = false);

/// The ISO sample tapes in tapes/.
std::vector<CorpusTape> sample_tapes();

/// Real programs of ../shared/data/outside* encoded in ISO, and the DEC source tapes there; note says
/// what was left out and why.
std::vector<CorpusTape> real_tapes(std::string& note);

}  // namespace bench
