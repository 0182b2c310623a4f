// The whole pipeline, end to end: the built `tape` binary run on generated files beside `cat` of the
// same files in the same run, interleaved, so that the ratios hold on a loaded machine too.
//   DecodeVsCat, EncodeVsCat   128 MiB tape / text to /dev/null: median times and tape/cat ratio
//   PeakRss/<command>/<MiB>    peak resident memory of one run (getrusage of the child)
//   InfoSampleVsCat            1000 runs of `tape info` on the bundled 16К20Ф3С5 tape, per run
//   VersionCpu                 `tape --version`, any command's fixed cost: least CPU time and peak memory
//   Lint200kBlocks             `tape lint` of a clean 200 000-block program: least CPU time
//   (decode and encode also give the least CPU time of each against cat's: cpu_ratio, the guard's figure)
// Run: build/bin/pipeline_bench (bench/run.sh prints the figures as a table); TAPE_BENCH_TAPE=PATH
// runs another tape binary instead of the one built beside it. The files go to a
// temporary folder under TMPDIR (about 2.3 GiB) and are removed at the end.
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "tape/encode.hpp"

#ifndef TAPE_BINARY
#error "TAPE_BINARY: the path of the built tape, set by bench/CMakeLists.txt"
#endif
#ifndef TAPE_SAMPLE_TAPE
#error "TAPE_SAMPLE_TAPE: the bundled 16К20Ф3С5 tape, set by bench/CMakeLists.txt"
#endif

