// tape scan against the figures of its issue, on tapes drawn by tape render as scanners and cameras show
// them (random frames: every hole pattern, no text to lean on):
//   Accuracy300  300 dpi, skew up to 3°, bow, stains, dust, blur, noise, uneven light, JPEG: >= 99.99 % right, 0 silently wrong
//   Accuracy200  the same at 200 dpi: >= 99.9 %
//   Phone        a flat photo at 6 px a code hole: >= 99 %, the rest doubtful
//   Faces        either face, either direction: the same read
//   Segments     30 overlapping segments, shuffled and turned: one exact read
//   Speed        frames a CPU second at 300 dpi (>= 394: a metre of tape)
//   Memory       the CLI's peak memory over the decoded picture (<= 3)
// Run: build/bin/scan_bench (TAPE_SCAN_BENCH_PICTURES=N: pictures per accuracy figure, default 25).
#include <benchmark/benchmark.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <filesystem>
#include <random>

#include "scan_util.hpp"
#include "tape/encode.hpp"

extern char** environ;

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
    tape::RasterOptions ro{.dpi = w.dpi, .mirror = u(rng) < 0.5, .skew_deg = -3 + 6 * u(rng), .bow_mm = 2 * u(rng),
                           .stains = 4, .seed = rng()};
    if (w.phone) ro.paper = 0xE8B060, ro.backing = 0xD0D0D0;  // orange paper on a light mat, holes light
    tape::Picture p = tape::render_picture(t, ro);
    tape::apply_effects(p, tape::PictureEffects{.light = 0.3 + 0.2 * u(rng), .dust = w.phone ? 10 : 40,
                                                .blur_px = w.blur * (0.8 + 0.4 * u(rng)), .noise = 4 + 4 * u(rng),
                                                .jpeg_quality = static_cast<int>(75 + 15 * u(rng)), .seed = rng()},
                        w.dpi);
    std::string path = temp_dir() + "/worn" + std::to_string(k) + ".png";
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

// Peak memory of `tape scan PICTURE` as a process, less that of a run on a tiny picture.
long peak_kib(const std::string& picture) {
    std::string out = temp_dir() + "/read.ptp";
    const char* argv[] = {TAPE_BINARY, "-q", "scan", picture.c_str(), "-o", out.c_str(), "--force", nullptr};
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    if (posix_spawn(&pid, TAPE_BINARY, &fa, nullptr, const_cast<char**>(argv), environ) != 0) return -1;
    posix_spawn_file_actions_destroy(&fa);
    int status = 0;
    rusage ru{};
    wait4(pid, &status, 0, &ru);
    return ru.ru_maxrss;
}

void BM_MemoryOverDecodedPicture(benchmark::State& state) {
    std::mt19937_64 rng(19);
    auto small = random_tape(rng, 60);
    std::string tiny = temp_dir() + "/tiny.png";
    write_picture(tape::render_picture(small, tape::RasterOptions{.dpi = 100}), tiny);
    double ratio = 0, decoded_mb = 0;
    for (auto _ : state) {
        auto bytes = tape::encode_picture(tape::Picture{1, 1, 3, {0, 0, 0}}, "png");  // warm the codec
        benchmark::DoNotOptimize(bytes);
        std::filesystem::path p = speed_picture();
        std::ifstream in(p, std::ios::binary);
        std::vector<std::uint8_t> file{std::istreambuf_iterator<char>(in), {}};
        tape::Picture decoded = tape::decode_picture(file);
        decoded_mb = static_cast<double>(decoded.pixels.size()) / 1e6;
        long base = peak_kib(tiny), peak = peak_kib(p);
        ratio = static_cast<double>(peak - base) * 1024 / static_cast<double>(decoded.pixels.size());
    }
    state.counters["decoded_MB"] = decoded_mb;
    state.counters["peak_over_decoded"] = ratio;
}
BENCHMARK(BM_MemoryOverDecodedPicture)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
