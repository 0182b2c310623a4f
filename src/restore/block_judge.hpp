// Judging a repair candidate by the block it stands in (repair.cpp): only by what goes wrong at and
// around the damaged words. The block with those words left out is the baseline: an error it has
// anyway decides nothing, nor does one the undamaged program makes elsewhere too.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "tape/restore.hpp"
#include "tape_rules.hpp"

namespace tape::detail {

/// How repair reads the restored image.
struct RepairSetup {
    FrameCode code;
    Dialect dialect = Dialect::gost;
    bool nc = true;                           ///< the text is an NC program: its grammar and rules apply
    const TapeRules* rules = nullptr;         ///< the program's own rules (with nc)
    const FormatSpec* spec = nullptr;         ///< the controller's format, when given
    const MachineProfile* machine = nullptr;  ///< the machine's profile, when given (rules has its modes)
    /// The image's first '%' (its frame index; none: SIZE_MAX): blocks after it are a program's.
    std::size_t first_percent = SIZE_MAX;
};

/// A block's frames with candidates in place, and which of them are being decided.
struct BlockTry {
    std::vector<Frame> frames;
    std::vector<std::size_t> decided;  ///< indices into frames
};

/// The rules a try breaks near its decided frames, that the block without them does not break:
/// lint's rule ids ("unknown-word"), and "unknown-code", "word-format", "block-number",
/// "value-range", "arc", "spec-…". Empty: it fits. One entry is no break: arc_closes, for a try whose
/// arc closes (the arc rule decides only between tries where some arc closes: see BlockRepair).
using Breaks = std::vector<std::string>;
inline constexpr std::string_view arc_closes = "+arc";

/// "word-format, block-number": the rules broken, for a reason.
std::string joined(const Breaks& breaks);

class BlockJudge {
public:
    /// The block whose frames are image[from, to) (its line, its end of block included), standing on
    /// line `line` (from 1) of the image's text; `damaged`: the frames to be decided (image indices).
    BlockJudge(const RepairSetup& setup, std::span<const Frame> image, std::size_t from, std::size_t to,
               std::uint64_t line, std::span<const std::size_t> damaged);

    Breaks judge(const BlockTry& t) const;
    /// The block's frames as the image has them.
    std::span<const Frame> frames() const { return frames_; }
    std::size_t from() const { return from_; }

private:
    LoadedTape load_with_context(const std::string& block_text) const;
    std::map<std::string, int> error_keys(const LoadedTape& t) const;
    std::map<std::string, int> by_rule(const std::map<std::string, int>& keys) const;
    bool tried_arc(const LoadedTape& t) const;
    bool tab_off_format(const BlockTry& t) const;
    void own_rules(const LoadedTape& t, const std::vector<std::pair<std::size_t, std::size_t>>& places,
                   Breaks& out) const;

    const RepairSetup& s_;
    std::vector<Frame> frames_;
    std::size_t from_;
    std::uint64_t line_;
    std::string before_, after_;  // context: the lines before and after the block, as text
    std::uint64_t before_lines_ = 0;
    std::map<std::string, int> baseline_;
    std::vector<std::pair<std::size_t, std::size_t>> spans_;  // the damaged words, columns from 1 inclusive
};

/// The block with `copies` copies of value where it has `written` from first_copy on, the copies
/// being decided.
BlockTry with_copies(std::span<const Frame> block, std::size_t first_copy, std::size_t written, std::size_t copies,
                     Frame value);

/// The text of frames as the decoder reads them (a bad frame as U+FFFD); places, when given, gets for
/// each frame of wanted (indices into frames) its line (from 0, in the text) and column (from 1, in
/// characters), column 0 for a frame that gives no character.
std::string block_text(const FrameCode& code, std::span<const Frame> frames, std::span<const std::size_t> wanted = {},
                       std::vector<std::pair<std::size_t, std::size_t>>* places = nullptr);

}  // namespace tape::detail
