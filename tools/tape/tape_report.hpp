// What info and decode say about a tape beyond its characters: leader labels and titles, binary loader
// formats with their blocks and checksums.
#pragma once

#include <optional>
#include <string>

#include "cli/json.hpp"
#include "tape/binary_tape.hpp"
#include "tape/label.hpp"

namespace cli {

/// "DETAIL 17 (frames 11-65, ISO letters)"; for a title in another font, which is not read: "a title
/// punched as letters of holes, not read (frames 181-372): `tape show` draws it".
std::string leader_label_words(const tape::LeaderLabel& label);
/// {"text", "first_frame", "frames", "code", "kind"} or null.
Json leader_label_info(const std::optional<tape::LeaderLabel>& label);

/// One line a block: "block 3: frames 120-172, load 000704, 46 bytes, checksum holds (stored 123)".
std::string binary_block_line(const tape::BinaryBlock& b);
/// The blocks worth a line: all when every is true or there are few, else those whose checksum does not hold.
std::string binary_block_lines(const tape::BinaryTape& t, bool every, const std::string& indent);
/// {"format", "name", "summary", "blocks": [...], "checksums": {...}, "start", "stray_frames"}.
Json binary_info(const tape::BinaryTape& t);

/// What tape info says of the image at path, its file named shown: code, parity, kind of tape, leader
/// label, loader format and blocks, frame counts. A file that cannot be read ends the program.
std::string tape_info_text(const std::string& path, const std::string& shown);

}  // namespace cli
