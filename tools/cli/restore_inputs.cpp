// Reads for restore and diff, read whole within the frames a paper tape can hold (restore_inputs.hpp).
#include "cli/restore_inputs.hpp"

#include <sys/stat.h>

#include "cli/messages.hpp"

namespace cli {
namespace {

[[noreturn]] void too_long(const std::string& name) {
    fail(display_name(name), tape::Errc::bad_image,
         "more than " + std::to_string(tape::max_read_frames) +
             " frames (254 km of tape): no paper tape is that long; restore, diff and tape-damage take reads up to "
             "that length");
}

}  // namespace

TapeInput read_bounded(const std::string& path, const std::string& format_id) {
    TapeInput in;
    in.name = path.empty() ? "-" : path;
    tape::InputOptions o = input_options(CodeChoice{}, format_id, "image");
    o.detect_code = false;
    auto input = open_input(in.name, o);
    in.format = input->format();
    struct stat st {};
    if (in.name != "-" && in.format && in.format->bytes_are_frames && ::stat(in.name.c_str(), &st) == 0 &&
        S_ISREG(st.st_mode) && static_cast<std::uint64_t>(st.st_size) > tape::max_read_frames)
        too_long(in.name);
    try {
        for (auto frames = input->next_frames(); !frames.empty(); frames = input->next_frames()) {
            if (in.frames.size() + frames.size() > tape::max_read_frames) too_long(in.name);
            in.frames.insert(in.frames.end(), frames.begin(), frames.end());
        }
    } catch (const tape::Error& e) {
        fail(display_name(in.name), e);
    }
    return in;
}

std::vector<TapeInput> read_all_bounded(const std::vector<std::string>& paths) {
    std::vector<TapeInput> out;
    for (const auto& p : paths) out.push_back(read_bounded(p));
    return out;
}

std::string unrelated_text(const tape::UnrelatedRead& e, const std::vector<TapeInput>& reads) {
    return "shares runs of frames with " + display_name(reads[e.reference()].name) + " over only " +
           std::to_string(static_cast<int>(e.anchored() * 100)) +
           "% of the runs that occur as often in each: a read of another tape, or too damaged to align";
}

}  // namespace cli
