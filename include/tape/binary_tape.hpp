// Binary loader tapes of minicomputers: the frames are no characters but words for a loader program.
//   PDP-8 RIM   leader of 0200 frames (eight at least are asked for, so that EIA's single ends of block
//               are no leader); pairs of words, each two 6-bit frames: an address (bit 7 of the
//               first frame's 7 bits, 0100, set) then the word stored there; trailer 0200. No checksum.
//   PDP-8 BIN   leader 0200; an origin word (0100 set), then data words stored one after another; a frame
//               0300-0370 sets the field (memory bank) for what follows; the last word before the 0200
//               trailer is the checksum: the sum of all frames before it (origins and data, not fields),
//               mod 4096. Everything between two rubouts (0377) is a comment the loader skips.
//   PDP-11 absolute loader  blocks between blank frames: 001 000, a byte count (header included) and a
//               load address, low byte first, the data bytes, and a checksum byte that makes the sum of
//               the block's bytes 0 mod 256. A block of count 6 ends the tape; its address is the start
//               address, an odd one meaning "halt after loading".
// The checksums are what restoration repairs binary tapes by: every stretch a checksum covers is a
// ChecksumSpan, and checksum_holds() tells whether frames (as read, or as repaired) pass it.
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tape/frame.hpp"

namespace tape {

enum class BinaryFormat {
    pdp8_rim,        ///< PDP-8 Read-In Mode loader: address, word pairs
    pdp8_bin,        ///< PDP-8 binary loader: origin, words, checksum
    pdp11_absolute,  ///< PDP-11 absolute loader: blocks with a byte checksum each
};
/// "PDP-8 RIM", "PDP-8 BIN", "PDP-11 absolute loader".
std::string_view binary_format_name(BinaryFormat f);
/// "pdp8-rim", "pdp8-bin", "pdp11-absolute": for JSON and scripts.
std::string_view binary_format_id(BinaryFormat f);

/// A checksum of a binary tape: which frames it covers and whether it holds.
struct ChecksumSpan {
    enum class State {
        holds,    ///< the stored checksum is the one the frames give
        fails,    ///< it is not: a frame in the span (or the checksum itself) is wrong
        missing,  ///< the tape ends before the checksum: nothing to check
    };
    State state = State::missing;
    std::uint64_t first = 0;     ///< 0-based index of the first frame covered
    std::uint64_t frames = 0;    ///< frames covered, the checksum's own included
    std::uint32_t stored = 0;    ///< as punched
    std::uint32_t computed = 0;  ///< from the frames
};
std::string_view checksum_state_name(ChecksumSpan::State s);

/// PDP-11 absolute loader: the checksum byte for a block's bytes from the 001 to the last data byte.
std::uint8_t pdp11_checksum(std::span<const Frame> block);
/// PDP-8 BIN: the checksum of a section's frames between leader and the checksum word (comments between
/// rubouts and field settings are skipped, as the loader does): their sum mod 4096.
std::uint16_t pdp8_bin_checksum(std::span<const Frame> frames);
/// True when frames, exactly one checksummed stretch of format as on tape (a PDP-11 block from 001 to its
/// checksum byte; a PDP-8 BIN section from the frame after the leader to the last frame of the checksum
/// word), pass their checksum. For restoration: try a candidate frame, ask again. RIM has no checksum:
/// false.
bool checksum_holds(BinaryFormat format, std::span<const Frame> frames);

/// One unit of a binary tape: a PDP-11 block, a PDP-8 section between leader and trailer.
struct BinaryBlock {
    BinaryFormat format = BinaryFormat::pdp11_absolute;
    std::uint64_t first = 0;                 ///< 0-based index of its first frame
    std::uint64_t frames = 0;                ///< frames it takes (checksum included)
    std::uint32_t origin = 0;                ///< where its first word loads (PDP-8: field * 4096 + address)
    std::uint32_t origins = 0;               ///< PDP-8: origin settings in it (RIM: one a word)
    std::uint64_t words = 0;                 ///< words (PDP-8) or bytes (PDP-11) it loads
    bool end = false;                        ///< PDP-11: the end block (count 6)
    std::optional<ChecksumSpan> checksum{};  ///< none for RIM
    bool cut = false;                        ///< the tape ends inside it (no trailer, or a short block)
};

/// What a loader would put in memory: 12-bit words for the PDP-8 (8 fields of 4096), bytes for the PDP-11
/// (64 KiB). Bounded: the whole address space, and a bit a location for what was loaded.
class MemoryImage {
public:
    explicit MemoryImage(BinaryFormat format);
    /// Stores value at address (wrapped into the address space).
    void store(std::uint32_t address, std::uint16_t value);
    bool loaded(std::uint32_t address) const { return address < size_ && loaded_[address]; }
    std::uint16_t at(std::uint32_t address) const { return address < size_ ? cells_[address] : 0; }
    /// Locations of the address space: 32768 words or 65536 bytes.
    std::uint32_t size() const { return size_; }
    /// The lowest and highest loaded address; nullopt when nothing was loaded.
    std::optional<std::pair<std::uint32_t, std::uint32_t>> extent() const;
    std::uint64_t count() const { return loaded_.count(); }
    bool words() const { return words_; }

private:
    std::uint32_t size_;
    bool words_;
    std::vector<std::uint16_t> cells_;
    std::bitset<65536> loaded_;
};

/// What a binary tape holds, read a format family at a time (the PDP-8's RIM and BIN, or the PDP-11's).
struct BinaryTape {
    std::optional<BinaryFormat> format;  ///< the format of most blocks; nullopt when none was read
    std::vector<BinaryBlock> blocks;     ///< in tape order, at most max_listed_blocks
    std::uint64_t block_count = 0;       ///< all of them
    std::uint64_t checksums_held = 0, checksums_failed = 0, checksums_missing = 0;
    std::optional<std::uint32_t> start;  ///< PDP-11: the end block's start address (odd: none, halt)
    bool ended = false;                  ///< PDP-11: an end block was read
    std::uint64_t stray_frames = 0;      ///< punched frames no block explains (between blocks, after the end)
    std::uint64_t first_stray = 0;       ///< 0-based index of the first of them
    std::uint64_t punched = 0;           ///< punched frames looked at
    bool mixed = false;                  ///< PDP-8: both RIM and BIN sections

