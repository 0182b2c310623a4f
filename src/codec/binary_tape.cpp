// Binary loader tapes: the formats' names, the memory image, and the detector that tries both families.
#include <cstdio>

#include "binary_parser.hpp"

namespace tape {
namespace {

std::string count_text(std::uint64_t n, const std::string& one, const std::string& many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string address_text(BinaryFormat f, std::uint32_t a) {
    return f == BinaryFormat::pdp11_absolute ? octal_text(a, 6) : octal_text(a, 5);
}

}  // namespace

std::string_view binary_format_name(BinaryFormat f) {
    switch (f) {
        case BinaryFormat::pdp8_rim:
            return "PDP-8 RIM";
        case BinaryFormat::pdp8_bin:
            return "PDP-8 BIN";
        case BinaryFormat::pdp11_absolute:
            return "PDP-11 absolute loader";
    }
    return "?";
}

std::string_view binary_format_id(BinaryFormat f) {
    switch (f) {
        case BinaryFormat::pdp8_rim:
            return "pdp8-rim";
        case BinaryFormat::pdp8_bin:
            return "pdp8-bin";
        case BinaryFormat::pdp11_absolute:
            return "pdp11-absolute";
    }
    return "?";
}

std::string_view checksum_state_name(ChecksumSpan::State s) {
    switch (s) {
        case ChecksumSpan::State::holds:
            return "holds";
        case ChecksumSpan::State::fails:
            return "fails";
        case ChecksumSpan::State::missing:
            return "missing";
    }
    return "?";
}

MemoryImage::MemoryImage(BinaryFormat format)
    : size_(format == BinaryFormat::pdp11_absolute ? 65536 : 32768), words_(format != BinaryFormat::pdp11_absolute) {}

void MemoryImage::store(std::uint32_t address, std::uint16_t value) {
    if (cells_.empty()) cells_.resize(size_);
    address %= size_;
    cells_[address] = value;
    loaded_.set(address);
}

std::optional<std::pair<std::uint32_t, std::uint32_t>> MemoryImage::extent() const {
    if (loaded_.none()) return std::nullopt;
    std::uint32_t low = 0, high = size_ - 1;
    while (!loaded_[low]) ++low;
    while (!loaded_[high]) --high;
    return std::pair(low, high);
}

void BinaryReader::Parser::add_block(const BinaryBlock& b) {
    ++tape_.block_count;
    if (tape_.blocks.size() < max_listed_blocks) tape_.blocks.push_back(b);
    if (b.format == BinaryFormat::pdp11_absolute) {
        tape_.format = b.format;
    } else {  // PDP-8: the format of most sections, RIM or BIN
        (b.format == BinaryFormat::pdp8_rim ? rim_sections_ : bin_sections_)++;
        tape_.format = bin_sections_ >= rim_sections_ ? BinaryFormat::pdp8_bin : BinaryFormat::pdp8_rim;
        tape_.mixed = rim_sections_ && bin_sections_;
    }
    if (!b.checksum) return;
    switch (b.checksum->state) {
        case ChecksumSpan::State::holds:
            ++tape_.checksums_held;
            break;
        case ChecksumSpan::State::fails:
            ++tape_.checksums_failed;
            break;
        case ChecksumSpan::State::missing:
            ++tape_.checksums_missing;
            break;
    }
}

void BinaryReader::Parser::add_stray(std::uint64_t count, std::uint64_t first) {
    if (tape_.stray_frames == 0) tape_.first_stray = first;
    tape_.stray_frames += count;
}

bool BinaryTape::recognised() const {
    if (!format || block_count == 0 || stray_frames * 5 > punched) return false;
    // A PDP-11 block is any 001 000 with a count: chance makes them of noise, but never their checksums.
    if (*format == BinaryFormat::pdp11_absolute) return checksums_held > 0 && checksums_held * 3 >= checksums_failed;
    // A PDP-8 section is leader, an origin, words of two 6-bit frames and a trailer, no other frame: noise and
    // text have frames with track 8. So a damaged tape whose checksums fail is still named (and its damage).
    std::uint64_t words = 0;
    for (const auto& b : blocks) words += b.words;
    return checksums_held + checksums_failed > 0 || words >= 4;
}

std::string BinaryTape::summary() const {
    if (!format) return "no block of a binary loader format";
    bool pdp11 = *format == BinaryFormat::pdp11_absolute;
    std::string s = mixed ? "PDP-8 RIM and BIN" : std::string(binary_format_name(*format));
    s += ": " + count_text(block_count, pdp11 ? "block" : "section", pdp11 ? "blocks" : "sections");
    std::uint64_t checks = checksums_held + checksums_failed + checksums_missing;
    if (checks == 0)
        s += ", no checksum (RIM has none)";
    else if (checksums_held == checks)
        s += checks == 1 ? ", its checksum holds" : ", every checksum holds";
    else
        s += ", " + std::to_string(checksums_held) + " of " + std::to_string(checks) + " checksums hold" +
             (checksums_failed ? ", " + std::to_string(checksums_failed) + " fail" : "") +
             (checksums_missing ? ", " + std::to_string(checksums_missing) + " cut off by the end of the tape" : "");
    if (pdp11 && !ended) s += "; no end block: the tape ends early";
    if (!pdp11 && !blocks.empty() && blocks.size() == block_count && blocks.back().cut)
        s += "; the tape ends inside the last section, without its trailer";
    if (start)
        s += "; start address " + address_text(*format, *start) +
             (*start & 1 ? " (odd: the loader halts, no program started)" : "");
    if (stray_frames)
        s += "; " + count_text(stray_frames, "punched frame", "punched frames") + " from frame " +
             std::to_string(first_stray + 1) + " belong to no block";
    return s;
}

BinaryReader::BinaryReader(Family family, bool keep_image)
    : parser_(family == Family::pdp8 ? make_pdp8_parser(keep_image) : make_pdp11_parser(keep_image)) {}
BinaryReader::~BinaryReader() = default;
BinaryReader::BinaryReader(BinaryReader&&) noexcept = default;
BinaryReader& BinaryReader::operator=(BinaryReader&&) noexcept = default;

void BinaryReader::feed(std::span<const Frame> frames) { parser_->feed(frames); }
void BinaryReader::finish() { parser_->finish(); }
const BinaryTape& BinaryReader::tape() const { return parser_->tape(); }
const MemoryImage& BinaryReader::image() const { return parser_->image(); }

BinaryDetector::BinaryDetector(bool keep_image)
    : readers_{BinaryReader(BinaryReader::Family::pdp8, keep_image),
               BinaryReader(BinaryReader::Family::pdp11, keep_image)} {}

// Past judged_after punched frames, a family that explains less than four fifths of them never will.
// It is judged every `judged_every` frames of the tape, counted from its start, so that a text tape
// costs its parsers a few thousand frames, not a long read-ahead, and the verdict does not depend on
// how the tape was cut.
void BinaryDetector::feed(std::span<const Frame> frames) {
    constexpr std::uint64_t judged_after = 4096, judged_every = 4096;
    while (!frames.empty() && !finished_ && !(given_up_[0] && given_up_[1])) {
        std::size_t n = std::min<std::uint64_t>(frames.size(), judged_every - fed_ % judged_every);
        for (std::size_t i = 0; i < readers_.size(); ++i) {
            if (given_up_[i]) continue;
            readers_[i].feed(frames.first(n));
            const BinaryTape& t = readers_[i].tape();
            given_up_[i] = t.punched >= judged_after && t.stray_frames * 5 > t.punched;
        }
        fed_ += n;
        frames = frames.subspan(n);
    }
}

void BinaryDetector::finish() {
    if (finished_) return;
    finished_ = true;
    for (std::size_t i = 0; i < readers_.size(); ++i)
        if (!given_up_[i]) readers_[i].finish();
}

const BinaryTape* BinaryDetector::tape() const {
    for (std::size_t i = 0; i < readers_.size(); ++i)
        if (!given_up_[i] && readers_[i].tape().recognised()) return &readers_[i].tape();
    return nullptr;
}

const MemoryImage* BinaryDetector::image() const {
    for (std::size_t i = 0; i < readers_.size(); ++i)
        if (!given_up_[i] && readers_[i].tape().recognised()) return &readers_[i].image();
    return nullptr;
}

std::string memory_image_bytes(const MemoryImage& image) {
    std::string out;
    auto extent = image.extent();
    if (!extent) return out;
    for (std::uint32_t a = 0; a <= extent->second; ++a) {
        std::uint16_t v = image.at(a);
        out += static_cast<char>(v & 0xFF);
        if (image.words()) out += static_cast<char>(v >> 8);
    }
    return out;
}

std::string memory_image_octal(const MemoryImage& image) {
    std::string out;
    const bool pdp11 = !image.words();
    const std::uint32_t step = pdp11 ? 2 : 1;  // the PDP-11's words are two bytes, low first
    int on_line = 0;
    for (std::uint32_t a = 0; a < image.size(); a += step) {
        if (!image.loaded(a) && !(pdp11 && image.loaded(a + 1))) {
            if (on_line) out += "\n";
            on_line = 0;
            continue;
        }
        if (on_line == 0) {
            out += pdp11 ? octal_text(a, 6) : octal_text(a, 5);
            out += ":";
        }
        std::uint32_t v = pdp11 ? image.at(a) | image.at(a + 1) << 8 : image.at(a);
        out += " " + octal_text(v, pdp11 ? 6 : 4);
        if (++on_line == 8) {
            out += "\n";
            on_line = 0;
        }
    }
    if (on_line) out += "\n";
    return out;
}

bool checksum_holds(BinaryFormat format, std::span<const Frame> frames) {
    if (format == BinaryFormat::pdp11_absolute) {
        if (frames.size() < 7 || frames[0] != 1 || frames[1] != 0) return false;
        std::size_t count = frames[2] | static_cast<std::size_t>(frames[3]) << 8;
        return count + 1 == frames.size() && pdp11_checksum(frames) == 0;
    }
    if (format != BinaryFormat::pdp8_bin) return false;
    // The word frames, as the loader takes them: the last two are the checksum word.
    std::vector<Frame> words;
    bool comment = false;
    for (Frame f : frames) {
        if (f == 0377) comment = !comment;
        if (comment || f == 0377 || (f & 0200)) continue;
        words.push_back(f);
    }
    if (words.size() < 4 || words.size() % 2) return false;
    Frame high = words[words.size() - 2], low = words.back();
    std::uint16_t stored = static_cast<std::uint16_t>(((high & 077) << 6) + low) & 07777;
    return pdp8_bin_checksum(std::span(words).first(words.size() - 2)) == stored;
}

std::string octal_text(std::uint32_t value, int digits) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%0*o", digits, value);
    return buf;
}

}  // namespace tape
