// Restoration measured by the counting rules of issue 20: repair rates over data frames only; a frame
// left out or added in a run of equal frames in doubt when any copy is; a wrong inferred frame silent;
// every silent error classified, with the damage logs, as decidable (most reads had it right),
// undecidable (some did) or invisible (none did).
// Run: build/bin/restore_bench (Release: cmake -DCMAKE_BUILD_TYPE=Release, target restore_bench).
//   BM_OneRead<corpus>/guess:  1 read, single-hole flips in 0.5% of the data frames
//   BM_ManyReads<corpus>/N:    N reads (3 or 5), each with 1% of its frames damaged (flips, drops, doubles,
//                              bursts), every set of reads damaged by seeds of its own
//   BM_FiveReadsSpeed:         5 reads of 10^6 frames aligned, voted and repaired
// RESTORE_BENCH_MACHINE and RESTORE_BENCH_ONLY (below): with a machine's profile, and on some tapes only.
// Corpora: generated programs (some with mistakes of their own), the sample tapes, and real programs
// and DEC source tapes from ../shared/data/outside* (a note says what is left out where it is absent).
// RESTORE_BENCH_SCALE (default 1) multiplies the number of tapes and seeds; RESTORE_BENCH_SHOW=1 prints each
// silent error of the many-read runs with the tape, the output, the damage and the problems around it
// (RESTORE_BENCH_SHOW_START=1: and the output's first data frames), and each frame of one read not
// restored right; RESTORE_BENCH_SHOW=flagged also each wrong frame in doubt; RESTORE_BENCH_DUMP=PREFIX
// writes the first set with more than 1000 silent errors as PREFIXtape.ptp, PREFIXout.ptp and PREFIXreadN.ptp.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>

#include "restore_corpus.hpp"
#include "tape/damage.hpp"
#include "tape/machine.hpp"
#include "tape/restore.hpp"

namespace {

using bench::CorpusTape;

std::uint64_t scale() {
    const char* s = std::getenv("RESTORE_BENCH_SCALE");
    return s ? std::max<std::uint64_t>(1, std::strtoull(s, nullptr, 10)) : 1;
}

benchmark::Counter per_run(std::uint64_t n) {
    return benchmark::Counter(static_cast<double>(n), benchmark::Counter::kAvgIterations);
}

// RESTORE_BENCH_MACHINE=NAME: the machine profile NAME (tape machines) for the tapes whose file name starts
// with the profile's name (16k20f3s5: the 16К20Ф3С5 sample tape); RESTORE_BENCH_ONLY=PREFIX: only the
// tapes whose name starts so.
const tape::MachineProfile* bench_machine(const CorpusTape* t) {
    static const std::optional<tape::MachineProfile> machine = []() -> std::optional<tape::MachineProfile> {
        const char* name = std::getenv("RESTORE_BENCH_MACHINE");
        if (!name || !*name) return std::nullopt;
        return tape::load_machine(name);
    }();
    return machine && t && t->name.rfind(machine->name, 0) == 0 ? &*machine : nullptr;
}

std::vector<CorpusTape> only(std::vector<CorpusTape> tapes) {
    const char* prefix = std::getenv("RESTORE_BENCH_ONLY");
    if (prefix && *prefix) std::erase_if(tapes, [&](const CorpusTape& t) { return t.name.rfind(prefix, 0) != 0; });
    return tapes;
}

// RESTORE_BENCH_ODDS: RestoreOptions::run_odds, to weigh run lengths otherwise than by default.
tape::RestoreResult restore_reads(const std::vector<std::vector<tape::Frame>>& reads, bool guess = false,
                                  const CorpusTape* t = nullptr) {
    std::vector<std::span<const tape::Frame>> spans(reads.begin(), reads.end());
    tape::RestoreOptions o{.code = tape::FrameCode::iso(), .dialect = tape::Dialect::automatic};
    if ((o.machine = bench_machine(t))) o.dialect = o.machine->dialect;
    o.guess = guess;
    if (const char* odds = std::getenv("RESTORE_BENCH_ODDS")) o.run_odds = std::strtod(odds, nullptr);
    return tape::restore(spans, o);
}

// One read with single-hole flips in 0.5% of the data frames (leader and trailer as punched).
std::vector<tape::Frame> flipped_read(const CorpusTape& t, std::uint64_t seed) {
    auto data = tape::punched_part(t.frames);
    tape::DamageOptions o;
    o.seed = seed;
    o.flips = 0.005;
    auto damaged = tape::damage(data, o);
    std::vector<tape::Frame> read(t.frames.begin(), t.frames.begin() + (data.data() - t.frames.data()));
    read.insert(read.end(), damaged.begin(), damaged.end());
    read.insert(read.end(), data.data() + data.size(), t.frames.data() + t.frames.size());
    return read;
}

struct OneReadTally {
    std::uint64_t bad = 0, right = 0, code_bad = 0, code_right = 0, wrong_inferred = 0, inferred = 0;
    std::uint64_t guessed = 0, guessed_right = 0, unmarked = 0, nc_bad = 0, nc_right = 0;

