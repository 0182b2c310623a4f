// Subprograms for the interpreter (tape/motion.hpp): where the programs, o-subs and numbered blocks of a
// text stand (by offset: a called body is loaded again from the text, never kept as blocks), and the
// state of the calls being followed.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tape/dialect.hpp"
#include "tape/motion.hpp"

namespace tape {

namespace motion {

/// Where a block starts in the text: a called body is loaded from here, its places counted on from it.
struct TextPlace {
    std::uint64_t offset = 0, line = 1, column = 1, ordinal = 1;
};

/// A body to run: from a block to end (a byte offset: the next program, the o-sub's endsub).
struct Body {
    TextPlace from{};
    std::uint64_t end = 0;
};

}  // namespace motion

class SubprogramIndex {
public:
    struct Program {
        std::optional<long long> number;  ///< O1000 → 1000; none for a program without one
        std::uint64_t start = 0;          ///< its first character ('%' or the O block)
        motion::Body body{};              ///< its blocks after the O block
        bool has_body = false;
    };
    struct Numbered {
        std::size_t program = 0;
        long long n = 0;
        motion::TextPlace at{};
        bool operator<(const Numbered& o) const { return program != o.program ? program < o.program : n < o.n; }
    };
    struct Sub {
        std::string label;  ///< "<name>" or "100", as the loader keeps it (lowercase)
        motion::Body body{};
    };

    SubprogramIndex(std::string_view text, std::span<const std::uint64_t> frame_of, Dialect dialect);

    const Program* program(long long number) const;
    /// The program whose text holds offset.
    std::size_t program_at(std::uint64_t offset) const;
    const Program& program_entry(std::size_t i) const { return programs_[i]; }
    /// The first block N<n> of program i.
    const motion::TextPlace* numbered(std::size_t program, long long n) const;
    const Sub* sub(std::string_view label) const;
    /// True when an M98 of another program than program i calls program number (a called program does
    /// not run on its own; one that only calls itself does).
    bool called(long long number, std::size_t i) const;

private:
    friend class SubprogramIndexer;
    std::vector<Program> programs_;
    std::vector<Numbered> numbered_;  // sorted
    std::vector<Sub> subs_;
    std::vector<std::pair<long long, std::size_t>> targets_;  // sorted: the program numbers M98 names, by whom
};

namespace motion {

/// A call met in a block, followed once the block has run.
struct PendingCall {
    enum class Kind : std::uint8_t { none, program, local, o_sub };
    Kind kind = Kind::none;
    long long number = 0;   ///< M98's P (as written), M97's N
    int p_digits = 0;       ///< the digits P is written with (Fanuc's P####LLLL form)
    long long repeats = 1;  ///< L (or the leading digits of an 8-digit P)
    bool repeats_given = false;
    std::string label;  ///< o-call: "<name>" or "100"; M98/M97: "M98 P1000" as written, for notes
};

/// The calls being followed.
struct CallState {
    struct Frame {
        std::uint64_t body = 0;         ///< the body's first offset: the same body twice is recursion
        std::uint64_t call_offset = 0;  ///< the calling block's offset
        std::string name;               ///< "O1000", "N15", "o<name>" for notes
        bool jumped = false;            ///< M99 P: the caller goes on at another block
    };
    std::vector<Frame> stack;  ///< innermost last
    PendingCall pending{};
    bool returned = false;    ///< M99, return or endsub met: the rest of the running body does not run
    bool ended = false;       ///< M02/M30 met: nothing runs until the next program
    bool standalone = false;  ///< this program is a called subprogram: in text order it does not run
    long long skip_to = -1;   ///< M99 P: the caller's blocks before N<skip_to> do not run
    std::size_t skip_depth = 0;
    std::uint64_t replayed = 0;  ///< blocks run from subprograms: bounded (max_replayed)
    static constexpr std::uint64_t max_replayed = 10'000'000;

    void reset() { *this = CallState{}; }
};

}  // namespace motion

}  // namespace tape
