// Binary loader tapes: PDP-8 RIM and BIN, PDP-11 absolute loader; their checksums and memory images.
#include "tape/binary_tape.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "tape/detect.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {

// A PDP-11 absolute-loader block as DEC's tools punch it: 001 000, count, address, data, checksum.
std::vector<Frame> pdp11_block(std::uint16_t address, const std::vector<Frame>& data) {
    std::size_t count = data.size() + 6;
    std::vector<Frame> b;
    for (std::size_t v : {std::size_t{1}, std::size_t{0}, count & 0xFF, count >> 8, std::size_t{address} & 0xFF,
                          std::size_t{address} >> 8})
        b.push_back(static_cast<Frame>(v));
    for (Frame f : data) b.push_back(f);
    b.push_back(pdp11_checksum(b));
    return b;
}

std::vector<Frame> pdp11_tape() {
    std::vector<Frame> t(20, 0);
    for (auto part :
         {pdp11_block(01000, {0x12, 0x34, 0x56, 0x78}), pdp11_block(01004, {0xAA, 0xBB}), pdp11_block(01001, {})}) {
        t.insert(t.end(), part.begin(), part.end());
        t.insert(t.end(), 4, 0);
    }
    return t;
}

// PDP-8 words as the loaders take them: two 6-bit frames, 0100 on an origin's first frame.
void word(std::vector<Frame>& t, std::uint16_t w, bool origin = false) {
    t.push_back(static_cast<Frame>((w >> 6 & 077) | (origin ? 0100 : 0)));
    t.push_back(static_cast<Frame>(w & 077));
}

std::vector<Frame> pdp8_bin(std::uint16_t origin, const std::vector<std::uint16_t>& words) {
    std::vector<Frame> t(30, 0200);
    std::size_t start = t.size();
    word(t, origin, true);
    for (auto w : words) word(t, w);
    std::uint16_t sum = pdp8_bin_checksum(std::span(t).subspan(start));
    word(t, sum);
    t.insert(t.end(), 30, 0200);
    return t;
}

std::vector<Frame> pdp8_rim(const std::vector<std::pair<std::uint16_t, std::uint16_t>>& pairs) {
    std::vector<Frame> t(30, 0200);
    for (auto [a, w] : pairs) {
        word(t, a, true);
        word(t, w);
    }
    t.insert(t.end(), 30, 0200);
    return t;
}

BinaryTape read_as(BinaryReader::Family family, std::span<const Frame> t, std::size_t cut = 0) {
    BinaryReader r(family);
    for (std::size_t i = 0; i < t.size(); i += cut ? cut : t.size())
        r.feed(t.subspan(i, std::min(t.size() - i, cut ? cut : t.size())));
    r.finish();
    return r.tape();
}

}  // namespace

TEST(Pdp11Absolute, BlocksChecksumsAndTheStartAddress) {
    auto t = pdp11_tape();
    BinaryTape b = read_as(BinaryReader::Family::pdp11, t);
    ASSERT_EQ(b.format, BinaryFormat::pdp11_absolute);
    EXPECT_TRUE(b.recognised());
    ASSERT_EQ(b.block_count, 3U);
    EXPECT_EQ(b.checksums_held, 3U);
    EXPECT_EQ(b.blocks[0].first, 20U);
    EXPECT_EQ(b.blocks[0].frames, 11U);
    EXPECT_EQ(b.blocks[0].origin, 01000U);
    EXPECT_EQ(b.blocks[0].words, 4U);
    EXPECT_TRUE(b.blocks[2].end);
    ASSERT_TRUE(b.start);
    EXPECT_EQ(*b.start, 01001U);
    EXPECT_EQ(b.summary(),
              "PDP-11 absolute loader: 3 blocks, every checksum holds; start address 001001 (odd: the "
              "loader halts, no program started)");
    EXPECT_TRUE(checksum_holds(BinaryFormat::pdp11_absolute, std::span(t).subspan(20, 11)));
}

TEST(Pdp11Absolute, AFlippedHoleFailsItsBlocksChecksumOnly) {
    auto t = pdp11_tape();
    t[20 + 7] ^= 0x04;  // a data byte of the first block
    BinaryTape b = read_as(BinaryReader::Family::pdp11, t);
    EXPECT_EQ(b.checksums_held, 2U);
    EXPECT_EQ(b.checksums_failed, 1U);
    EXPECT_TRUE(b.recognised()) << "most checksums hold";
    ASSERT_TRUE(b.blocks[0].checksum);
    EXPECT_EQ(b.blocks[0].checksum->state, ChecksumSpan::State::fails);
    EXPECT_EQ(b.blocks[0].checksum->first, 20U);
    EXPECT_EQ(b.blocks[0].checksum->frames, 11U);
    EXPECT_FALSE(checksum_holds(BinaryFormat::pdp11_absolute, std::span(t).subspan(20, 11)));
    t[20 + 7] ^= 0x04;  // repaired: the checksum holds again
    EXPECT_TRUE(checksum_holds(BinaryFormat::pdp11_absolute, std::span(t).subspan(20, 11)));
}