    void add(const CorpusTape& t, std::uint64_t seed, bool guess) {
        auto read = flipped_read(t, seed);
        auto r = restore_reads({read}, guess, &t);
        std::map<std::uint64_t, tape::FrameStatus> status;
        // The tape's end no read reached is a problem placed at the last frame: it says nothing of how
        // that frame was repaired.
        for (const auto& p : r.problems)
            if (p.frame && p.status != tape::FrameStatus::missing) status[*p.frame] = p.status;
        for (std::size_t i = 0; i < t.frames.size() && i < r.frames.size(); ++i) {
            if (read[i] == t.frames[i]) continue;
            bool ok = r.frames[i] == t.frames[i];
            auto s = status.count(i + 1) ? status[i + 1] : tape::FrameStatus::clean;
            ++bad, right += ok;
            if (!ok && std::getenv("RESTORE_BENCH_SHOW")) show_one(t, read, r, i);
            if (t.nc) ++nc_bad, nc_right += ok;
            if (t.code[i]) ++code_bad, code_right += ok;
            inferred += s == tape::FrameStatus::inferred;
            wrong_inferred += !ok && (s == tape::FrameStatus::inferred || s == tape::FrameStatus::clean ||
                                      s == tape::FrameStatus::voted);
            guessed += s == tape::FrameStatus::guessed, guessed_right += ok && s == tape::FrameStatus::guessed;
            bool neither = guess && s != tape::FrameStatus::inferred && s != tape::FrameStatus::guessed;
            unmarked += neither;
            if (neither && std::getenv("RESTORE_BENCH_SHOW")) show_one(t, read, r, i);
        }
    }
    static char printable(char c) { return c >= 32 && c < 127 ? c : '?'; }
    // RESTORE_BENCH_SHOW: each damaged frame not restored right, with its block, status, reason and
    // candidates: "tape-name, frame, original, read, written, status, candidates, block, reason" (tab-separated).
    static void show_one(const CorpusTape& t, const std::vector<tape::Frame>& read, const tape::RestoreResult& r,
                         std::size_t i) {
        std::size_t a = i, b = i;
        while (a > 0 && (t.frames[a - 1] & 0x7F) != '\n' && i - a < 60) --a;
        while (b + 1 < t.frames.size() && (t.frames[b] & 0x7F) != '\n' && b - i < 60) ++b;
        std::string block;
        for (std::size_t k = a; k <= std::max(b, i); ++k) {
            if (k == i) block += '[';
            block += printable(static_cast<char>(t.frames[k] & 0x7F));
            if (k == i) block += ']';
        }
        const tape::RestoreProblem* problem = nullptr;
        for (const auto& p : r.problems)
            if (p.frame && *p.frame == i + 1) problem = &p;
        std::string candidates;
        if (problem)
            for (tape::Frame c : problem->candidates) candidates += printable(static_cast<char>(c & 0x7F));
        std::fprintf(stderr, "%s\t%zu\t%02x\t%02x\t%02x\t%s\t%s\t%s\t%s\n", t.name.c_str(), i, t.frames[i], read[i],
                     r.frames[i], problem ? std::string(tape::status_name(problem->status)).c_str() : "clean",
                     candidates.c_str(), block.c_str(), problem ? problem->reason.c_str() : "");
    }
    void report(benchmark::State& state) const {
        state.counters["damaged"] = per_run(bad);
        state.counters["right"] = per_run(right);
        state.counters["right_pct"] = bad ? 100.0 * static_cast<double>(right) / static_cast<double>(bad) : 0;
        state.counters["nc_right_pct"] =
            nc_bad ? 100.0 * static_cast<double>(nc_right) / static_cast<double>(nc_bad) : 0;
        state.counters["code_damaged"] = per_run(code_bad);
        state.counters["code_right_pct"] =
            code_bad ? 100.0 * static_cast<double>(code_right) / static_cast<double>(code_bad) : 0;
        state.counters["inferred"] = per_run(inferred);
        state.counters["wrong_inferred"] = per_run(wrong_inferred);
        state.counters["guessed"] = per_run(guessed);
        state.counters["guessed_right"] = per_run(guessed_right);
        state.counters["not_inferred_nor_guessed"] = per_run(unmarked);
    }
};

void run_one_read(benchmark::State& state, const std::vector<CorpusTape>& tapes, std::uint64_t seeds) {
    bool guess = state.range(0) != 0;
    OneReadTally t;
    for (auto _ : state)
        for (std::uint64_t s = 1; s <= seeds; ++s)
            for (const auto& tape : tapes) t.add(tape, s * 7919 + tape.frames.size(), guess);
    t.report(state);
}

void BM_OneReadGenerated(benchmark::State& state) {
    std::vector<CorpusTape> tapes;
    for (std::uint64_t p = 0; p < 4 * scale(); ++p) tapes.push_back(bench::generated_tape(250'000, p + 100, p % 2));
    run_one_read(state, tapes, 1);
}
BENCHMARK(BM_OneReadGenerated)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond);

void BM_OneReadSampleTapes(benchmark::State& state) { run_one_read(state, only(bench::sample_tapes()), 200 * scale()); }
BENCHMARK(BM_OneReadSampleTapes)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond);

// Real programs and DEC source tapes, seeds enough for 10^5 flips (about 30 passes over 0.7 MB).
void BM_OneReadReal(benchmark::State& state) {
    std::string note;
    auto tapes = bench::real_tapes(note);
    if (!note.empty()) std::fprintf(stderr, "restore_bench: %s\n", note.c_str());
    if (tapes.empty()) return state.SkipWithError(note.c_str());
    run_one_read(state, tapes, 30 * scale());
}
BENCHMARK(BM_OneReadReal)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond);

