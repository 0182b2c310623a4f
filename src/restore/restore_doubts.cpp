// The doubts file beside a restored image (tape/restore_doubts.hpp).
#include "tape/restore_doubts.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
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

namespace {

using Json = nlohmann::json;

// Entries refused are said one by one up to this many, then counted: a hostile file cannot flood the terminal.
constexpr std::size_t refusals_said = 10;

// A member as JSON shows it, cut short: what the entry holds, for the message that refuses it.
std::string shown(const Json& v) {
    std::string s = v.dump(-1, ' ', true, Json::error_handler_t::replace);
    return s.size() > 40 ? s.substr(0, 37) + "..." : s;
}

// A frame number as restore writes it: a whole number from 0. JSON reads a larger one (past 2^64), a
// fraction or an exponent as a double, which no frame is and whose conversion would be undefined; a
// sign as a signed number.
std::optional<std::uint64_t> frame_number(const Json& v) {
    if (v.is_number_unsigned()) return v.get<std::uint64_t>();
    return std::nullopt;
}

std::optional<DoubtfulFrame> refuse(std::string& why, std::string text) {
    why = std::move(text);
    return std::nullopt;
}

// One problem of the file as a DoubtfulFrame: nullopt for one that is neither in doubt nor a run decided
// against a read; nullopt and why for one that is not as restore writes it.
std::optional<DoubtfulFrame> entry(const Json& p, std::string& why) {
    if (!p.is_object()) return refuse(why, "not an object");
    auto in_doubt = p.find("in_doubt");
    if (in_doubt == p.end() || !in_doubt->is_boolean()) return refuse(why, "no in_doubt true or false");
    auto run = p.find("run_length");
    bool decided = !in_doubt->get<bool>() && run != p.end() && run->is_boolean() && run->get<bool>();
    if (!in_doubt->get<bool>() && !decided) return std::nullopt;
    DoubtfulFrame d;
    d.decided = decided;
    auto frame = p.find("frame"), after = p.find("after");
    d.left_out = frame == p.end() || frame->is_null();
    const char* key = d.left_out ? "after" : "frame";
    const auto& place = d.left_out ? after : frame;
    if (place == p.end()) return refuse(why, std::string("no ") + key);
    auto n = frame_number(*place);
    if (!n) return refuse(why, std::string("its ") + key + " (" + shown(*place) + ") is no frame number");
    if (!d.left_out && *n == 0) return refuse(why, "its frame is 0: frames are counted from 1");
    d.frame = *n;
    for (auto [field, out] : {std::pair{"status", &d.status}, std::pair{"reason", &d.reason}}) {
        auto v = p.find(field);
        if (v == p.end() || !v->is_string()) return refuse(why, std::string("no ") + field + " in words");
        *out = v->get<std::string>();
    }
    return d;
}

bool same_image(const Json& j, std::span<const std::uint8_t> image) {
    auto it = j.find("image");
    if (it == j.end() || !it->is_object()) return false;
    auto bytes = it->find("bytes"), fnv = it->find("fnv1a64");
    return bytes != it->end() && frame_number(*bytes) == image.size() && fnv != it->end() && fnv->is_string() &&
           fnv->get<std::string>() == image_fingerprint(image);
}

}  // namespace

DoubtsFile read_doubts(std::string_view json, std::span<const std::uint8_t> image) {
    DoubtsFile out;
    Json j = Json::parse(json, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        out.refused.push_back("not the JSON tape restore writes: not read");
        return out;
    }
    if (!same_image(j, image)) return out;  // of the image as it was: changed since, its doubts are not its own
    auto problems = j.find("problems");
    if (problems == j.end() || !problems->is_array()) {
        out.refused.push_back("no list of problems: not read");
        return out;
    }
    std::size_t refused = 0;
    for (std::size_t i = 0; i < problems->size(); ++i) {
        std::string why;
        auto d = entry((*problems)[i], why);
        if (d) out.frames.push_back(std::move(*d));
        if (why.empty()) continue;
        if (++refused <= refusals_said)
            out.refused.push_back("problem " + std::to_string(i + 1) + ": " + why + ": not read");
    }
    if (refused > refusals_said)
        out.refused.push_back(std::to_string(refused - refusals_said) + " more problem(s) not read");
    std::stable_sort(out.frames.begin(), out.frames.end(), [](const auto& a, const auto& b) {
        return std::pair(a.place(), !a.left_out) < std::pair(b.place(), !b.left_out);
    });
    return out;
}

DoubtsFile read_doubts_beside(const std::string& image_path) {
    std::string doubts = read_small_file(doubts_file_for(image_path), largest_image);
    if (doubts.empty()) return {};
    std::string bytes = read_small_file(image_path, largest_image);
    return read_doubts(doubts, std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
}

std::vector<DoubtfulFrame> doubts_beside(const std::string& image_path) {
    std::vector<DoubtfulFrame> out;
    for (auto& d : read_doubts_beside(image_path).frames)
        if (!d.decided) out.push_back(std::move(d));
    return out;
}

std::string DoubtfulFrame::message() const {
    std::string where = !left_out ? ""
                        : frame   ? "a frame left out after this one, "
                                  : "a frame left out before this one, ";
    if (decided) return "run length decided against a read (" + status + "): " + where + reason;
    return "restored in doubt (" + status + "): " + where + reason;
}

}  // namespace tape