TEST(Pdp11Absolute, ATapeCutInsideABlockSaysSo) {
    auto t = pdp11_tape();
    t.resize(20 + 8);
    BinaryTape b = read_as(BinaryReader::Family::pdp11, t);
    ASSERT_EQ(b.block_count, 1U);
    EXPECT_TRUE(b.blocks[0].cut);
    EXPECT_EQ(b.blocks[0].checksum->state, ChecksumSpan::State::missing);
    EXPECT_FALSE(b.ended);
    EXPECT_FALSE(b.recognised()) << "no checksum to go by";
}

TEST(Pdp11Absolute, TheMemoryImageIsTheLoadersAndTheSameHoweverCut) {
    auto t = pdp11_tape();
    BinaryReader whole(BinaryReader::Family::pdp11, true);
    whole.feed(t);
    whole.finish();
    const MemoryImage& m = whole.image();
    EXPECT_EQ(m.count(), 6U);
    ASSERT_TRUE(m.extent());
    EXPECT_EQ(m.extent()->first, 01000U);
    EXPECT_EQ(m.extent()->second, 01005U);
    std::string bytes = memory_image_bytes(m);
    ASSERT_EQ(bytes.size(), 01006U);
    EXPECT_EQ(bytes.substr(01000), "\x12\x34\x56\x78\xAA\xBB");
    EXPECT_EQ(memory_image_octal(m), "001000: 032022 074126 135652\n");
    for (std::size_t cut : {1, 3, 7})
        EXPECT_EQ(read_as(BinaryReader::Family::pdp11, t, cut).summary(),
                  read_as(BinaryReader::Family::pdp11, t).summary());
}

TEST(Pdp8Bin, OriginWordsAndTheChecksum) {
    auto t = pdp8_bin(0200, {07300, 01276, 03274});
    BinaryTape b = read_as(BinaryReader::Family::pdp8, t);
    ASSERT_EQ(b.format, BinaryFormat::pdp8_bin);
    EXPECT_TRUE(b.recognised());
    ASSERT_EQ(b.block_count, 1U);
    EXPECT_EQ(b.blocks[0].origin, 0200U);
    EXPECT_EQ(b.blocks[0].words, 3U);
    EXPECT_EQ(b.blocks[0].first, 30U);
    EXPECT_EQ(b.blocks[0].frames, 10U);
    EXPECT_EQ(b.blocks[0].checksum->state, ChecksumSpan::State::holds);
    EXPECT_TRUE(checksum_holds(BinaryFormat::pdp8_bin, std::span(t).subspan(30, 10)));
    BinaryReader r(BinaryReader::Family::pdp8, true);
    r.feed(t);
    r.finish();
    EXPECT_EQ(memory_image_octal(r.image()), "00200: 7300 1276 3274\n");
    t[33] ^= 010;  // a hole lost in a data word
    EXPECT_EQ(read_as(BinaryReader::Family::pdp8, t).blocks[0].checksum->state, ChecksumSpan::State::fails);
}

TEST(Pdp8Bin, AChecksumWordPunchedWithTheOriginBitAddsIt) {
    // The loader forms words by adding (TAD): a low frame with 0100 adds 0100, as FOCAL-8's tape has it.
    std::vector<Frame> t(10, 0200);
    word(t, 0, true);
    word(t, 01000);                                                   // frames 010 000
    std::uint16_t sum = pdp8_bin_checksum(std::span(t).subspan(10));  // 0100 + 010 = 0110
    EXPECT_EQ(sum, 0110U);
    t.push_back(0100);  // high frame 00, with the origin bit
    t.push_back(0110);  // low frame 010 with 0100: the word is 0000 + 0110
    t.insert(t.end(), 10, 0200);
    BinaryTape b = read_as(BinaryReader::Family::pdp8, t);
    ASSERT_EQ(b.block_count, 1U);
    EXPECT_EQ(b.blocks[0].checksum->state, ChecksumSpan::State::holds) << b.summary();
}

