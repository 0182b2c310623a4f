// Telling codes and parity conventions apart from the frames themselves.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "tape/code.hpp"
#include "tape/error.hpp"
#include "tape/frame.hpp"

namespace tape {

struct CodeDetection {
    std::optional<Code> code;  ///< nullopt when the tape fits neither ISO nor EIA
    std::string reason;        ///< why, in words a machinist understands
    Hint hint{};               ///< when neither fits: the reading that might (ISO with another parity)
};

/// Decides ISO or EIA from the frames before the first end of block (ISO LF 0x0A, EIA EOB 0x80),
/// as controllers do: the parity of those frames, which end of block and program start appear.
CodeDetection detect_code(std::span<const Frame> frames);

/// How many punched frames fit each parity convention.
struct ParityCounts {
    std::uint64_t frames = 0;  ///< punched frames (blank tape not counted)
    std::uint64_t even = 0;    ///< an even number of holes
    std::uint64_t odd = 0;
    std::uint64_t mark = 0;   ///< track 8 punched
    std::uint64_t space = 0;  ///< track 8 not punched

    /// The convention most frames fit (even, odd, mark, space in that order on a tie), or
    /// nullopt when there are no punched frames or fewer than 90% of them fit any one ("mixed").
    std::optional<Parity> dominant() const;
    /// Frames that do not fit p.
    std::uint64_t misfits(Parity p) const;
};

ParityCounts count_parity(std::span<const Frame> frames);

}  // namespace tape
