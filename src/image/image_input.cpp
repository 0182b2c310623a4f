#include "tape/image_input.hpp"

#include <algorithm>

#include "tape/error.hpp"

namespace tape {
namespace {

constexpr std::size_t chunk_bytes = 128 << 10;    // small enough to stay in the cache between stages
constexpr std::size_t detection_limit = 4 << 20;  // frames held for detection at most
constexpr std::size_t prefix_bytes = 4096;        // what content detection of the format looks at

}  // namespace

ImageInput::ImageInput(const std::string& path, const ImageFormat* format)
    : ImageInput(std::make_unique<FileSource>(path), path, format) {}

ImageInput::ImageInput(std::unique_ptr<ByteSource> source, const std::string& name, const ImageFormat* format)
    : source_(std::move(source)), format_(format) {
    if (!format_ && name != "-" && !name.empty()) format_ = image_format_for_path(name);
    // ".txt" may be a holes picture or anything else: there the content decides. A format given by the
    // caller or named by a format's own extension (".holes") is never overridden by the content.
    bool content_decides = !format_ || (!format && extension_is_ambiguous(name));
    if (content_decides) {
        std::uint8_t buf[prefix_bytes];
        while (bytes_.size() < prefix_bytes) {
            std::size_t n = source_->read(std::span(buf, prefix_bytes - bytes_.size()));
            if (n == 0) break;
            bytes_.insert(bytes_.end(), buf, buf + n);
        }
        format_ = &detect_image_format(bytes_);
    }
    whole_file_format_ = format_->binary ? format_->id != "raw" : false;
}

bool ImageInput::fill() {
    if (ended_) return false;
    std::size_t had = bytes_.size();
    bytes_.resize(had + chunk_bytes);
    std::size_t n = source_->read(std::span(bytes_).subspan(had));
    bytes_.resize(had + n);
    bool last = n == 0;
    if (last) ended_ = true;
    if (format_->id == "raw") {
        ahead_.insert(ahead_.end(), bytes_.begin(), bytes_.end());
        bytes_.clear();
        return !last || !ahead_.empty();
    }
    if (whole_file_format_) {
        if (!last) return true;  // keep reading: this format is parsed whole
        auto frames = format_->read(bytes_);
        ahead_.insert(ahead_.end(), frames.begin(), frames.end());
        bytes_.clear();
        return !ahead_.empty();
    }
    // A text format: whole lines are parsed as they come; line numbers in errors count from the start.
    auto end = last ? bytes_.end() : std::find(bytes_.rbegin(), bytes_.rend(), '\n').base();
    if (end == bytes_.begin() && !last) return true;
    std::span<const std::uint8_t> lines(bytes_.data(), static_cast<std::size_t>(end - bytes_.begin()));
    try {
        auto frames = format_->read(lines);
        ahead_.insert(ahead_.end(), frames.begin(), frames.end());
    } catch (const Error& e) {
        Position where = e.where();
        if (where.line) *where.line += lines_before_;
        throw Error(e.code(), where, e.what());
    }
    lines_before_ += static_cast<std::uint64_t>(std::count(lines.begin(), lines.end(), '\n'));
    bytes_.erase(bytes_.begin(), end);
    return !last || !ahead_.empty();
}

std::span<const Frame> ImageInput::next() {
    given_.clear();
    if (!ahead_.empty()) {
        given_.swap(ahead_);
        return given_;
    }
    if (format_->id == "raw" && bytes_.empty()) {
        // The common case, without a copy: the bytes are the frames.
        if (!raw_buffer_) raw_buffer_ = std::make_unique_for_overwrite<std::uint8_t[]>(chunk_bytes);
        if (ended_) return {};
        std::size_t n = source_->read(std::span(raw_buffer_.get(), chunk_bytes));
        if (n == 0) ended_ = true;
        return std::span<const Frame>(raw_buffer_.get(), n);
    }
    while (ahead_.empty()) {
        if (!fill()) return {};
        if (ended_ && ahead_.empty()) return {};
    }
    given_.swap(ahead_);
    return given_;
}

CodeDetection ImageInput::detect() {
    // detect_code looks at the frames before the first end of block (at most 4096 punched ones) and
    // counts parity over the first 16384 frames: read ahead until both are covered or the limit is hit.
    std::size_t scanned = 0, punched = 0;
    bool decided = false;  // an end of block, or 4096 punched frames, among the frames read so far
    auto enough = [&] {
        for (; scanned < ahead_.size() && !decided; ++scanned) {
            Frame f = ahead_[scanned];
            if (f == 0x00 || f == 0xFF || f == 0x7F) continue;
            decided = f == 0x0A || f == 0x80 || ++punched >= 4096;
        }
        return decided && ahead_.size() >= 16384;
    };
    while (!enough() && ahead_.size() < detection_limit)
        if (!fill() && ended_) break;
    return detect_code(ahead_);
}

}  // namespace tape
