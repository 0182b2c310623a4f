// What a scanner or a camera adds to a picture of a tape (tape/render.hpp): light falling unevenly,
// dust on the glass, blur, noise and JPEG's losses, each drawn from a seed so that a test picture is
// the same every run.
#include <algorithm>
#include <cmath>
#include <random>

#include "tape/error.hpp"
#include "tape/render.hpp"

namespace tape {
namespace {

std::uint8_t byte(double v) { return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L)); }

void uneven_light(Picture& p, double light) {
    for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) {
            double fx = static_cast<double>(x) / p.width, fy = static_cast<double>(y) / p.height;
            double shade =
                std::clamp(0.6 * fx + 0.25 * fy + 0.15 * std::sin(fx * 9 + fy * 4) * std::sin(fy * 7), 0.0, 1.0);
            std::uint8_t* px = p.at(x, y);
            for (int k = 0; k < p.channels; ++k) px[k] = byte(px[k] * (1 - light * shade));
        }
}

// Specks up to 1 mm across (a feed hole is 1.17 mm), mostly dark, some light.
void dust(Picture& p, int count, double dpi, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    const double px_mm = dpi / 25.4;
    for (int i = 0; i < count; ++i) {
        double cx = u(rng) * p.width, cy = u(rng) * p.height, r = (0.1 + 0.4 * u(rng)) * px_mm;
        double level = u(rng) < 0.75 ? 20 + 60 * u(rng) : 200 + 50 * u(rng), opacity = 0.7 + 0.3 * u(rng);
        for (int y = std::max(0, static_cast<int>(cy - r - 1));
             y <= std::min(p.height - 1, static_cast<int>(cy + r + 1)); ++y)
            for (int x = std::max(0, static_cast<int>(cx - r - 1));
                 x <= std::min(p.width - 1, static_cast<int>(cx + r + 1)); ++x) {
                double cover = std::clamp(r - std::hypot(x - cx, y - cy) + 0.5, 0.0, 1.0) * opacity;
                std::uint8_t* px = p.at(x, y);
                for (int k = 0; k < p.channels; ++k) px[k] = byte(px[k] + (level - px[k]) * cover);
            }
    }
}

// A Gaussian blur, rows then columns, over lines of floats (the picture's channels side by side).
void blur_lines(std::vector<float>& line, std::vector<float>& out, int length, int c,
                const std::vector<float>& kernel) {
    const int radius = static_cast<int>(kernel.size() / 2);
    for (int b = 0; b < length; ++b) {
        int lo = std::max(0, b - radius), hi = std::min(length - 1, b + radius);
        for (int k = 0; k < c; ++k) {
            float v = 0;
            // Taps past an end take the end pixel's value.
            for (int i = b - radius; i < lo; ++i)
                v += kernel[static_cast<std::size_t>(i - b + radius)] * line[static_cast<std::size_t>(k)];
            for (int i = lo; i <= hi; ++i)
                v += kernel[static_cast<std::size_t>(i - b + radius)] * line[static_cast<std::size_t>(i * c + k)];
            for (int i = hi + 1; i <= b + radius; ++i)
                v += kernel[static_cast<std::size_t>(i - b + radius)] *
                     line[static_cast<std::size_t>((length - 1) * c + k)];
            out[static_cast<std::size_t>(b * c + k)] = v;
        }
    }
}

void blur(Picture& p, double sigma) {
    const int radius = static_cast<int>(std::ceil(3 * sigma)), c = p.channels;
    std::vector<float> kernel(static_cast<std::size_t>(2 * radius + 1));
    float sum = 0;
    for (int i = -radius; i <= radius; ++i)
        sum += kernel[static_cast<std::size_t>(i + radius)] =
            static_cast<float>(std::exp(-i * i / (2 * sigma * sigma)));
    for (auto& k : kernel) k /= sum;
    std::vector<float> line, out;
    for (int y = 0; y < p.height; ++y) {
        line.assign(p.at(0, y), p.at(0, y) + p.width * c);
        out.resize(line.size());
        blur_lines(line, out, p.width, c, kernel);
        for (std::size_t i = 0; i < out.size(); ++i) p.at(0, y)[i] = byte(out[i]);
    }
    line.resize(static_cast<std::size_t>(p.height * c));
    out.resize(line.size());
    for (int x = 0; x < p.width; ++x) {
        for (int y = 0; y < p.height; ++y) std::copy_n(p.at(x, y), c, &line[static_cast<std::size_t>(y * c)]);
        blur_lines(line, out, p.height, c, kernel);
        for (int y = 0; y < p.height; ++y)
            for (int k = 0; k < c; ++k) p.at(x, y)[k] = byte(out[static_cast<std::size_t>(y * c + k)]);
    }
}

// Gaussian noise from pairs of uniform numbers (Box-Muller): the same for a seed on every machine.
void noise(Picture& p, double sigma, std::mt19937_64& rng) {
    constexpr double unit = 1.0 / 18446744073709551616.0;  // 2^-64
    for (std::size_t i = 0; i + 1 < p.pixels.size(); i += 2) {
        double u1 = (static_cast<double>(rng()) + 1) * unit, u2 = static_cast<double>(rng()) * unit;
        double r = sigma * std::sqrt(-2 * std::log(u1)), a = 2 * 3.141592653589793 * u2;
        p.pixels[i] = byte(p.pixels[i] + r * std::cos(a));
        p.pixels[i + 1] = byte(p.pixels[i + 1] + r * std::sin(a));
    }
}

}  // namespace

void apply_effects(Picture& p, const PictureEffects& e, double dpi) {
    if (!(e.light >= 0 && e.light <= 0.9) || e.dust < 0 || e.dust > 100000 || !(e.blur_px >= 0 && e.blur_px <= 50) ||
        !(e.noise >= 0 && e.noise <= 128) || e.jpeg_quality < 0 || e.jpeg_quality > 100 || !(dpi > 0))
        throw Error(Errc::usage, "picture effects out of range");
    std::mt19937_64 rng(e.seed);
    if (e.light > 0) uneven_light(p, e.light);
    if (e.dust > 0) dust(p, e.dust, dpi, rng);
    if (e.blur_px > 0) blur(p, e.blur_px);
    if (e.noise > 0) noise(p, e.noise, rng);
    if (e.jpeg_quality > 0) {
        auto bytes = encode_picture(p, "jpeg", e.jpeg_quality);
        p = decode_picture(bytes);
    }
}

}  // namespace tape
