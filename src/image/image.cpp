// The image format table: the one place formats are listed.
#include "tape/image.hpp"

#include <algorithm>
#include <cctype>

#include "image_formats.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

// In the order content detection tries them; one line per format.
const ImageFormat formats[] = {
    holes_image_format(), hex_image_format(),  hex8_image_format(), hex5_image_format(),
    dump_image_format(),  bits_image_format(), raw_image_format(),
};

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
    return out;
}

}  // namespace

std::span<const ImageFormat> image_formats() { return formats; }

const ImageFormat* find_image_format(std::string_view id) {
    for (const auto& f : formats)
        if (f.id == id) return &f;
    return nullptr;
}

const ImageFormat* image_format_for_path(std::string_view path) {
    auto dot = path.rfind('.');
    auto slash = path.rfind('/');
    if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) return nullptr;
    std::string ext = lower(path.substr(dot));
    for (const auto& f : formats)
        for (auto e : f.extensions)
            if (e == ext) return &f;
    return nullptr;
}

bool extension_is_ambiguous(std::string_view path) { return lower(path).ends_with(".txt"); }

const ImageFormat& detect_image_format(std::span<const std::uint8_t> prefix) {
    const ImageFormat* best = &formats[0];
    int best_score = -1;
    for (const auto& f : formats) {
        if (!f.can_read()) continue;
        int score = f.match(prefix);
        if (score > best_score) {
            best = &f;
            best_score = score;
        }
    }
    return *best;
}

std::optional<Code> header_code(std::string_view comment) {
    constexpr std::string_view key = "code:";
    auto hash = comment.find_first_not_of(" \t");
    if (hash == std::string_view::npos || comment[hash] != '#') return std::nullopt;
    comment.remove_prefix(hash + 1);
    comment.remove_prefix(std::min(comment.find_first_not_of(" \t"), comment.size()));
    if (!comment.starts_with(key)) return std::nullopt;
    comment.remove_prefix(key.size());
    comment.remove_prefix(std::min(comment.find_first_not_of(" \t"), comment.size()));
    return parse_code(comment.substr(0, comment.find_first_of(" \t,;\r")));
}

// raw: what simulators, punches and other tools take.
const ImageFormat& default_image_format() { return *find_image_format("raw"); }

std::vector<Frame> ImageFormat::read(std::span<const std::uint8_t> bytes) const {
    if (!make_reader) throw Error(Errc::usage, std::string(id) + " images can only be written");
    std::vector<Frame> frames;
    auto reader = make_reader();
    reader->read(bytes, frames);
    reader->finish(frames);
    return frames;
}

std::string ImageFormat::write(std::span<const Frame> frames, const ImageWriteOptions& options) const {
    if (!make_writer) throw Error(Errc::usage, std::string(id) + " images can only be read");
    std::string out;
    auto writer = make_writer(options);
    writer->write(frames, out);
    writer->finish(out);
    return out;
}

}  // namespace tape
