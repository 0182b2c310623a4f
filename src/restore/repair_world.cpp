// The restored image as repair sees it (repair_world.hpp).
#include "repair_world.hpp"

#include <algorithm>

namespace tape::detail {
namespace {

bool end_of_block(const FrameCode& code, Frame f) {
    return code.kind(f) == FrameKind::character && code.character(f) == '\n';
}

// Whether an undamaged line holds DEL, or blank tape between two of its characters.
void learn_skipped_frames(RepairWorld& w, const FrameCode& code, std::span<const Frame> line) {
    bool character_before = false, blank_since = false;
    for (Frame f : line) {
        FrameKind k = code.kind(f);
        w.rubouts |= k == FrameKind::rubout;
        if (k == FrameKind::blank) {
            blank_since |= character_before;
        } else if (k == FrameKind::character) {
            w.blank_inside_lines |= blank_since && code.character(f) != '\n';
            character_before = true, blank_since = false;
        }
    }
}

// A damaged frame at `at` may touch its line's block number: it stands among the line's first frames up
// to the first that is no part of a number ("/", ":", "N" and digits, blanks skipped), that one included
// (where a lost digit of the number is placed), or it is the line's first character. `at` may be the
// image's end (a frame left out after the last one).
bool touches_number(const FrameCode& code, std::span<const Frame> image, std::size_t line_start, std::size_t at) {
    bool first = true;
    for (std::size_t i = line_start; i <= at && i < image.size(); ++i) {
        FrameKind k = code.kind(image[i]);
        if (k == FrameKind::blank || k == FrameKind::rubout) continue;
        if (i == at) return true;
        char c = k == FrameKind::character ? code.character(image[i]) : '?';
        bool number = c == '/' || c == ':' || c == 'N' || c == 'n' || (c >= '0' && c <= '9') || (c == ' ' && !first);
        if (!number) return false;
        first = false;
    }
    return true;
}

}  // namespace

std::uint64_t RepairWorld::line_of(std::size_t frame) const {
    auto it = std::upper_bound(block_starts.begin(), block_starts.end(), frame);
    return static_cast<std::uint64_t>(it - block_starts.begin());
}

std::unique_ptr<RepairWorld> learn_world(std::span<const Frame> image, std::span<const std::size_t> damaged,
                                         const FrameCode& code, const RestoreOptions& o) {
    auto w = std::make_unique<RepairWorld>();
    w->text = block_text(code, image);
    w->block_starts.push_back(0);
    for (std::size_t i = 0; i < image.size(); ++i)
        if (end_of_block(code, image[i])) w->block_starts.push_back(i + 1);
    w->setup.code = code;
    w->setup.spec = o.spec;
    w->setup.machine = o.machine;
    for (std::size_t i = 0; i < image.size() && w->setup.first_percent == SIZE_MAX; ++i)
        if (code.kind(image[i]) == FrameKind::character && code.character(image[i]) == '%') w->setup.first_percent = i;
    w->setup.nc = looks_like_nc_program(w->text);
    w->setup.dialect = o.dialect != Dialect::automatic ? o.dialect : guess_dialect(w->text).dialect;
    std::set<std::uint64_t>& lines = w->damaged_lines;
    for (std::size_t d : damaged) {
        std::uint64_t line = w->line_of(d);
        lines.insert(line);
        if (touches_number(code, image, w->block_starts[line - 1], d)) w->numbers_damaged.insert(line);
    }
    for (std::size_t l = 1; l < w->block_starts.size(); ++l) {
        if (lines.count(l)) continue;
        auto line = image.subspan(w->block_starts[l - 1], w->block_starts[l] - w->block_starts[l - 1]);
        w->chars.learn(line);
        learn_skipped_frames(*w, code, line);
    }
    if (!w->setup.nc) return w;
    w->rules = std::make_unique<TapeRules>(lines, w->numbers_damaged, o.spec, o.machine);
    load_each(w->text, {}, *w->rules, LoadOptions{w->setup.dialect});
    w->rules->finish(w->text);
    w->setup.rules = w->rules.get();
    w->setup.nc = w->rules->grammar_fits();
    return w;
}

std::optional<std::pair<std::size_t, std::size_t>> block_around(const FrameCode& code, std::span<const Frame> image,
                                                                std::size_t at) {
    constexpr std::size_t longest = 512;
    std::size_t from = at, to = at + 1;
    while (from > 0 && !end_of_block(code, image[from - 1])) {
        if (at - from > longest) return std::nullopt;
        --from;
    }
    while (to < image.size() && !end_of_block(code, image[to - 1])) {
        if (to - at > longest) return std::nullopt;
        ++to;
    }
    return std::make_pair(from, to);
}

}  // namespace tape::detail
