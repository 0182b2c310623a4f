// tape scan against the figures of its issue, on tapes drawn by tape render as scanners and cameras show
// them (random frames: every hole pattern, no text to lean on):
// - Accuracy300: 300 dpi, skew up to 3 degrees, bow, stains, dust, blur, noise, uneven light, JPEG:
//   >= 99.99 % right, 0 silently wrong;
// - Accuracy200: the same at 200 dpi: >= 99.9 %;
// - Phone6pxPerHole: a flat photo at 6 px a code hole: >= 99 %, the rest doubtful;
// - FacesAndDirections: either face, either direction: the same read;
// - ThirtySegmentsShuffled: 30 overlapping segments, shuffled and turned: one exact read;
// - Speed300Dpi: frames a CPU second at 300 dpi (>= 394: a metre of tape);
// - MemoryOverDecodedPicture: the peak memory a scan adds over the decoded picture (<= 3).
// Run: build/bin/scan_bench (TAPE_SCAN_BENCH_PICTURES=N: pictures per accuracy figure, default 25;
// TAPE_SCAN_BENCH_VERBOSE=1: each picture not read right is named, and kept in the bench's folder).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>

#include "scan_util.hpp"
#include "tape/encode.hpp"

namespace {

constexpr std::size_t frames_a_picture = 400;  // a metre of tape

std::string temp_dir() {
    static std::string dir = [] {
        char tmpl[] = "/tmp/tape-scan-bench-XXXXXX";
        return std::string(::mkdtemp(tmpl));
    }();
    return dir;
}

int pictures() {
    const char* n = std::getenv("TAPE_SCAN_BENCH_PICTURES");
    return n ? std::max(1, std::atoi(n)) : 25;
}

// Random frames between a leader of 30 and a trailer of 10 (the longer blank run tells the start).
std::vector<tape::Frame> random_tape(std::mt19937_64& rng, std::size_t frames) {
    std::vector<tape::Frame> t(30, tape::blank_frame);
    for (std::size_t i = 0; i < frames - 40; ++i) t.push_back(static_cast<tape::Frame>(rng() % 255 + 1));
    t.insert(t.end(), 10, tape::blank_frame);
    return t;
}

struct Worn {
    double dpi, blur;
    bool phone = false;
};

// A picture of t as a flatbed (or, phone, a camera) shows it, written as JPEG.
std::string worn_picture(const std::vector<tape::Frame>& t, const Worn& w, std::mt19937_64& rng, int k) {
    std::uniform_real_distribution<double> u(0, 1);
    tape::RasterOptions ro{.dpi = w.dpi,
                           .mirror = u(rng) < 0.5,
                           .skew_deg = -3 + 6 * u(rng),
                           .bow_mm = 2 * u(rng),
                           .stains = 4,
                           .seed = rng()};
    if (w.phone) ro.paper = 0xE8B060, ro.backing = 0xD0D0D0;  // orange paper on a light mat, holes light
    tape::Picture p = tape::render_picture(t, ro);
    tape::apply_effects(p,
                        tape::PictureEffects{.light = 0.3 + 0.2 * u(rng),
                                             .dust = w.phone ? 10 : 40,
                                             .blur_px = w.blur * (0.8 + 0.4 * u(rng)),
                                             .noise = 4 + 4 * u(rng),
                                             .jpeg_quality = static_cast<int>(75 + 15 * u(rng)),
                                             .seed = rng()},
                        w.dpi);
    std::string path =
        temp_dir() + "/worn" + std::to_string(static_cast<int>(w.dpi)) + "-" + std::to_string(k) + ".png";
    if (u(rng) < 0.5) p = half_turn(p);
    write_picture(p, path);
    return path;
}

void accuracy(benchmark::State& state, Worn w) {
    ReadScore total;
    std::uint64_t refused = 0;
    for (auto _ : state) {
        std::mt19937_64 rng(static_cast<std::uint64_t>(w.dpi * 1000));
        for (int k = 0; k < pictures(); ++k) {
            auto t = random_tape(rng, frames_a_picture);
            std::vector<std::string> paths{worn_picture(t, w, rng, k)};
            try {
                ReadScore s = score_read(t, tape::scan_images(paths));
                if (std::getenv("TAPE_SCAN_BENCH_VERBOSE") && s.right < s.frames) {  // kept to look at, with its tape
                    std::ofstream(paths[0] + ".ptp", std::ios::binary)
                        .write(reinterpret_cast<const char*>(t.data()), static_cast<std::streamsize>(t.size()));
                    std::fprintf(stderr, "%s: %llu of %llu right, %llu silently wrong\n", paths[0].c_str(),
                                 static_cast<unsigned long long>(s.right), static_cast<unsigned long long>(s.frames),
                                 static_cast<unsigned long long>(s.silently_wrong));
                }
                total.frames += s.frames, total.right += s.right, total.doubtful += s.doubtful;
                total.flagged_wrong += s.flagged_wrong, total.silently_wrong += s.silently_wrong;
            } catch (const tape::Error&) {
                ++refused, total.frames += t.size();
            }
        }
    }
    state.counters["frames"] = static_cast<double>(total.frames);
    state.counters["right_pct"] = 100 * total.right_share();
    state.counters["silently_wrong"] = static_cast<double>(total.silently_wrong);
    state.counters["flagged_wrong"] = static_cast<double>(total.flagged_wrong);
    state.counters["doubtful"] = static_cast<double>(total.doubtful);
    state.counters["refused_pictures"] = static_cast<double>(refused);
}
BENCHMARK_CAPTURE(accuracy, Accuracy300, Worn{300, 1.2})->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(accuracy, Accuracy200, Worn{200, 0.9})->Iterations(1)->Unit(benchmark::kSecond);
// 6 px across a 1.83 mm code hole: 83 dpi.
BENCHMARK_CAPTURE(accuracy, Phone6pxPerHole, Worn{6 / 1.83 * 25.4, 0.8, true})->Iterations(1)->Unit(benchmark::kSecond);

void BM_FacesAndDirections(benchmark::State& state) {
    std::uint64_t differ = 0, reads = 0;
    for (auto _ : state) {
        std::mt19937_64 rng(11);
        auto t = random_tape(rng, frames_a_picture);
        for (bool mirror : {false, true})
            for (bool turned : {false, true}) {
                tape::Picture p = tape::render_picture(t, tape::RasterOptions{.mirror = mirror, .skew_deg = 2});
                std::vector<std::string> paths{temp_dir() + "/face.png"};
                write_picture(turned ? half_turn(p) : p, paths[0]);
                differ += tape::scan_images(paths).frames != t;
                ++reads;
            }
    }
    state.counters["reads"] = static_cast<double>(reads);
    state.counters["reads_unlike_the_tape"] = static_cast<double>(differ);
}
BENCHMARK(BM_FacesAndDirections)->Iterations(1)->Unit(benchmark::kSecond);

void BM_ThirtySegmentsShuffled(benchmark::State& state) {
    std::uint64_t exact = 0, gaps = 0, doubtful = 0;
    for (auto _ : state) {
        std::mt19937_64 rng(13);
        auto t = random_tape(rng, 1200);
        tape::Picture whole = tape::render_picture(t, tape::RasterOptions{.dpi = 200});
        const int n = 30, width = whole.width / 12, step = (whole.width - width) / (n - 1);
        std::vector<std::string> paths;
        for (int k = 0; k < n; ++k) {
            tape::Picture seg = columns(whole, k * step, k == n - 1 ? whole.width : k * step + width);
            paths.push_back(temp_dir() + "/seg" + std::to_string(k) + ".png");
            write_picture(rng() % 2 ? half_turn(seg) : seg, paths.back());
        }
        std::shuffle(paths.begin(), paths.end(), rng);
        auto r = tape::scan_images(paths);
        exact += r.frames == t, gaps += r.gaps.size(), doubtful += r.doubts.runs.size();
    }
    state.counters["exact"] = static_cast<double>(exact);
    state.counters["gaps"] = static_cast<double>(gaps);
    state.counters["doubtful_runs"] = static_cast<double>(doubtful);
}
BENCHMARK(BM_ThirtySegmentsShuffled)->Iterations(1)->Unit(benchmark::kSecond);

const std::string& speed_picture() {
    static const std::string path = [] {
        std::mt19937_64 rng(17);
        auto t = random_tape(rng, 2 * frames_a_picture);
        return worn_picture(t, Worn{300, 1.2}, rng, 1000);
    }();
    return path;
}

// CPU time of the whole read (decoding the JPEG included); items are frames.
void BM_Speed300Dpi(benchmark::State& state) {
    std::vector<std::string> paths{speed_picture()};
    std::size_t frames = 0;
    for (auto _ : state) frames = tape::scan_images(paths).frames.size();
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * frames));
    state.counters["frames"] = static_cast<double>(frames);
}
BENCHMARK(BM_Speed300Dpi)->MeasureProcessCPUTime()->Unit(benchmark::kMillisecond);

