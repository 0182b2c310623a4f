// Searches a reader performs on a loaded tape: forward to a main block, back to the rewind stop,
// a program by number, a block by number. Positions are text offsets; frame_offset() converts.
#pragma once

#include <cstdint>
#include <optional>
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

}  // namespace tape
