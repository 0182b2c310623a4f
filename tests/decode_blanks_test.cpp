// The blank-in-block report (Decoder) against the plain reading of its rule, a frame at a time, as the
// decoder did it before it learnt to skip what cannot change the answer: the same findings, frame for
// frame, on the project's sample tapes, every tape of ../shared/data, and made-up tapes with blank runs
// and DEL in every kind of place, however the tape is cut into chunks.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

#include "every_tape.hpp"
#include "tape/code.hpp"
#include "tape/decode.hpp"
#include "test_util.hpp"

namespace {

using namespace tape;

struct Blank {
    std::uint64_t frame = 0;
    std::string message;
    bool operator==(const Blank&) const = default;
    friend std::ostream& operator<<(std::ostream& os, const Blank& b) {
        return os << "frame " << b.frame << ": " << b.message;
    }
};

// The rule read plainly, a frame at a time: a blank run after a printable character and
// before the next one is inside a block; after an end of block, a run longer than the tape's habit
// there (15 of the last 16) is said once two more block starts keep the habit.
class PlainReading {
public:
    explicit PlainReading(const FrameCode& code) : code_(code) {}

    void frame(Frame f, std::uint64_t index) {
        FrameKind kind = code_.kind(f);
        if (kind == FrameKind::rubout) return;
        if (f == 0) {
            if (before_ != Before::nothing && !blanks_) from_ = index;
            if (before_ != Before::nothing) ++blanks_;
            return;
        }
        char c = kind == FrameKind::character ? code_.character(f) : '\0';
        bool printable = kind == FrameKind::character && static_cast<unsigned char>(c) >= 0x20;
        if (before_ == Before::printable && blanks_)
            say(from_, blanks_, "inside a block");
        else if (before_ == Before::end_of_block && printable && c != '%')
            block_start();
        blanks_ = 0;
        before_ = printable ? Before::printable : c == '\n' ? Before::end_of_block : Before::nothing;
    }
    std::vector<Blank> said;

private:
    void block_start() {
        std::uint64_t run = std::min<std::uint64_t>(blanks_, 255);
        if (suspect_.frames) {
            if (run != suspect_.usual) {
                suspect_ = {};
            } else if (++suspect_.kept == 2) {
                say(suspect_.from, suspect_.frames,
                    "at the start of a block, where this tape has " + std::to_string(suspect_.usual) +
                        " after each end of block");
                suspect_ = {};
            }
        }
        std::array<unsigned, 256> count{};
        std::size_t usual = 0;
        for (std::size_t k = 0; k < seen_ && k < habit_.size(); ++k)
            if (++count[habit_[k]] > count[usual]) usual = habit_[k];
        if (seen_ >= habit_.size() && count[usual] + 1 >= habit_.size() && run > usual && !suspect_.frames)
            suspect_ = {from_ + usual, run - usual, usual, 0};
        habit_[seen_++ % habit_.size()] = static_cast<std::uint8_t>(run);
    }
    void say(std::uint64_t from, std::uint64_t n, const std::string& where) {
        said.push_back({from + 1, std::to_string(n) + " " + where});
    }

