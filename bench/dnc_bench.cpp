// tape dnc serving a shop: N machines on pseudo-terminals at once, each control asking for a program,
// taking it and punching one out, again and again for a stretch of simulated time; then SIGTERM in
// the middle of N punch-outs. The service is the real binary in a process of its own, so its CPU time
// is its own (getrusage of the child). Figures: characters lost or doubled, punch-outs filed, the
// worst line's pace against its configured rate, request to first frame, CPU per core, the time
// SIGTERM takes and the partial punch-outs kept as FAILED.
//
// Faster than real time: with scale k every rate is k times 960 characters a second (9600 baud), the
// controls punch at the same k-fold pace and think k times less, and the service's receive time-out
// is k times shorter; the simulated time is the real time times k. CPU is measured at scale 1 only
// (real 9600 baud), where it means what the issue asks.
#include <benchmark/benchmark.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <thread>

#include "pty_util.hpp"
#include "spawn_util.hpp"
#include "tape/feed.hpp"
#include "tape/input.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

constexpr double line_cps = 960;  // 9600 baud, 10 bits a character
constexpr std::size_t leader = 20;

std::string program(const std::string& number, int blocks, int salt) {
    std::string text = "%\n" + number + " (BENCH)\n";
    for (int i = 1; i <= blocks; ++i)
        text += "N" + std::to_string(i * 10) + " G01 X" + std::to_string(i + salt) + ".5 Y-" + std::to_string(i) +
                ". F" + std::to_string(100 + salt) + "\n";
    return text + "M30\n%\n";
}

// What the service sends for text, as it encodes it (the same library call, the config's settings).
std::vector<tape::Frame> sent_frames(const std::string& text) {
    tape::InputOptions io;
    io.kind = tape::InputKind::text;
    tape::Input input(std::make_unique<tape::MemorySource>(
                          std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size())),
                      "bench", io);
    tape::FeedOptions o;
    o.encode.leader = o.encode.trailer = leader;
    o.percent = true;
    return tape::frames_to_send(input, o);
}

std::vector<std::uint8_t> iso(std::string_view text) {
    static const tape::FrameCode code = tape::FrameCode::iso();
    std::vector<std::uint8_t> out;
    for (char c : text) out.push_back(*code.frame_for(static_cast<unsigned char>(c)));
    return out;
}

struct Figures {
    std::mutex mutex;
    std::uint64_t requests = 0, frames = 0, lost_or_doubled = 0, punch_outs = 0;
    std::vector<double> pace_errors, latencies;                // one per transfer
    std::vector<std::pair<std::string, std::string>> punched;  // file stem, text
    std::vector<std::string> partial;                          // what was punched when SIGTERM came
};

class Shop {
public:
    Shop(int machines, double scale, int burst) : scale_(scale), rate_(line_cps * scale), burst_(burst) {
        for (auto sub : {"programs", "received", "run"}) std::filesystem::create_directories(dir_ + "/" + sub);
        std::filesystem::permissions(dir_ + "/run",
                                     std::filesystem::perms::owner_all);  // tape dnc refuses one open to others
        for (int m = 0; m < machines; ++m) {
            lines_.push_back(std::make_unique<Pty>());
            std::string number = "O" + std::to_string(1001 + m);
            texts_.push_back(program(number, 120, m));
            std::ofstream(dir_ + "/programs/" + number + ".nc") << texts_.back();
            expected_.push_back(sent_frames(texts_.back()));
        }
        write_config();
    }
    ~Shop() {
        if (!std::getenv("TAPE_DNC_BENCH_KEEP")) std::filesystem::remove_all(dir_);  // kept to look into, when asked
    }
    bool ok() const { return lines_.front()->ok(); }

    void run(double simulated_seconds, benchmark::State& state) {
        pid_t pid = spawn_to_files(TAPE_BINARY, {"dnc", "--config", dir_ + "/dnc.toml"}, "", dir_ + "/log");
        std::this_thread::sleep_for(1s);
        auto end = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(simulated_seconds / scale_));
        std::atomic<int> partial_ready{0};
        std::vector<std::thread> controls;
        for (std::size_t m = 0; m < lines_.size(); ++m)
            controls.emplace_back([this, m, end, &partial_ready] { control(m, end, partial_ready); });
        while (partial_ready < static_cast<int>(lines_.size())) std::this_thread::sleep_for(10ms);
        std::this_thread::sleep_for(300ms);  // the partial punch-outs are on the service's side
        auto asked = Clock::now();
        ::kill(pid, SIGTERM);
        int status = 0;
        rusage usage{};
        ::wait4(pid, &status, 0, &usage);
        double sigterm = std::chrono::duration<double>(Clock::now() - asked).count();
        for (auto& t : controls) t.join();
        report(state, usage, sigterm, simulated_seconds);
    }