// Several damaged reads, restored and scored.
struct ManyReadsTally {
    std::uint64_t sets = 0, exact = 0, frames = 0, silent = 0, flagged = 0, in_doubt = 0, run_votes = 0;
    std::uint64_t decidable = 0, undecidable = 0, invisible = 0;

    void add(const CorpusTape& t, int reads, std::uint64_t seed) {
        std::vector<std::vector<tape::Frame>> rs;
        std::vector<tape::DamageLog> logs(static_cast<std::size_t>(reads));
        for (int k = 0; k < reads; ++k)
            rs.push_back(tape::damage(t.frames, tape::mixed_damage(0.01, seed * 7 + static_cast<std::uint64_t>(k) + 1),
                                      &logs[static_cast<std::size_t>(k)]));
        auto r = restore_reads(rs, false, &t);
        auto check = tape::check_restore(t.frames, r);
        ++sets, exact += check.exact, frames += tape::punched_part(t.frames).size();
        silent += check.silently_wrong, flagged += check.flagged_wrong, run_votes += r.run_length_votes;
        for (const auto& p : r.problems) in_doubt += tape::in_doubt(p.status);
        static bool dumped = false;
        if (const char* dump = std::getenv("RESTORE_BENCH_DUMP"); dump && !dumped && check.silently_wrong > 1000) {
            dumped = true;
            auto put = [&](const std::string& name, const std::vector<tape::Frame>& f) {
                if (FILE* out = std::fopen((std::string(dump) + name).c_str(), "wb")) {
                    std::fwrite(f.data(), 1, f.size(), out);
                    std::fclose(out);
                }
            };
            put("tape.ptp", t.frames), put("out.ptp", r.frames);
            for (std::size_t k = 0; k < rs.size(); ++k) put("read" + std::to_string(k + 1) + ".ptp", rs[k]);
        }
        if (const char* show = std::getenv("RESTORE_BENCH_SHOW"); show && std::string(show) == "flagged")
            for (std::size_t k = 0; k < check.flagged_at.size(); ++k)
                show_flagged(t.frames, r, check.flagged_at[k], check.flagged_output[k], seed);
        for (std::size_t k = 0; k < check.silent_at.size(); ++k) {
            if (std::getenv("RESTORE_BENCH_SHOW"))
                show(t.name, t.frames, logs, r, check.silent_at[k], check.silent_output[k], seed);
            classify(t.frames, logs, check.silent_at[k]);
        }
    }
    // Frames around at as text, at in brackets, an end of block as '|'.
    static std::string context(std::span<const tape::Frame> f, std::size_t at) {
        std::string s;
        for (std::size_t i = at > 12 ? at - 12 : 0; i < std::min(f.size(), at + 12); ++i) {
            char c = static_cast<char>(f[i] & 0x7f);
            s += i == at ? "[" : "";
            s += c == '\n' ? '|' : (c >= 32 && c < 127 ? c : '?');
            s += i == at ? "]" : "";
        }
        return s;
    }
    // RESTORE_BENCH_SHOW: each silent error with the tape, the output and the damage around it.
    static void show(const std::string& name, const std::vector<tape::Frame>& t,
                     const std::vector<tape::DamageLog>& logs, const tape::RestoreResult& r, std::size_t x,
                     std::size_t out, std::uint64_t set) {
        std::fprintf(stderr, "silent at %zu (%s, set %llu): tape \"%s\" output \"%s\"\n", x, name.c_str(),
                     static_cast<unsigned long long>(set), context(t, x).c_str(), context(r.frames, out).c_str());
        if (std::getenv("RESTORE_BENCH_SHOW_START")) {
            auto b = tape::punched_part(r.frames);
            std::size_t o = static_cast<std::size_t>(b.data() - r.frames.data());
            std::fprintf(stderr, "  output from %zu:", o);
            for (std::size_t i = o; i < o + 6; ++i) std::fprintf(stderr, " %02x", r.frames[i]);
            std::fprintf(stderr, "\n");
            for (const auto& p : r.problems)
                if (p.frame && *p.frame <= o + 6)
                    std::fprintf(stderr, "  problem at %llu: %s: %s\n", static_cast<unsigned long long>(*p.frame),
                                 std::string(tape::status_name(p.status)).c_str(), p.reason.c_str());
            for (std::size_t k = 0; k < logs.size(); ++k)
                for (const auto& e : logs[k].events)
                    if (e.original < 60)
                        std::fprintf(stderr, "  read %zu: %s at %zu (%zu frames)\n", k + 1,
                                     std::string(tape::damage_kind_name(e.kind)).c_str(), e.original, e.frames);
        }
        for (std::size_t k = 0; k < logs.size(); ++k)
            for (const auto& e : logs[k].events)
                if (e.original + 12 >= x && e.original <= x + 12)
                    std::fprintf(stderr, "  read %zu: %s at %zu (%zu frames)\n", k + 1,
                                 std::string(tape::damage_kind_name(e.kind)).c_str(), e.original, e.frames);
        for (const auto& p : r.problems)
            if (p.frame && *p.frame + 12 >= out + 1 && *p.frame <= out + 13)
                std::fprintf(stderr, "  problem at %llu: %s: %s\n", static_cast<unsigned long long>(*p.frame),
                             std::string(tape::status_name(p.status)).c_str(), p.reason.c_str());
    }
    // RESTORE_BENCH_SHOW=flagged: each frame wrong in doubt too, with the problem at it.
    static void show_flagged(const std::vector<tape::Frame>& t, const tape::RestoreResult& r, std::size_t x,
                             std::size_t out, std::uint64_t set) {
        std::string status = "left out";
        for (const auto& p : r.problems)
            if (p.frame && *p.frame == out + 1) status = std::string(tape::status_name(p.status)) + ": " + p.reason;
        std::fprintf(stderr, "flagged at %zu (set %llu): tape \"%s\" output \"%s\" %s\n", x,
                     static_cast<unsigned long long>(set), context(t, x).c_str(), context(r.frames, out).c_str(),
                     status.c_str());
    }
    // How many reads read the run of equal frames around tape frame x (and its neighbours) undamaged.
    void classify(const std::vector<tape::Frame>& t, const std::vector<tape::DamageLog>& logs, std::size_t x) {
        std::size_t a = std::min(x, t.size() - 1), b = a;
        while (a > 0 && t[a - 1] == t[x < t.size() ? x : a]) --a;
        while (b + 1 < t.size() && t[b + 1] == t[a]) ++b;
        std::size_t right = 0;
        for (const auto& log : logs) {
            bool touched = false;
            for (const auto& e : log.events) {
                if (e.kind == tape::DamageKind::leader_added || e.kind == tape::DamageKind::leader_removed) continue;
                std::size_t from = e.original, to = e.original + std::max<std::size_t>(e.frames, 1) - 1;
                touched |= to + 1 >= a && from <= b + 1;
            }
            right += !touched;
        }
        ++(right * 2 > logs.size() ? decidable : right > 0 ? undecidable : invisible);
        if (std::getenv("RESTORE_BENCH_SHOW"))
            std::fprintf(stderr, "  (%s: %zu of %zu reads read it undamaged)\n",
                         right * 2 > logs.size() ? "decidable"
                         : right > 0             ? "undecidable"
                                                 : "invisible",
                         right, logs.size());
    }
    void report(benchmark::State& state) const {
        state.counters["sets"] = per_run(sets);
        state.counters["byte_exact"] = per_run(exact);
        state.counters["data_frames"] = per_run(frames);
        state.counters["silently_wrong"] = per_run(silent);
        state.counters["silent_per_1e7"] = frames ? 1e7 * static_cast<double>(silent) / static_cast<double>(frames) : 0;
        state.counters["decidable"] = per_run(decidable);
        state.counters["undecidable"] = per_run(undecidable);
        state.counters["invisible"] = per_run(invisible);
        state.counters["wrong_per_1e6"] =
            frames ? 1e6 * static_cast<double>(silent + flagged) / static_cast<double>(frames) : 0;
        state.counters["in_doubt_pct"] =
            frames ? 100.0 * static_cast<double>(in_doubt) / static_cast<double>(frames) : 0;
        state.counters["run_length_votes"] = per_run(run_votes);
    }
};