TEST(Pdp8Bin, FieldSettingsAndCommentsBetweenRubouts) {
    std::vector<Frame> t(10, 0200);
    std::size_t start = t.size();
    for (Frame f : {0377, 'H' | 0200, 'I' | 0200, 0377}) t.push_back(f);  // a comment the loader skips
    t.push_back(0310);                                                    // field 1
    word(t, 0400, true);
    word(t, 01234);
    std::uint16_t sum = pdp8_bin_checksum(std::span(t).subspan(start));
    word(t, sum);
    t.insert(t.end(), 10, 0200);
    BinaryReader r(BinaryReader::Family::pdp8, true);
    r.feed(t);
    r.finish();
    ASSERT_EQ(r.tape().block_count, 1U);
    EXPECT_EQ(r.tape().blocks[0].checksum->state, ChecksumSpan::State::holds);
    EXPECT_EQ(r.tape().blocks[0].origin, 010400U) << "field 1, address 0400";
    EXPECT_TRUE(r.image().loaded(010400));
    EXPECT_EQ(r.image().at(010400), 01234U);
}

TEST(Pdp8Rim, AddressWordPairsWithoutChecksum) {
    auto t = pdp8_rim({{07756, 06032}, {07757, 06031}, {07760, 05357}, {07761, 07106}});
    BinaryTape b = read_as(BinaryReader::Family::pdp8, t);
    ASSERT_EQ(b.format, BinaryFormat::pdp8_rim);
    EXPECT_TRUE(b.recognised());
    EXPECT_FALSE(b.blocks[0].checksum);
    EXPECT_EQ(b.blocks[0].words, 4U);
    EXPECT_EQ(b.summary(), "PDP-8 RIM: 1 section, no checksum (RIM has none)");
    BinaryReader r(BinaryReader::Family::pdp8, true);
    r.feed(t);
    r.finish();
    EXPECT_EQ(memory_image_octal(r.image()), "07756: 6032 6031 5357 7106\n");
}

TEST(Pdp8Bin, ATapeWithoutItsTrailerChecksNothing) {
    auto t = pdp8_bin(0200, {07300, 01276});
    ASSERT_GT(t.size(), 30U);
    t.erase(t.end() - 30, t.end());  // no trailer
    t.insert(t.end(), 50, 0);        // blank runout, not words of 0000
    BinaryTape b = read_as(BinaryReader::Family::pdp8, t);
    ASSERT_EQ(b.block_count, 1U);
    EXPECT_EQ(b.blocks[0].checksum->state, ChecksumSpan::State::missing);
    EXPECT_TRUE(b.blocks[0].cut);
    EXPECT_EQ(b.blocks[0].frames, 8U) << "the runout is not part of it";
}

TEST(BinaryDetector, TextTapesAreNoBinaryTapes) {
    std::vector<Frame> text(20000);
    for (std::size_t i = 0; i < text.size(); ++i) text[i] = "%\nN10 G01 X12.5\n"[i % 16];
    BinaryDetector d;
    d.feed(text);
    d.finish();
    EXPECT_EQ(d.tape(), nullptr);
}

TEST(BinaryDetector, TheBundledBinLoaderTapeIsBin) {
    BinaryDetector d;
    d.feed(read_frames(sample_path("bad/pdp8-bin-loader.bin")));
    d.finish();
    ASSERT_NE(d.tape(), nullptr);
    EXPECT_EQ(d.tape()->format, BinaryFormat::pdp8_bin);
    EXPECT_EQ(d.tape()->summary(), "PDP-8 BIN: 1 section, its checksum holds");
}

TEST(BinaryDetector, TheVerdictNamesTheFormat) {
    auto d = detect_code(pdp11_tape());
    EXPECT_EQ(d.kind, TapeKind::binary);
    ASSERT_TRUE(d.evidence.binary);
    EXPECT_EQ(d.reason.rfind("binary tape, not a character code: PDP-11 absolute loader: 3 blocks", 0), 0U) << d.reason;
}

// Real tapes from outside (../shared/data), where they are.
TEST(BinaryDetector, RealDecTapes) {
    std::string dir = shared_data_dir() + "/outside2/tapes/";
    if (shared_data_dir().empty()) GTEST_SKIP() << "../shared/data is absent: the real tapes are not in the project";
    struct Case {
        const char* file;
        BinaryFormat format;
        std::uint64_t blocks, held;
    };
    for (const Case& c : {Case{"pdp11/MAINDEC-11-D0AA-PB.ptap", BinaryFormat::pdp11_absolute, 20, 20},
                          Case{"pdp11/DEC-11-E1PA-PB.ptap", BinaryFormat::pdp11_absolute, 105, 105},
                          Case{"pdp8/FOCAL-8.bn", BinaryFormat::pdp8_bin, 1, 1},
                          Case{"pdp8/D1EA-Memory-Address.rim", BinaryFormat::pdp8_rim, 3, 0}}) {
        BinaryDetector d;
        d.feed(read_frames(dir + c.file));
        d.finish();
        ASSERT_NE(d.tape(), nullptr) << c.file;
        EXPECT_EQ(d.tape()->format, c.format) << c.file;
        EXPECT_EQ(d.tape()->block_count, c.blocks) << c.file;
        EXPECT_EQ(d.tape()->checksums_held, c.held) << c.file;
    }
}
