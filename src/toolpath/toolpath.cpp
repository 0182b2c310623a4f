// The moves kept for drawing (tape/toolpath.hpp).
#include "tape/toolpath.hpp"

#include <algorithm>

namespace tape {

// A block's frames run from its first to the frame before the next block's first (its end of block
// included), as the loader gave them; the last block's to its move's last frame.
std::uint64_t Toolpath::last_frame_of(const PathMove& m) const {
    std::uint64_t last = std::max(*m.frame, m.last_frame.value_or(*m.frame));
    auto next = std::upper_bound(block_frames_.begin(), block_frames_.end(), std::make_pair(m.block, UINT64_MAX));
    if (next != block_frames_.end() && next->second > *m.frame) last = std::max(last, next->second - 1);
    return last;
}

void Toolpath::mark_doubtful(std::vector<std::uint64_t> frames) {
    std::sort(frames.begin(), frames.end());
    for (auto& m : moves_) {
        if (!m.frame || m.doubt) continue;
        auto it = std::lower_bound(frames.begin(), frames.end(), *m.frame);
        m.doubt = it != frames.end() && *it <= last_frame_of(m);
    }
}

void Toolpath::move(const Move& m) {
    if (m.kind == MoveKind::not_simulated) {
        if (not_simulated_.size() < 100) not_simulated_.push_back(m);
        ++not_simulated_count_;
        if (!has_last_) return;
        // Marked where the tool stood: where on the part the picture stops being sure.
        Move here = m;
        here.start = here.end = last_end_;
        here.known = last_known_;
        has_last_ = false;
        return keep(here);
    }
    if (m.kind != MoveKind::rapid && m.kind != MoveKind::linear && m.kind != MoveKind::arc) return;
    if ((m.known & all_axes) == 0) {
        ++unknown_;
        has_last_ = false;
        return;
    }
    last_end_ = m.end;
    last_known_ = m.known;
    has_last_ = true;
    keep(m);
}

void Toolpath::program_start(const Program&) { has_last_ = false; }

void Toolpath::keep(const Move& m) {
    PathMove p{.start = m.start,
               .end = m.end,
               .centre = m.centre,
               .kind = m.kind,
               .plane = m.state.plane,
               .clockwise = m.clockwise,
               .turns = m.turns,
               .tool = m.state.tool,
               .known = m.known & all_axes,
               .block = m.block,
               .line = m.where.line,
               .frame = m.where.frame,
               .last_frame = m.last_frame};
    moves_.push_back(p);
    if (!keep_blocks_) return;
    // A block's moves share its text (a canned cycle is many moves of one block).
    if (text_at_.empty() || m.block != last_block_) {
        text_at_.push_back(static_cast<std::uint32_t>(texts_.size()));
        texts_ += m.block == source_block_ ? source_ : "block " + std::to_string(m.block);
        texts_ += '\n';
    } else {
        text_at_.push_back(text_at_.back());
    }
    last_block_ = m.block;
}

void Toolpath::note_block(const Block& block) {
    if (block.where.frame && (block_frames_.empty() || block_frames_.back().first < block.ordinal))
        block_frames_.emplace_back(block.ordinal, *block.where.frame);
    subprogram_block(block);
}

void Toolpath::subprogram_block(const Block& block) {
    if (!keep_blocks_) return;
    source_block_ = block.ordinal;
    source_ = block.source;
    std::replace(source_.begin(), source_.end(), '\n', ' ');
}

std::string_view Toolpath::block_text(std::size_t i) const {
    if (!keep_blocks_ || i >= text_at_.size()) return {};
    std::size_t from = text_at_[i], to = texts_.find('\n', from);
    return std::string_view(texts_).substr(from, to == std::string::npos ? std::string::npos : to - from);
}

}  // namespace tape
