// The restored image as repair sees it (repair_world.hpp).
#include "repair_world.hpp"

#include <algorithm>

namespace tape::detail {
namespace {

bool end_of_block(const FrameCode& code, Frame f) {
    return code.kind(f) == FrameKind::character && code.character(f) == '\n';
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
    w->setup.nc = looks_like_nc_program(w->text);
    w->setup.dialect = o.dialect != Dialect::automatic ? o.dialect : guess_dialect(w->text).dialect;
    std::set<std::uint64_t>& lines = w->damaged_lines;
    for (std::size_t d : damaged) lines.insert(w->line_of(d));
    for (std::size_t l = 1; l < w->block_starts.size(); ++l)
        if (!lines.count(l))
            w->chars.learn(image.subspan(w->block_starts[l - 1], w->block_starts[l] - w->block_starts[l - 1]));
    if (!w->setup.nc) return w;
    w->rules = std::make_unique<TapeRules>(lines, o.spec);
    load_each(w->text, {}, *w->rules, LoadOptions{w->setup.dialect});
    w->rules->finish(w->text);
    w->setup.rules = w->rules.get();
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