// Each set of reads has damage of its own: the seed counts sets, not passes (with one pass, ten tapes
// damaged alike repeat one coincidence of damage ten times).
void run_many(benchmark::State& state, const std::vector<CorpusTape>& tapes, std::uint64_t seeds) {
    ManyReadsTally t;
    for (auto _ : state)
        for (std::uint64_t s = 0; s < seeds; ++s)
            for (std::size_t k = 0; k < tapes.size(); ++k)
                t.add(tapes[k], static_cast<int>(state.range(0)), s * tapes.size() + k);
    t.report(state);
}

void BM_ManyReadsGenerated(benchmark::State& state) {
    std::vector<CorpusTape> tapes;
    for (std::uint64_t p = 0; p < 10 * scale(); ++p) tapes.push_back(bench::generated_tape(1'000'000, p + 1, p % 2));
    run_many(state, tapes, 1);
}
BENCHMARK(BM_ManyReadsGenerated)->Arg(3)->Arg(5)->Iterations(1)->Unit(benchmark::kSecond);

// Real programs and DEC source tapes, each restored as its own tape (one program's style, its own
// repeated sections: TOKARKA holds thousands of near-identical blocks, comp.ngc two near-identical
// sections), ten sets of reads each: about 7 x 10^6 frames.
void BM_ManyReadsReal(benchmark::State& state) {
    std::string note;
    auto tapes = bench::real_tapes(note);
    if (tapes.empty()) return state.SkipWithError(note.c_str());
    run_many(state, tapes, 10 * scale());
}
BENCHMARK(BM_ManyReadsReal)->Arg(3)->Arg(5)->Iterations(1)->Unit(benchmark::kSecond);

void BM_ManyReadsSampleTapes(benchmark::State& state) { run_many(state, only(bench::sample_tapes()), 1000 * scale()); }
BENCHMARK(BM_ManyReadsSampleTapes)->Arg(3)->Arg(5)->Iterations(1)->Unit(benchmark::kSecond);

void BM_FiveReadsSpeed(benchmark::State& state) {
    auto t = bench::generated_tape(1'000'000, 42);
    std::vector<std::vector<tape::Frame>> reads;
    for (std::uint64_t k = 0; k < 5; ++k) reads.push_back(tape::damage(t.frames, tape::mixed_damage(0.01, k + 50)));
    for (auto _ : state) {
        auto r = restore_reads(reads);
        benchmark::DoNotOptimize(r.frames.data());
    }
    state.counters["frames_per_read"] = static_cast<double>(t.frames.size());
}
BENCHMARK(BM_FiveReadsSpeed)->Iterations(3)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
