#include "program/restart_calls.hpp"

#include <algorithm>

namespace tape {
namespace {

// The start of the line holding offset.
std::uint64_t line_start(std::string_view text, std::uint64_t offset) {
    if (offset == 0) return 0;
    auto lf = text.rfind('\n', offset - 1);
    return lf == std::string_view::npos ? 0 : lf + 1;
}

// Just past the end of the line holding offset (its LF included).
std::uint64_t line_end(std::string_view text, std::uint64_t offset) {
    auto lf = text.find('\n', offset);
    return lf == std::string_view::npos ? text.size() : lf + 1;
}

bool calls_program(const Block& b) {
    return std::any_of(b.words.begin(), b.words.end(),
                       [](const Word& w) { return w.address == 'M' && !w.macro && w.integer() == 98; });
}

}  // namespace

std::string definitions_before(const LoadedTape& tape, const Program& p, std::size_t index) {
    std::string out;
    std::optional<std::uint64_t> open;  // the line start of the o-sub being defined
    for (std::size_t i = 0; i < index && i < p.blocks.size(); ++i)
        for (const auto& s : p.blocks[i].statements) {
            if (s.kind != Statement::Kind::o_word) continue;
            if (s.keyword == "sub" && !open) open = line_start(tape.text, p.blocks[i].where.offset);
            if (s.keyword == "endsub" && open) {
                auto to = line_end(tape.text, p.blocks[i].where.offset);
                out += tape.text.substr(*open, to - *open);
                open.reset();
            }
        }
    if (!out.empty() && out.back() != '\n') out += '\n';
    return out;
}

std::uint64_t rest_end(const LoadedTape& tape, const Program& p, std::size_t index) {
    std::uint64_t end = tape.text.size();
    for (const auto& other : tape.programs)
        if (other.start.offset > p.start.offset && other.start.offset < end) end = other.start.offset;
    bool calls = std::any_of(p.blocks.begin() + static_cast<std::ptrdiff_t>(std::min(index, p.blocks.size())),
                             p.blocks.end(), calls_program);
    return calls ? tape.text.size() : end;
}

}  // namespace tape
