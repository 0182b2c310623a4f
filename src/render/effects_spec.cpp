// The picture effects of tape render written as KEY=VALUE,... (tape/render.hpp): how a user or a test
// asks for a tape drawn as a scanner or a camera would show it.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

#include "tape/error.hpp"
#include "tape/render.hpp"

namespace tape {
namespace {

std::string shown(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

double number(std::string_view key, std::string_view value, double lo, double hi) {
    double v = 0;
    auto r = std::from_chars(value.data(), value.data() + value.size(), v);
    if (r.ec != std::errc() || r.ptr != value.data() + value.size() || !std::isfinite(v) || v < lo || v > hi)
        throw Error(Errc::usage, std::string(key) + "=" + std::string(value) + ": a number from " + shown(lo) + " to " +
                                     shown(hi) + " is needed");
    return v;
}

std::uint32_t colour(std::string_view key, std::string_view value) {
    std::uint32_t v = 0;
    auto r = std::from_chars(value.data(), value.data() + value.size(), v, 16);
    if (value.size() != 6 || r.ec != std::errc() || r.ptr != value.data() + value.size())
        throw Error(Errc::usage, std::string(key) + "=" + std::string(value) + ": a colour as RRGGBB in hex is needed");
    return v;
}

void set(std::string_view key, std::string_view value, RasterOptions& r, PictureEffects& e) {
    if (key == "skew")
        r.skew_deg = number(key, value, -45, 45);
    else if (key == "bow")
        r.bow_mm = number(key, value, -100, 100);
    else if (key == "stains")
        r.stains = static_cast<int>(number(key, value, 0, 1000));
    else if (key == "paper")
        r.paper = colour(key, value);
    else if (key == "backing")
        r.backing = colour(key, value);
    else if (key == "light")
        e.light = number(key, value, 0, 0.9);
    else if (key == "dust")
        e.dust = static_cast<int>(number(key, value, 0, 100000));
    else if (key == "blur")
        e.blur_px = number(key, value, 0, 50);
    else if (key == "noise")
        e.noise = number(key, value, 0, 128);
    else if (key == "jpeg")
        e.jpeg_quality = static_cast<int>(number(key, value, 1, 100));
    else if (key == "seed")
        r.seed = e.seed = static_cast<std::uint64_t>(number(key, value, 0, 1e15));
    else
        throw Error(Errc::usage, "no picture effect " + std::string(key) +
                                     " (skew, bow, stains, paper, backing, light, dust, blur, noise, jpeg, seed)");
}

}  // namespace

void parse_picture_effects(std::string_view spec, RasterOptions& raster, PictureEffects& effects) {
    while (!spec.empty()) {
        auto comma = spec.find(',');
        std::string_view item = spec.substr(0, comma);
        spec = comma == std::string_view::npos ? std::string_view{} : spec.substr(comma + 1);
        auto eq = item.find('=');
        if (eq == std::string_view::npos) throw Error(Errc::usage, std::string(item) + ": KEY=VALUE is needed");
        set(item.substr(0, eq), item.substr(eq + 1), raster, effects);
    }
}

}  // namespace tape