namespace {

namespace fs = std::filesystem;
constexpr std::uint64_t MiB = 1 << 20;

// ---- files --------------------------------------------------------------------------------------

// A part program as a machinist writes one: numbered blocks of G, X, Z and F words, now and then S and
// M words or a comment, LF at the end of each; the numbers vary, so the text is not one block repeated.
class ProgramText {
public:
    // Appends blocks to out until it holds at least `bytes` bytes.
    void fill(std::string& out, std::size_t bytes) {
        char block[128];
        while (out.size() < bytes) {
            ++n_;
            int len = std::snprintf(block, sizeof block, "N%04llu G0%llu X%c%08llu Z%c%07llu F%llu",
                                    static_cast<unsigned long long>(n_ % 10000), next(4), next(2) ? '+' : '-',
                                    next(100000000), next(2) ? '+' : '-', next(10000000), 10 + next(20000));
            out.append(block, static_cast<std::size_t>(len));
            if (n_ % 7 == 0) {
                len = std::snprintf(block, sizeof block, " S%llu M0%llu", 100 + next(2900), 3 + next(7));
                out.append(block, static_cast<std::size_t>(len));
            }
            if (n_ % 13 == 0) out += " (FINISH PASS)";
            out += '\n';
        }
    }

private:
    unsigned long long next(std::uint64_t below) {
        state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;  // Knuth's MMIX LCG
        return static_cast<unsigned long long>((state_ >> 33) % below);
    }
    std::uint64_t state_ = 1, n_ = 0;
};

void write_all(int fd, const void* data, std::size_t n, const std::string& path) {
    auto p = static_cast<const char*>(data);
    while (n > 0) {
        ssize_t w = ::write(fd, p, n);
        if (w < 0) throw std::runtime_error("cannot write " + path);
        p += w;
        n -= static_cast<std::size_t>(w);
    }
}

// The text (`%`, blocks, `M02`, `%`) and its ISO tape with the default leader and trailer, made in one
// pass a MiB at a time through the library's Encoder.
void make_program(const std::string& text_path, const std::string& tape_path, std::uint64_t bytes) {
    int text_fd = ::open(text_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    int tape_fd = ::open(tape_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (text_fd < 0 || tape_fd < 0) throw std::runtime_error("cannot create " + text_path);
    ProgramText program;
    tape::Encoder encoder(tape::EncodeOptions{});
    std::vector<tape::Frame> frames;
    std::string piece = "%\n";
    std::uint64_t written = 0;
    auto put = [&] {
        write_all(text_fd, piece.data(), piece.size(), text_path);
        encoder.feed(piece, frames);
        write_all(tape_fd, frames.data(), frames.size(), tape_path);
        written += piece.size();
        piece.clear();
        frames.clear();
    };
    while (written + MiB < bytes) {
        program.fill(piece, MiB);
        put();
    }
    program.fill(piece, bytes - written > 16 ? bytes - written - 16 : 0);
    piece += "N9999 M02\n%\n";
    put();
    encoder.finish(frames);
    write_all(tape_fd, frames.data(), frames.size(), tape_path);
    ::close(text_fd);
    ::close(tape_fd);
}

// The generated files, made when first asked for, in a folder removed at exit.
class Workdir {
public:
    static Workdir& get() {
        static Workdir w;
        return w;
    }
    Workdir(const Workdir&) = delete;
    Workdir& operator=(const Workdir&) = delete;
    ~Workdir() {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    // A file of that name in the folder.
    std::string path(const std::string& name) const { return dir_ + "/" + name; }

    // "<dir>/program-<MiB>.txt" or ".ptp".
    std::string file(std::uint64_t mib, bool tape) {
        std::string base = dir_ + "/program-" + std::to_string(mib);
        if (!made_[mib]) {
            make_program(base + ".txt", base + ".ptp", mib * MiB);
            made_[mib] = true;
        }
        return base + (tape ? ".ptp" : ".txt");
    }

private:
    Workdir() {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/tape-pipeline-bench.XXXXXX";
        if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot create a folder in TMPDIR");
        dir_ = pattern;
    }
    std::string dir_;
    std::map<std::uint64_t, bool> made_;
};

// ---- running commands ---------------------------------------------------------------------------

// The tape binary under test: the one built beside this benchmark, or TAPE_BENCH_TAPE (to compare builds).
const std::string& tape_binary() {
    static const std::string path = [] {
        const char* other = std::getenv("TAPE_BENCH_TAPE");
        return std::string(other && *other ? other : TAPE_BINARY);
    }();
    return path;
}

struct Outcome {
    double seconds = 0;
    double cpu_seconds = 0;  // user + system of the child
    long max_rss_kib = 0;    // ru_maxrss of the child
    int exit_status = -1;    // 128 + signal when killed
};

// Runs argv (looked up in PATH) with stdin, stdout and stderr on /dev/null, under an address-space limit
// (so that a command that loads a 1 GiB tape whole fails instead of filling the machine), and waits.
Outcome run(const std::vector<std::string>& args, rlim_t address_space = 0) {
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    auto start = std::chrono::steady_clock::now();
    pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("cannot fork");
    if (pid == 0) {  // only async-signal-safe calls from here to exec
        int null = ::open("/dev/null", O_RDWR);
        if (null < 0) ::_exit(126);
        ::dup2(null, 0);
        ::dup2(null, 1);
        ::dup2(null, 2);
        if (address_space) {
            struct rlimit limit = {address_space, address_space};
            ::setrlimit(RLIMIT_AS, &limit);
        }
        ::execvp(argv[0], argv.data());
        ::_exit(127);
    }
    int status = 0;
    struct rusage usage {};
    while (::wait4(pid, &status, 0, &usage) < 0)
        if (errno != EINTR) throw std::runtime_error("wait4 failed");
    Outcome o;
    o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    o.max_rss_kib = usage.ru_maxrss;
    auto seconds_of = [](const timeval& t) { return static_cast<double>(t.tv_sec) + t.tv_usec / 1e6; };
    o.cpu_seconds = seconds_of(usage.ru_utime) + seconds_of(usage.ru_stime);
    o.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return o;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    std::size_t n = v.size();
    return n == 0 ? 0 : n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

// `tape <command> FILE` beside `cat FILE`, alternately, both to /dev/null. The benchmark's time is
// tape's; the counters are the medians and their ratio (the figure of the issue: at most 2).
void versus_cat(benchmark::State& state, const char* command, bool tape_input) {
    std::string path = Workdir::get().file(128, tape_input);
    run({"cat", path});  // the file is in the page cache for both from here on
    std::vector<double> tape_s, cat_s;
    double tape_cpu = 1e9, cat_cpu = 1e9;  // the least of the runs: what a loaded machine adds counts least
    for (auto _ : state) {
        Outcome c = run({"cat", path});
        Outcome t = run({tape_binary(), command, path});
        tape_cpu = std::min(tape_cpu, t.cpu_seconds);
        cat_cpu = std::min(cat_cpu, c.cpu_seconds);
        if (t.exit_status != 0 || c.exit_status != 0) {
            state.SkipWithError(
                ("tape " + std::string(command) + " failed, exit " + std::to_string(t.exit_status)).c_str());
            break;
        }
        state.SetIterationTime(t.seconds);
        tape_s.push_back(t.seconds);
        cat_s.push_back(c.seconds);
    }
    double t = median(tape_s), c = median(cat_s);
    state.counters["tape_ms"] = t * 1e3;
    state.counters["cat_ms"] = c * 1e3;
    state.counters["ratio"] = c > 0 ? t / c : 0;
    state.counters["cpu_ms"] = tape_cpu * 1e3;
    state.counters["cat_cpu_ms"] = cat_cpu * 1e3;
    state.counters["cpu_ratio"] = cat_cpu > 0 ? tape_cpu / cat_cpu : 0;
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * 128 * MiB));
}

void BM_DecodeVsCat(benchmark::State& state) { versus_cat(state, "decode", true); }
void BM_EncodeVsCat(benchmark::State& state) { versus_cat(state, "encode", false); }

// Peak resident memory of `tape <command>` on a tape (or, for encode, a text) of range(1) MiB.
const char* const rss_commands[] = {"decode", "encode", "info", "blocks"};

void BM_PeakRss(benchmark::State& state) {
    const char* command = rss_commands[state.range(0)];
    auto mib = static_cast<std::uint64_t>(state.range(1));
    std::string path = Workdir::get().file(mib, std::string(command) != "encode");
    state.SetLabel(command);
    Outcome o;
    for (auto _ : state) {
        o = run({tape_binary(), command, path}, rlim_t{8} << 30);
        state.SetIterationTime(o.seconds);
    }
    state.counters["rss_MiB"] = static_cast<double>(o.max_rss_kib) / 1024;
    state.counters["exit"] = o.exit_status;
    state.counters["MiB"] = static_cast<double>(mib);
}

// Start-up and a small tape: 1000 runs each of `tape info SAMPLE` and `cat SAMPLE`, in alternating
// batches of 100; the counters are microseconds a run and their ratio.
void BM_InfoSampleVsCat(benchmark::State& state) {
    constexpr int runs = 1000, batch = 100;
    double tape_s = 0, cat_s = 0;
    for (auto _ : state) {
        for (int b = 0; b < runs / batch; ++b) {
            auto start = std::chrono::steady_clock::now();
            for (int i = 0; i < batch; ++i) run({"cat", TAPE_SAMPLE_TAPE});
            auto middle = std::chrono::steady_clock::now();
            for (int i = 0; i < batch; ++i)
                if (run({tape_binary(), "info", TAPE_SAMPLE_TAPE}).exit_status != 0)
                    state.SkipWithError("tape info failed");
            auto end = std::chrono::steady_clock::now();
            cat_s += std::chrono::duration<double>(middle - start).count();
            tape_s += std::chrono::duration<double>(end - middle).count();
        }
    }
    double n = static_cast<double>(state.iterations()) * runs;
    state.counters["tape_us"] = tape_s / n * 1e6;
    state.counters["cat_us"] = cat_s / n * 1e6;
    state.counters["ratio"] = cat_s > 0 ? tape_s / cat_s : 0;
}

// Any command's fixed cost: the least CPU time and the largest peak of `tape --version` runs.
void BM_VersionCpu(benchmark::State& state) {
    double cpu = 1e9;
    long rss = 0;
    for (auto _ : state) {
        Outcome o = run({tape_binary(), "--version"});
        if (o.exit_status != 0) state.SkipWithError("tape --version failed");
        state.SetIterationTime(o.seconds);
        cpu = std::min(cpu, o.cpu_seconds);
        rss = std::max(rss, o.max_rss_kib);
    }
    state.counters["cpu_ms"] = cpu * 1e3;
    state.counters["rss_MiB"] = static_cast<double>(rss) / 1024;
}

// A clean mill program of `blocks` blocks, numbered in order (lint finds nothing to say).
std::string make_lint_program(std::size_t blocks) {
    std::string path = Workdir::get().path("lint-" + std::to_string(blocks) + ".nc");
    if (fs::exists(path)) return path;
    std::string text = "%\nO1000\nN1 G90 G54 G00 X0 Y0 Z50.\n";
    std::uint64_t state = 3;
    auto next = [&](unsigned below) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<unsigned>((state >> 33) % below);
    };
    char block[96];
    for (std::size_t n = 2; n <= blocks; ++n) {
        int len = std::snprintf(block, sizeof block, "N%zu G01 X%u.%03u Y%u.%03u F%u\n", n, next(500), next(1000),
                                next(300), next(1000), 100 + next(900));
        text.append(block, static_cast<std::size_t>(len));
    }
    text += "M30\n%\n";
    int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) throw std::runtime_error("cannot create " + path);
    write_all(fd, text.data(), text.size(), path);
    ::close(fd);
    return path;
}

// `tape lint` of 200 000 blocks (6.7 MB): the least CPU time (target 0.1 s), and cat's of the same file.
void BM_Lint200kBlocks(benchmark::State& state) {
    std::string path = make_lint_program(200000);
    double cpu = 1e9, cat_cpu = 1e9;
    for (auto _ : state) {
        Outcome c = run({"cat", path});
        Outcome t = run({tape_binary(), "lint", path});
        if (t.exit_status != 0) state.SkipWithError("tape lint found something in a clean program");
        state.SetIterationTime(t.seconds);
        cpu = std::min(cpu, t.cpu_seconds);
        cat_cpu = std::min(cat_cpu, c.cpu_seconds);
    }
    state.counters["cpu_ms"] = cpu * 1e3;
    state.counters["cat_cpu_ms"] = cat_cpu * 1e3;
}

}  // namespace

BENCHMARK(BM_VersionCpu)->Iterations(20)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Lint200kBlocks)->Iterations(7)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeVsCat)->Iterations(15)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EncodeVsCat)->Iterations(15)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PeakRss)
    ->ArgsProduct({{0, 1, 2, 3}, {1, 1024}})
    ->ArgNames({"command", "MiB"})
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_InfoSampleVsCat)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