// A line of /proc/self/status in KiB ("VmHWM:", "VmRSS:").
long status_kib(const std::string& key) {
    std::ifstream in("/proc/self/status");
    for (std::string line; std::getline(in, line);)
        if (line.rfind(key, 0) == 0) return std::atol(line.c_str() + key.size());
    return -1;
}

// The peak memory of one scan over the picture it decodes: the process's peak is reset (clear_refs 5)
// just before, and what the scan adds to the memory then in use is its own.
void BM_MemoryOverDecodedPicture(benchmark::State& state) {
    std::vector<std::string> paths{speed_picture()};
    std::size_t decoded = 0;
    {
        std::ifstream in(paths[0], std::ios::binary);
        std::vector<std::uint8_t> file{std::istreambuf_iterator<char>(in), {}};
        decoded = tape::decode_picture(file).pixels.size();
    }
    double ratio = 0;
    for (auto _ : state) {
        std::ofstream("/proc/self/clear_refs") << "5";
        long before = status_kib("VmRSS:");
        auto r = tape::scan_images(paths);
        benchmark::DoNotOptimize(r.frames.data());
        ratio = static_cast<double>(status_kib("VmHWM:") - before) * 1024 / static_cast<double>(decoded);
    }
    state.counters["decoded_MB"] = static_cast<double>(decoded) / 1e6;
    state.counters["peak_over_decoded"] = ratio;
}
BENCHMARK(BM_MemoryOverDecodedPicture)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
