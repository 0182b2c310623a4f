// tape show: the holes picture with frame numbers and characters, bad frames marked.
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/options.hpp"
#include "cli/outputs.hpp"
#include "cli/run.hpp"
#include "commands.hpp"
#include "tape/survey.hpp"
#include "tape_report.hpp"

namespace cli {
namespace {

struct ShowArgs {
    std::string input = "-", format;
    CodeChoice choice;
};

void run(const ShowArgs& a) {
    std::string name = display_name(a.input);
    auto in = open_input(a.input, input_options(a.choice, a.format, "image"));
    const tape::DecodeOptions& o = decide_code(*in, name);
    tape::FrameCode code = tape::FrameCode::make(o.code, o.parity, o.eia_table);
    auto writer = tape::find_image_format("holes")->make_writer(tape::ImageWriteOptions{&code});
    tape::Surveyor surveyor(code);
    std::string picture;
    std::optional<tape::LeaderLabel> label;
    try {
        // A leader label is drawn with its holes, but its frames are no characters to count as bad.
        label = in->label();
        std::uint64_t at = 0;
        std::vector<tape::Frame> scratch;
        for (auto frames = in->next_frames(); !frames.empty(); frames = in->next_frames()) {
            writer->write(frames, picture);
            surveyor.feed(tape::without_label(frames, at, label, scratch));
            at += frames.size();
            write_output("-", picture, false, false);
            picture.clear();
        }
    } catch (const tape::Error& e) {
        fail(name, e);
    }
    writer->finish(picture);
    write_output("-", picture, false, false);
    if (label && label->font == tape::LabelFont::title)
        say(name, "in the leader, " + leader_label_words(*label) + ": not characters");
    else if (label)
        say(name, "leader label " + label_text(*label) + ": letters of holes, not characters");
    auto s = surveyor.result();
    if (s.parity_errors + s.not_in_code > 0) {
        say(name, std::to_string(s.parity_errors) + " parity error(s), " + std::to_string(s.not_in_code) +
                      " frame(s) not in the code, marked '!'");
        throw Exit{bad_data};
    }
}

}  // namespace

void add_show(CLI::App& app) {
    auto a = std::make_shared<ShowArgs>();
    auto* sub = app.add_subcommand("show", "Draw the tape: holes, frame numbers, characters, bad frames marked '!'");
    sub->add_option("input", a->input, "Tape image; - or nothing for stdin");
    add_code_options(sub, a->choice, true, CodeSet::all);
    sub->add_option("--format,-f", a->format, "Image format of IN: " + format_choices(false))
        ->check(format_check(false));
    sub->callback([a] { run(*a); });
}

}  // namespace cli
