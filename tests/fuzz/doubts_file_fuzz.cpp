// libFuzzer target: the doubts file beside a restored image (IMAGE.restore.json), read by every command
// that reads the image. The input is read as it is, and again with its "image" made the fingerprint of
// the image the harness holds, so that the fuzzer reaches the problems behind the fingerprint check.
// Whatever comes in: no exception, no undefined conversion (a frame past 2^64, negative, a fraction),
// every entry read has a place, the entries are sorted, and the refusals said are bounded.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <string_view>

#include "tape/restore_doubts.hpp"

namespace {

const std::uint8_t image_bytes[] = {0, 0, 0, 0x25, 0x0A, 0x4E, 0x31, 0x0A, 0, 0};

void check(const tape::DoubtsFile& f) {
    constexpr std::size_t most_said = 11;  // ten refusals and how many more
    if (f.refused.size() > most_said) __builtin_trap();
    for (std::size_t i = 0; i < f.frames.size(); ++i) {
        const auto& d = f.frames[i];
        if (!d.left_out && d.frame == 0) __builtin_trap();
        if (i > 0 && f.frames[i - 1].place() > d.place()) __builtin_trap();
        if (d.message().empty()) __builtin_trap();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    std::span<const std::uint8_t> image(image_bytes);
    check(tape::read_doubts(text, image));
    auto j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) return 0;
    j["image"] = {{"bytes", image.size()}, {"fnv1a64", tape::image_fingerprint(image)}};
    check(tape::read_doubts(j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), image));
    return 0;
}
