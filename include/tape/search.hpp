// Searches a reader performs on a loaded tape: forward to a main block, back to the rewind stop,
// a program by number, a block by number. Positions are text offsets; frame_offset() converts.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tape/program.hpp"

namespace tape {

struct BlockRef {
    const Program* program = nullptr;
    const Block* block = nullptr;
};

/// The first text offset whose frame is at or after frame (from 1); text size when none.
/// For text input (no frames) frame is taken as a line number.
std::uint64_t frame_offset(const LoadedTape& tape, std::uint64_t frame);

/// Forward from offset: the next ':' main block (§2.6), or the next with that number.
std::optional<BlockRef> find_main_block(const LoadedTape& tape, std::uint64_t from,
                                        std::optional<long long> number = {});

/// Backward from offset: the last '%' program start before it, where a rewinding reader stops.
const Program* find_rewind_stop(const LoadedTape& tape, std::uint64_t from);

/// The program with that number after '%' ("41" finds %41 and %041).
const Program* find_program(const LoadedTape& tape, std::string_view number);

/// Every block whose N (or :) number has that value.
std::vector<BlockRef> find_numbered_blocks(const LoadedTape& tape, long long number);

/// Every main block, in tape order.
std::vector<BlockRef> main_blocks(const LoadedTape& tape);

/// One search, as a reader does it, fed by the loader as it streams: a tape of any length is searched
/// in bounded memory. from is a frame for tapes, a line for text programs (0 or 1: the start).
struct SearchQuery {
    enum class Kind { main_block, rewind_stop, program, numbered_block } kind = Kind::main_block;
    std::optional<long long> number{};  ///< main block (optional) or block number
    std::string program{};              ///< program number, for Kind::program
    std::uint64_t from = 1;
    bool from_tape = false;  ///< from counts frames (else lines)
};

struct SearchHit {
    Location where;
    std::string text;  ///< the block as written ("O1234 (BRACKET)" for a Fanuc program), or "%41" for a program start
};

class Searcher : public ProgramVisitor {
public:
    explicit Searcher(SearchQuery query) : query_(std::move(query)) {}
    void program_start(const Program& header) override;
    void block(const Block& block) override;
    void record_end(const Location& where, bool closes_program) override;
    /// The hits in tape order (the rewind stop: the one last before from).
    const std::vector<SearchHit>& hits() const { return hits_; }

private:
    bool at_or_after_from(const Location& where) const;

    SearchQuery query_;
    std::vector<SearchHit> hits_;
    std::optional<std::string> number_block_{};  // the program found: the number its O block holds
};

}  // namespace tape
