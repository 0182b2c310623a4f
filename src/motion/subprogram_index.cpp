// Where a text's subprograms stand (src/motion/subprograms.hpp): one pass of the loader over the text,
// keeping offsets only — programs by O number, LinuxCNC o-subs by label, numbered blocks (for M97 and
// M99 P) — and the program numbers its M98 blocks call. Only a text that writes a call is indexed.
#include <algorithm>

#include "motion/subprograms.hpp"

namespace tape {

namespace {

// M97, M98 (M097, m98) or an o-word "call" written anywhere: a quick look, comments included.
bool may_call(std::string_view t) {
    for (std::size_t i = 0; i + 3 < t.size(); ++i) {
        char c = static_cast<char>(t[i] | 0x20);
        if (c == 'm') {
            std::size_t j = i + 1;
            while (j < t.size() && t[j] == '0') ++j;
            if (j + 1 < t.size() && t[j] == '9' && (t[j + 1] == '7' || t[j + 1] == '8')) return true;
        } else if (c == 'c' && (t[i + 1] | 0x20) == 'a' && (t[i + 2] | 0x20) == 'l' && (t[i + 3] | 0x20) == 'l') {
            return true;
        }
    }
    return false;
}

// "O1000", ":1000" (Fanuc's main program number) or "1000" as the number M98 P calls.
std::optional<long long> program_number(std::string_view s) {
    s = program_key(s);
    if (s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
    long long n = 0;
    for (char c : s) n = n * 10 + (c - '0');
    return n;
}

motion::TextPlace place_of(const Block& b) {
    return motion::TextPlace{b.where.offset, b.where.line, b.where.column, b.ordinal};
}

}  // namespace

// The loader's programs and blocks into the index.
class SubprogramIndexer : public ProgramVisitor {
public:
    explicit SubprogramIndexer(SubprogramIndex& out) : out_(out) {}

    void program_start(const Program& h) override {
        close(h.start.offset);
        SubprogramIndex::Program p;
        p.start = h.start.offset;
        if (h.number) p.number = program_number(*h.number);
        o_block_ = h.numbered_by_block ? h.number : std::nullopt;
        out_.programs_.push_back(p);
    }
    void block(const Block& b) override {
        if (out_.programs_.empty()) out_.programs_.push_back({});
        auto& p = out_.programs_.back();
        if (!p.has_body && o_block_ && b.source.starts_with(*o_block_)) {
            o_block_.reset();  // "O1000": the program's number, its body follows
        } else if (!p.has_body) {
            p.body.from = place_of(b);
            p.has_body = true;
        }
        if (b.number)
            if (auto n = b.number->integer()) out_.numbered_.push_back({out_.programs_.size() - 1, *n, place_of(b)});
        statements(b);
        targets(b);
    }
    void record_end(const Location& where, bool) override { close(where.offset); }
    void end(const Location& where) override {
        close(where.offset);
        std::stable_sort(out_.numbered_.begin(), out_.numbered_.end());
        std::sort(out_.targets_.begin(), out_.targets_.end());
    }

private:
    void close(std::uint64_t at) {
        if (!out_.programs_.empty() && out_.programs_.back().body.end == 0) out_.programs_.back().body.end = at;
    }
    // o<name> sub ... o<name> endsub: the body between, its first block the one after "sub".
    void statements(const Block& b) {
        if (opening_) {
            out_.subs_.back().body.from = place_of(b);
            opening_ = false;
        }
        for (const auto& s : b.statements) {
            if (s.kind != Statement::Kind::o_word) continue;
            if (s.keyword == "sub") {
                out_.subs_.push_back({s.label, {place_of(b), b.where.offset}});
                open_.push_back(out_.subs_.size() - 1);
                opening_ = true;
            } else if (s.keyword == "endsub" && !open_.empty()) {
                auto& sub = out_.subs_[open_.back()];
                if (opening_ || sub.body.from.offset > b.where.offset) sub.body.from = place_of(b);
                sub.body.end = b.where.offset;
                open_.pop_back();
                opening_ = false;
            }
        }
    }
    // M98 P1000: program 1000 is called (and, P with more than 4 digits, its last four: Fanuc's P####LLLL).
    void targets(const Block& b) {
        bool m98 = std::any_of(b.words.begin(), b.words.end(),
                               [](const Word& w) { return w.address == 'M' && w.integer() == 98; });
        if (!m98) return;
        for (const auto& w : b.words)
            if (w.address == 'P' && w.integer()) {
                std::size_t by = out_.programs_.size() - 1;
                out_.targets_.emplace_back(*w.integer(), by);
                if (w.digits().size() > 4) out_.targets_.emplace_back(*w.integer() % 10000, by);
            }
    }

    SubprogramIndex& out_;
    std::optional<std::string> o_block_;
    std::vector<std::size_t> open_;  // o-subs not yet closed
    bool opening_ = false;           // the next block is an o-sub's first
};

SubprogramIndex::SubprogramIndex(std::string_view text, std::span<const std::uint64_t> frame_of, Dialect dialect) {
    SubprogramIndexer indexer(*this);
    LoadOptions lo;
    lo.dialect = dialect;
    load_each(text, frame_of, indexer, lo);
}

const SubprogramIndex::Program* SubprogramIndex::program(long long number) const {
    for (const auto& p : programs_)
        if (p.number == number && p.has_body) return &p;
    return nullptr;
}

std::size_t SubprogramIndex::program_at(std::uint64_t offset) const {
    auto it = std::upper_bound(programs_.begin(), programs_.end(), offset,
                               [](std::uint64_t o, const Program& p) { return o < p.start; });
    return it == programs_.begin() ? 0 : static_cast<std::size_t>(it - programs_.begin() - 1);
}

const motion::TextPlace* SubprogramIndex::numbered(std::size_t program, long long n) const {
    auto it = std::lower_bound(numbered_.begin(), numbered_.end(), Numbered{program, n, {}});
    return it != numbered_.end() && it->program == program && it->n == n ? &it->at : nullptr;
}

const SubprogramIndex::Sub* SubprogramIndex::sub(std::string_view label) const {
    for (const auto& s : subs_)
        if (s.label == label && s.body.end >= s.body.from.offset) return &s;
    return nullptr;
}

bool SubprogramIndex::called(long long number, std::size_t i) const {
    auto it = std::lower_bound(targets_.begin(), targets_.end(), std::make_pair(number, std::size_t{0}));
    for (; it != targets_.end() && it->first == number; ++it)
        if (it->second != i) return true;
    return false;
}

SubprogramText::SubprogramText(std::string_view text, std::span<const std::uint64_t> frame_of)
    : text_(text), frame_of_(frame_of), has_calls_(may_call(text)) {}

SubprogramText::~SubprogramText() = default;

const SubprogramIndex& SubprogramText::index(Dialect dialect) const {
    if (!index_) index_ = std::make_unique<SubprogramIndex>(text_, frame_of_, dialect);
    return *index_;
}

}  // namespace tape
