#include "tape/search.hpp"

#include <algorithm>

namespace tape {
namespace {

template <typename Fn>
void for_each_block(const LoadedTape& t, Fn fn) {
    for (const auto& p : t.programs)
        for (const auto& b : p.blocks)
            if (!fn(BlockRef{&p, &b})) return;
}

}  // namespace

std::uint64_t frame_offset(const LoadedTape& t, std::uint64_t frame) {
    if (t.frame_of.empty()) {
        std::uint64_t line = 1, i = 0;
        for (; i < t.text.size() && line < frame; ++i) line += t.text[i] == '\n';
        return i;
    }
    auto it = std::lower_bound(t.frame_of.begin(), t.frame_of.end(), frame == 0 ? 0 : frame - 1);
    return static_cast<std::uint64_t>(it - t.frame_of.begin());
}

std::optional<BlockRef> find_main_block(const LoadedTape& t, std::uint64_t from, std::optional<long long> number) {
    std::optional<BlockRef> hit;
    for_each_block(t, [&](BlockRef r) {
        if (!r.block->main || r.block->where.offset < from) return true;
        if (number && r.block->number && r.block->number->integer() != number) return true;
        hit = r;
        return false;
    });
    return hit;
}

const Program* find_rewind_stop(const LoadedTape& t, std::uint64_t from) {
    const Program* stop = nullptr;
    for (const auto& p : t.programs)
        if (p.percent && p.start.offset < from) stop = &p;  // a program without '%' has no stop
    return stop;
}

const Program* find_program(const LoadedTape& t, std::string_view number) {
    for (const auto& p : t.programs)
        if (p.number && program_key(*p.number) == program_key(number)) return &p;
    return nullptr;
}

std::vector<BlockRef> find_numbered_blocks(const LoadedTape& t, long long number) {
    std::vector<BlockRef> hits;
    for_each_block(t, [&](BlockRef r) {
        if (r.block->number && r.block->number->integer() == number) hits.push_back(r);
        return true;
    });
    return hits;
}

std::vector<BlockRef> main_blocks(const LoadedTape& t) {
    std::vector<BlockRef> hits;
    for_each_block(t, [&](BlockRef r) {
        if (r.block->main) hits.push_back(r);
        return true;
    });
    return hits;
}

bool Searcher::at_or_after_from(const Location& where) const {
    if (query_.from <= 1) return true;
    return query_.from_tape ? where.frame.value_or(0) >= query_.from : where.line >= query_.from;
}

void Searcher::program_start(const Program& p) {
    using Kind = SearchQuery::Kind;
    std::string text = p.percent ? "%" + p.number.value_or("") : p.number.value_or("");
    if (query_.kind == Kind::rewind_stop && p.percent && !at_or_after_from(p.start))
        hits_.assign(1, SearchHit{p.start, text});
    if (query_.kind == Kind::program && hits_.empty() && p.number && at_or_after_from(p.start) &&
        program_key(*p.number) == program_key(query_.program)) {
        if (p.numbered_by_block)
            number_block_ = *p.number;  // the hit is its "O1234" block, as written, where it stands
        else
            hits_.push_back(SearchHit{p.start, text});
    }
}

// The '%' after the last program (Fanuc's end of record, LinuxCNC's closing '%') stops a rewind too.
void Searcher::record_end(const Location& where, bool) {
    if (query_.kind == SearchQuery::Kind::rewind_stop && !at_or_after_from(where))
        hits_.assign(1, SearchHit{where, "%"});
}

void Searcher::block(const Block& b) {
    using Kind = SearchQuery::Kind;
    if (number_block_ && std::any_of(b.words.begin(), b.words.end(), [&](const Word& w) {
            return (w.address == 'O' || w.address == ':') && w.text == *number_block_;
        })) {
        hits_.push_back(SearchHit{b.where, b.text()});
        number_block_.reset();
    }
    bool numbered = query_.number && b.number && b.number->integer() == query_.number;
    if (query_.kind == Kind::main_block && b.main && at_or_after_from(b.where) &&
        (!query_.number || !b.number || numbered))
        hits_.push_back(SearchHit{b.where, b.text()});
    if (query_.kind == Kind::numbered_block && numbered && at_or_after_from(b.where))
        hits_.push_back(SearchHit{b.where, b.text()});
}

}  // namespace tape
