// Reads for restore, diff and tape-damage (restore_inputs.hpp).
#include "cli/restore_inputs.hpp"

namespace cli {

std::vector<TapeInput> read_all_bounded(const std::vector<std::string>& paths) {
    std::vector<TapeInput> out;
    for (const auto& p : paths) out.push_back(read_tape(p, ""));
    return out;
}

std::string unrelated_text(const tape::UnrelatedRead& e, const std::vector<TapeInput>& reads) {
    return "shares runs of frames with " + display_name(reads[e.reference()].name) + " over only " +
           std::to_string(static_cast<int>(e.anchored() * 100)) +
           "% of the runs that occur as often in each: a read of another tape, or too damaged to align";
}

}  // namespace cli
