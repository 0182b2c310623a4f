// The parsers behind BinaryReader, one per family of binary loader formats (binary_pdp8.cpp,
// binary_pdp11.cpp): each takes frames one at a time and fills a BinaryTape and a MemoryImage.
#pragma once

#include <memory>

#include "tape/binary_tape.hpp"

namespace tape {

class BinaryReader::Parser {
public:
    Parser(BinaryFormat image_format, bool keep_image) : image_(image_format), keep_image_(keep_image) {}
    virtual ~Parser() = default;
    virtual void feed(std::span<const Frame> frames) = 0;
    virtual void finish() = 0;

    const BinaryTape& tape() const { return tape_; }
    const MemoryImage& image() const { return image_; }

protected:
    /// Counts a block, listing it while the list is short.
    void add_block(const BinaryBlock& b);
    /// Counts punched frames no block explains, from 0-based index first.
    void add_stray(std::uint64_t count, std::uint64_t first);
    void store(std::uint32_t address, std::uint16_t value) {
        if (keep_image_) image_.store(address, value);
    }

    BinaryTape tape_;
    MemoryImage image_;
    bool keep_image_;
    std::uint64_t rim_sections_ = 0, bin_sections_ = 0;
};

std::unique_ptr<BinaryReader::Parser> make_pdp8_parser(bool keep_image);
std::unique_ptr<BinaryReader::Parser> make_pdp11_parser(bool keep_image);

}  // namespace tape