private:
    std::string dir_ = std::filesystem::temp_directory_path() / ("tape-dnc-bench-" + std::to_string(::getpid()));
    double scale_, rate_;
    int burst_;
    std::vector<std::unique_ptr<Pty>> lines_;
    std::vector<std::string> texts_;
    std::vector<std::vector<tape::Frame>> expected_;
    Figures f_;
    Clock::time_point started_ = Clock::now();

    void write_config() const {
        std::ofstream out(dir_ + "/dnc.toml");
        out << "[library]\nprograms = \"" << dir_ << "/programs\"\nreceived = \"" << dir_ << "/received\"\n"
            << "[service]\nruntime_directory = \"" << dir_ << "/run\"\n";
        for (std::size_t m = 0; m < lines_.size(); ++m)
            out << "[[machine]]\nname = \"m" << m << "\"\ndevice = \"" << lines_[m]->device("baud=9600&flow=xonxoff")
                << "\"\nrate = " << rate_ << "\nleader = " << leader << "\ntrailer = " << leader
                << "\nreceive_timeout = " << 5 / scale_ << "\nburst = " << burst_ << "\n";
    }

    void paced_write(const Pty& pty, const std::vector<std::uint8_t>& bytes) const {
        auto next = Clock::now();
        for (std::size_t at = 0; at < bytes.size(); at += 8) {
            std::this_thread::sleep_until(next);
            std::size_t n = std::min<std::size_t>(8, bytes.size() - at);
            if (::write(pty.master, bytes.data() + at, n) != static_cast<ssize_t>(n)) return;
            next += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(n / rate_));
        }
    }

    void request(std::size_t m) {
        const Pty& pty = *lines_[m];
        auto ask = iso("%\n(PRG=O" + std::to_string(1001 + m) + ")\n%\n");
        const auto& want = expected_[m];
        if (::write(pty.master, ask.data(), ask.size()) != static_cast<ssize_t>(ask.size())) return;
        auto asked = Clock::now(), first = asked, last = asked;
        std::vector<std::uint8_t> got;
        std::size_t first_chunk = 0;
        auto limit = asked + std::chrono::duration<double>(2 * want.size() / rate_ + 5);
        while (got.size() < want.size() && Clock::now() < limit) {
            if (pty.receive(got, 100ms) == 0) continue;
            last = Clock::now();
            if (!first_chunk) first = last, first_chunk = got.size();
        }
        pty.receive_until_quiet(got, 50ms, 1s);  // anything more would be doubled
        std::uint64_t wrong = got.size() > want.size() ? got.size() - want.size() : want.size() - got.size();
        for (std::size_t i = 0; i < std::min(got.size(), want.size()); ++i) wrong += got[i] != want[i];
        double seconds = std::chrono::duration<double>(last - first).count();
        double pace = seconds > 0 ? (got.size() - first_chunk) / seconds : 0;
        std::lock_guard lock(f_.mutex);
        ++f_.requests;
        f_.frames += got.size();
        f_.lost_or_doubled += wrong;
        f_.latencies.push_back(std::chrono::duration<double>(first - asked).count());
        if (got.size() > 200) f_.pace_errors.push_back(std::abs(pace / rate_ - 1));
    }

    void control(std::size_t m, Clock::time_point end, std::atomic<int>& partial_ready) {
        std::uint32_t random = static_cast<std::uint32_t>(m) * 2654435761u + 1;
        auto think = [&] {
            random = random * 1664525u + 1013904223u;
            std::this_thread::sleep_for(std::chrono::duration<double>((0.5 + (random >> 8) % 1500 / 1000.0) / scale_));
        };
        for (int seq = 0; Clock::now() < end; ++seq) {
            request(m);
            think();
            std::string stem = "O" + std::to_string(100000 + m * 1000 + seq);
            std::string text = program(stem, 60, seq);
            paced_write(*lines_[m], iso(text));
            {
                std::lock_guard lock(f_.mutex);
                ++f_.punch_outs;
                f_.punched.emplace_back(stem, text);
            }
            think();
        }
        std::string text = program("O" + std::to_string(900000 + m), 40, 0);
        std::string half = text.substr(0, text.size() / 2);
        paced_write(*lines_[m], iso(half));
        {
            std::lock_guard lock(f_.mutex);
            f_.partial.push_back(half);
        }
        ++partial_ready;
    }

    void report(benchmark::State& state, const rusage& usage, double sigterm, double simulated) {
        std::uint64_t filed = 0, failed_kept = 0;
        for (const auto& [stem, text] : f_.punched) {
            std::ifstream in(dir_ + "/received/" + stem + ".nc", std::ios::binary);
            std::string got{std::istreambuf_iterator<char>(in), {}};
            filed += got == text;
        }
        std::multiset<std::string> partial(f_.partial.begin(), f_.partial.end());
        for (const auto& e : std::filesystem::directory_iterator(dir_ + "/received")) {
            if (!e.path().filename().string().starts_with("FAILED-")) continue;
            std::ifstream in(e.path(), std::ios::binary);
            auto at = partial.find(std::string{std::istreambuf_iterator<char>(in), {}});
            if (at != partial.end()) partial.erase(at), ++failed_kept;
        }
        double cpu =
            usage.ru_utime.tv_sec + usage.ru_utime.tv_usec / 1e6 + usage.ru_stime.tv_sec + usage.ru_stime.tv_usec / 1e6;
        double wall = std::chrono::duration<double>(Clock::now() - started_).count();
        state.counters["machines"] = static_cast<double>(lines_.size());
        state.counters["simulated_s"] = simulated;
        state.counters["requests"] = static_cast<double>(f_.requests);
        state.counters["frames_sent"] = static_cast<double>(f_.frames);
        state.counters["lost_or_doubled"] = static_cast<double>(f_.lost_or_doubled);
        state.counters["punch_outs"] = static_cast<double>(f_.punch_outs);
        state.counters["punch_outs_filed"] = static_cast<double>(filed);
        // The worst, the 99th percentile and the share within the target: a control thread of this
        // benchmark starved by other work on the machine shows as one slow transfer.
        auto share = [](const std::vector<double>& v, double limit) {
            return v.empty() ? 0 : 100.0 * std::count_if(v.begin(), v.end(), [&](double x) {
                                       return x <= limit;
                                   }) / static_cast<double>(v.size());
        };
        auto p99 = [](std::vector<double> v) {
            std::sort(v.begin(), v.end());
            return v.empty() ? 0 : v[v.size() * 99 / 100];
        };
        auto most = [](const std::vector<double>& v) { return v.empty() ? 0 : *std::max_element(v.begin(), v.end()); };
        state.counters["pace_worst_err_pct"] = 100 * most(f_.pace_errors);
        state.counters["pace_p99_err_pct"] = 100 * p99(f_.pace_errors);
        state.counters["pace_within_1pct_share"] = share(f_.pace_errors, 0.01);
        state.counters["first_frame_max_ms"] = 1000 * most(f_.latencies);
        state.counters["first_frame_p99_ms"] = 1000 * p99(f_.latencies);
        state.counters["first_frame_within_100ms_share"] = share(f_.latencies, 0.1);
        state.counters["cpu_s"] = cpu;
        state.counters["cpu_pct_of_core"] = 100 * cpu / wall;
        state.counters["sigterm_s"] = sigterm;
        state.counters["failed_kept"] = static_cast<double>(failed_kept);
        std::ifstream log(dir_ + "/log");
        std::string line;
        std::uint64_t errors = 0;
        while (std::getline(log, line)) errors += line.starts_with("<3>");
        state.counters["log_errors"] = static_cast<double>(errors);
    }
};

// Args: machines, simulated seconds, time scale, burst (frames a line is sent at one wake-up).
void BM_DncShop(benchmark::State& state) {
    for (auto _ : state) {
        Shop shop(static_cast<int>(state.range(0)), static_cast<double>(state.range(2)),
                  static_cast<int>(state.range(3)));
        if (!shop.ok()) {
            state.SkipWithError("no pseudo-terminal here");
            return;
        }
        shop.run(static_cast<double>(state.range(1)), state);
    }
}
BENCHMARK(BM_DncShop)
    ->Args({4, 30, 1, 16})
    ->Args({32, 60, 1, 16})
    ->Args({32, 60, 1, 32})
    ->Args({32, 600, 4, 16})
    ->Args({32, 600, 1, 16})
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
