// The moves kept for drawing (tape/toolpath.hpp).
#include "tape/toolpath.hpp"

#include <algorithm>

namespace tape {

void Toolpath::mark_doubtful(std::vector<std::uint64_t> frames) {
    std::sort(frames.begin(), frames.end());
    for (auto& m : moves_) {
        if (!m.frame || m.doubt) continue;
        std::uint64_t first = *m.frame, last = std::max(first, m.last_frame.value_or(first));
        auto it = std::lower_bound(frames.begin(), frames.end(), first);
        m.doubt = it != frames.end() && *it <= last;
    }
}

void Toolpath::move(const Move& m) {
    if (m.kind == MoveKind::not_simulated) {
        if (not_simulated_.size() < 100) not_simulated_.push_back(m);
        ++not_simulated_count_;
        return;
    }
    if (m.kind != MoveKind::rapid && m.kind != MoveKind::linear && m.kind != MoveKind::arc) return;
    if ((m.known & all_axes) != all_axes) {
        ++unknown_;
        return;
    }
    PathMove p{.start = m.start,
               .end = m.end,
               .centre = m.centre,
               .kind = m.kind,
               .plane = m.state.plane,
               .clockwise = m.clockwise,
               .turns = m.turns,
               .tool = m.state.tool,
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
