#include "tape/image_input.hpp"

#include <algorithm>
#include <new>

#include "tape/error.hpp"

namespace tape {
namespace {

constexpr std::size_t chunk_bytes = 128 << 10;       // small enough to stay in the cache between stages
constexpr std::size_t detection_frames = 256 << 10;  // frames read ahead to detect the code
constexpr std::size_t detection_limit = 4 << 20;     // ... and at most, past a long blank leader
constexpr std::size_t prefix_bytes = 4096;           // what content detection of the format looks at

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
        bytes_.resize(prefix_bytes);
        bytes_.resize(source_->read_full(bytes_));
        format_ = &detect_image_format(bytes_);
    }
    if (!format_->can_read())
        throw Error(Errc::usage, "cannot read " + std::string(format_->id) + " images, only write them");
    reader_ = format_->make_reader();
}

void ImageInput::allocate_buffer() {
    read_buffer_.reset(static_cast<std::uint8_t*>(std::aligned_alloc(4096, chunk_bytes)));
    if (!read_buffer_) throw std::bad_alloc();
}

bool ImageInput::fill() {
    if (ended_) return false;
    if (!read_buffer_) allocate_buffer();
    std::span<const std::uint8_t> chunk = bytes_;  // the bytes format detection looked at come first
    std::size_t n = 0;
    if (chunk.empty()) {
        n = source_->read(std::span(read_buffer_.get(), chunk_bytes));
        chunk = std::span(read_buffer_.get(), n);
    }
    if (chunk.empty()) ended_ = true;
    std::size_t had = ahead_.size();
    if (ended_)
        reader_->finish(ahead_);
    else
        reader_->read(chunk, ahead_);
    bytes_.clear();
    return !ended_ || ahead_.size() > had;
}

std::span<const Frame> ImageInput::next() {
    given_.clear();
    given_any_ = true;
    if (!ahead_.empty()) {
        given_.swap(ahead_);
        return given_;
    }
    if (format_->bytes_are_frames && bytes_.empty()) {
        // The common case, without a copy: the bytes are the frames.
        if (!read_buffer_) allocate_buffer();
        if (ended_) return {};
        std::size_t n = source_->read(std::span(read_buffer_.get(), chunk_bytes));
        if (n == 0) ended_ = true;
        return std::span<const Frame>(read_buffer_.get(), n);
    }
    while (ahead_.empty())
        if (!fill()) return {};
    given_.swap(ahead_);
    return given_;
}

CodeDetection ImageInput::detect(const CodeTable* eia_table) {
    // The verdict is drawn from the read-ahead: the whole of most tapes (an NC program is a few
    // thousand frames), the first detection_frames of a longer one. A leader longer than that (no
    // punched frame yet) is read on, up to detection_limit.
    auto punched = [&] { return std::any_of(ahead_.begin(), ahead_.end(), [](Frame f) { return f != 0; }); };
    while (ahead_.size() < detection_frames || (ahead_.size() < detection_limit && !punched()))
        if (!fill() && ended_) break;
    Detector detector(eia_table, format_->bytes_are_frames);
    std::vector<Frame> scratch;
    detector.feed(without_label(ahead_, 0, given_any_ ? std::nullopt : label(), scratch));
    if (ended_)
        detector.finish();
    else
        detector.partial();
    return detector.result();
}

std::optional<Code> ImageInput::declared_code() {
    if (ahead_.empty() && !given_any_) fill();  // the header comes first: one chunk holds it
    return reader_->declared_code();
}

const std::optional<LeaderLabel>& ImageInput::label() {
    if (label_checked_ || given_any_) return label_;
    label_checked_ = true;
    std::size_t first = 0;  // the leader's first punched frame; the frames before it are not looked at again
    for (;;) {
        while (first < ahead_.size() && ahead_[first] == blank_frame) ++first;
        if (first < ahead_.size() && ahead_.size() - first > label_search_frames) break;
        if (first == ahead_.size() && ahead_.size() >= detection_limit) break;  // an endless leader holds no label
        if (!fill() && ended_) break;
    }
    label_ = find_label(ahead_);
    return label_;
}

}  // namespace tape