    /// True when the tape is in this format beyond doubt: blocks explain four fifths of the punched frames,
    /// and for the PDP-11 a third of the checksums at least hold; a PDP-8 tape is known by its sections
    /// (leader, origin, 6-bit frames, trailer) even when its checksums fail, so that damage is named.
    bool recognised() const;
    /// "PDP-11 absolute loader: 20 blocks, every checksum holds, start address 000001 (halt)".
    std::string summary() const;
};
inline constexpr std::size_t max_listed_blocks = 4096;

/// Reads a tape as one family of binary formats a chunk at a time, in bounded memory; the result is the
/// same however the tape is cut. With an image, the memory a loader would fill is kept too.
class BinaryReader {
public:
    enum class Family { pdp8, pdp11 };
    explicit BinaryReader(Family family, bool keep_image = false);
    ~BinaryReader();
    BinaryReader(BinaryReader&&) noexcept;
    BinaryReader& operator=(BinaryReader&&) noexcept;

    void feed(std::span<const Frame> frames);
    /// The tape has ended. Call once, then read the results.
    void finish();
    const BinaryTape& tape() const;
    /// The memory image (keep_image only; empty otherwise).
    const MemoryImage& image() const;

    class Parser;  // one per family: binary_pdp8.cpp, binary_pdp11.cpp

private:
    std::unique_ptr<Parser> parser_;
};

/// Both families tried over the same frames, and the one that explains the tape. A family that explains
/// too little of the first frames is given up, so that a tape of text costs next to nothing.
class BinaryDetector {
public:
    explicit BinaryDetector(bool keep_image = false);
    void feed(std::span<const Frame> frames);
    /// The tape has ended: what a family holds back (a section without its trailer) is counted. Once; frames
    /// fed after it are not looked at.
    void finish();
    /// The tape in the format recognised, or nullptr when neither family explains it (yet).
    const BinaryTape* tape() const;
    /// The memory image of the format recognised (keep_image only).
    const MemoryImage* image() const;

private:
    std::array<BinaryReader, 2> readers_;
    std::array<bool, 2> given_up_{};
    std::uint64_t fed_ = 0;  // frames fed so far
    bool finished_ = false;
};

/// The memory image as a file: the PDP-11's bytes from address 0 to the highest loaded, the PDP-8's words as
/// two bytes each (low byte first, 12 bits used) from field 0 address 0 to the highest loaded; locations
/// never loaded are 0. So a byte's offset in the file is its address (PDP-8: twice the word's).
std::string memory_image_bytes(const MemoryImage& image);
/// The memory image as octal lines: "00200: 7300 1276 3274 ..." (PDP-8, 5-digit field and address) or
/// "001000: 012706 001000 ..." (PDP-11, 16-bit words), eight to a line, only where something was loaded.
std::string memory_image_octal(const MemoryImage& image);
/// value in octal with leading zeros to digits places, as DEC wrote addresses and words: octal_text(0200, 5)
/// is "00200".
std::string octal_text(std::uint32_t value, int digits);

}  // namespace tape
