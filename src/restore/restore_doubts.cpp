// The doubts file beside a restored image (tape/restore_doubts.hpp).
#include "tape/restore_doubts.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <utility>

namespace tape {
namespace {

// Larger images are not fingerprinted: no restored paper tape is that long.
constexpr std::uint64_t largest_image = 1ULL << 30;

std::string read_small_file(const std::string& path, std::uint64_t most) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode) || static_cast<std::uint64_t>(st.st_size) > most)
        return {};
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

std::string doubts_file_for(std::string_view image_path) { return std::string(image_path) + ".restore.json"; }

std::string image_fingerprint(std::span<const std::uint8_t> bytes) {
    std::uint64_t h = 0xCBF29CE484222325ULL;
    for (std::uint8_t b : bytes) h = (h ^ b) * 0x100000001B3ULL;
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

std::vector<DoubtfulFrame> doubts_beside(const std::string& image_path) {
    std::vector<DoubtfulFrame> out;
    std::string doubts = read_small_file(doubts_file_for(image_path), largest_image);
    if (doubts.empty()) return out;
    try {
        auto j = nlohmann::json::parse(doubts);
        const auto& image = j.at("image");
        std::string bytes = read_small_file(image_path, largest_image);
        auto data = std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
        if (image.at("bytes").get<std::uint64_t>() != bytes.size() ||
            image.at("fnv1a64").get<std::string>() != image_fingerprint(data))
            return out;
        for (const auto& p : j.at("problems")) {
            if (!p.at("in_doubt").get<bool>()) continue;
            // A frame left out has no frame of its own: its place is after frame `after`.
            bool left_out = p.at("frame").is_null();
            out.push_back({p.at(left_out ? "after" : "frame").get<std::uint64_t>(), p.at("status").get<std::string>(),
                           p.at("reason").get<std::string>(), left_out});
            if (!left_out && out.back().frame == 0) return {};  // no frame 0: not a file restore wrote
        }
    } catch (const nlohmann::json::exception&) {
        return {};
    }
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
        return std::pair(a.place(), !a.left_out) < std::pair(b.place(), !b.left_out);
    });
    return out;
}

std::string DoubtfulFrame::message() const {
    std::string where = !left_out ? ""
                        : frame   ? "a frame left out after this one, "
                                  : "a frame left out before this one, ";
    return "restored in doubt (" + status + "): " + where + reason;
}

}  // namespace tape