    const FrameCode& code_;
    enum class Before { nothing, printable, end_of_block } before_ = Before::nothing;
    std::uint64_t from_ = 0, blanks_ = 0;
    std::array<std::uint8_t, 16> habit_{};
    std::size_t seen_ = 0;
    struct {
        std::uint64_t from = 0, frames = 0, usual = 0;
        int kept = 0;
    } suspect_;
};

std::vector<Blank> plain_reading(std::span<const Frame> frames, Code code) {
    FrameCode c = FrameCode::make(code, Parity::even);
    PlainReading r(c);
    for (std::size_t i = 0; i < frames.size(); ++i) r.frame(frames[i], i);
    return r.said;
}

// The decoder's findings, the tape fed in chunks of the sizes given (cycled), as a device gives them.
std::vector<Blank> decoder_reading(std::span<const Frame> frames, Code code, std::span<const std::size_t> chunks) {
    DecodeOptions o;
    o.code = code;
    o.keep_going = true;
    Decoder d(o);
    DecodeResult r;
    for (std::size_t at = 0, k = 0; at < frames.size(); ++k) {
        std::size_t n = std::min(chunks[k % chunks.size()], frames.size() - at);
        d.feed(frames.subspan(at, n), r);
        at += n;
    }
    d.finish(r);
    std::vector<Blank> out;
    for (const auto& x : r.diagnostics) {
        if (x.code != Errc::blank_frame) continue;
        // "N blank frames (frames a-b) WHERE: ..." or "blank frame WHERE: ...": the count and the place.
        std::string m = x.message;
        std::uint64_t n = m.starts_with("blank frame ") ? 1 : std::stoull(m);
        std::string where = m.substr(m.find(n == 1 ? "frame " : ") ") + (n == 1 ? 6 : 2));
        out.push_back({*x.where.frame, std::to_string(n) + " " + where.substr(0, where.find(':'))});
    }
    return out;
}

void expect_same_reading(std::span<const Frame> frames, const std::string& name) {
    for (Code code : {Code::iso, Code::eia}) {
        auto plain = plain_reading(frames, code);
        for (auto chunks : {std::vector<std::size_t>{1u << 20}, std::vector<std::size_t>{1, 7, 64, 3, 1000}}) {
            auto decoded = decoder_reading(frames, code, chunks);
            auto by_frame = [](const Blank& a, const Blank& b) { return a.frame < b.frame; };
            std::stable_sort(decoded.begin(), decoded.end(), by_frame);  // a run is said after it, at its frame
            std::stable_sort(plain.begin(), plain.end(), by_frame);
            auto differ = std::mismatch(decoded.begin(), decoded.end(), plain.begin(), plain.end());
            if (differ.first != decoded.end() || differ.second != plain.end())
                ADD_FAILURE() << name << " in " << code_name(code) << ", chunks of " << chunks.size()
                              << " sizes: " << decoded.size() << " findings against " << plain.size()
                              << "; the first that differ: "
                              << (differ.first != decoded.end() ? *differ.first : Blank{}) << " against "
                              << (differ.second != plain.end() ? *differ.second : Blank{});
        }
    }
}

TEST(BlankInBlock, SameFindingsAsTheFrameByFrameRuleOnEveryTape) {
    auto tapes = every_tape();
    for (const auto& t : tapes) {
        expect_same_reading(t.frames, t.path);
        if (HasFailure()) break;
    }
    EXPECT_GE(tapes.size(), every_tape_minimum());
}

// Text blocks with blank runs after characters, after ends of block (now the habit, now more), DEL
// between and inside them, bad frames, and no blank at all for long stretches.
std::vector<Frame> made_up_tape(std::mt19937& random) {
    const std::string letters = "N1G0X.5-%\n\n\n\r";
    std::vector<Frame> out(20, 0);
    int habit = static_cast<int>(random() % 3);
    for (int block = 0; block < 400; ++block) {
        if (random() % 50 == 0) habit = static_cast<int>(random() % 3);
        int blanks = random() % 9 == 0 ? habit + 1 + static_cast<int>(random() % 4) : habit;
        out.insert(out.end(), static_cast<std::size_t>(blanks), 0);
        for (int k = 1 + static_cast<int>(random() % 12); k > 0; --k) {
            unsigned r = random() % 100;
            if (r < 4)
                out.push_back(0);
            else if (r < 7)
                out.push_back(0xFF);
            else if (r < 8)
                out.push_back(static_cast<Frame>(random()));
            else {
                auto c = static_cast<unsigned char>(letters[random() % (letters.size() - 4)]);
                out.push_back(static_cast<Frame>(c | (std::popcount(c) % 2 ? 0x80 : 0)));
            }
        }
        out.push_back(random() % 10 == 0 ? 0x8D : 0x0A);  // CR now and then
        if (random() % 7 == 0) out.push_back(0xFF);
    }
    out.insert(out.end(), 20, 0);
    return out;
}

TEST(BlankInBlock, SameFindingsAsTheFrameByFrameRuleOnMadeUpTapes) {
    std::mt19937 random(2026);
    std::size_t block_starts = 0;  // the habit's findings, which need the ends of block looked at
    for (int t = 0; t < 200; ++t) {
        auto frames = made_up_tape(random);
        for (const auto& b : plain_reading(frames, Code::iso))
            block_starts += b.message.find("start of a block") != std::string::npos;
        expect_same_reading(frames, "made-up tape " + std::to_string(t));
        if (HasFailure()) break;
    }
    EXPECT_GT(block_starts, 100u);
}

}  // namespace
