// tape plot: a program's toolpath drawn (SVG, PNG, PDF, or an HTML page whose moves name their blocks),
// from its text or its tape; from a tape, the moves read from bad or doubtful frames in the doubt colour.
#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/outputs.hpp"
#include "cli/programs.hpp"
#include "commands.hpp"
#include "motion_input.hpp"
#include "tape/render.hpp"
#include "tape/restore_doubts.hpp"
#include "tape/toolpath.hpp"

namespace cli {
namespace {

// A tape longer than this is not drawn beside the toolpath in the HTML page (its picture would be
// metres long); the moves then name their frames without a link.
constexpr std::uint64_t max_tape_in_page = 20'000;

struct PlotArgs {
    std::string input = "-", output, view = "xy", title;
    ProgramSource source;
    MotionArgs motion;
    bool front_post = false, diameter = false, force = false;
    int width = 1200, height = 900;
};

tape::PlotOptions plot_options(const PlotArgs& a, const std::string& name) {
    tape::PlotOptions o;
    o.view = a.motion.lathe   ? tape::PlotView::lathe
             : a.view == "xz" ? tape::PlotView::xz
             : a.view == "yz" ? tape::PlotView::yz
                              : tape::PlotView::xy;
    if (a.motion.lathe && a.view != "xy")
        fail("", tape::Errc::usage, "--view is for mills: a lathe is drawn as its X-Z half profile");
    if (!a.motion.lathe && (a.front_post || a.diameter))
        fail("", tape::Errc::usage, "--front-post and --diameter are for lathes (--lathe)");
    o.front_post = a.front_post;
    o.diameter = a.diameter;
    o.width = a.width;
    o.height = a.height;
    o.title = a.title.empty() ? name : a.title;
    return o;
}

// Frames in doubt: those the loader read past as bad, and those the restoration's report beside the
// image left in doubt or guessed.
std::vector<std::uint64_t> plot_doubt_frames(const PlotArgs& a, const MotionRead& read) {
    std::vector<std::uint64_t> frames = read.bad_frames;
    if (a.input != "-")
        for (const auto& d : tape::doubts_beside(a.input))
            if (!d.left_out) frames.push_back(d.frame);
    return frames;
}

// The HTML page's tape picture (a tape short enough to draw) with an anchor at each block's first frame.
std::string tape_appendix(const PlotArgs& a, const MotionRead& read, const tape::Toolpath& path,
                          std::vector<std::uint64_t> doubtful) {
    if (!read.from_tape || a.input == "-") return {};  // stdin is read once
    TapeInput tape = read_tape(a.input, a.source.format);
    if (tape.frames.empty() || tape.frames.size() > max_tape_in_page) return {};
    tape::RenderOptions o;
    std::sort(doubtful.begin(), doubtful.end());
    doubtful.erase(std::unique(doubtful.begin(), doubtful.end()), doubtful.end());
    for (auto f : doubtful)
        if (f >= 1 && f <= tape.frames.size()) o.marks.push_back({f, tape::MarkKind::doubtful, "in doubt"});
    for (const auto& m : path.moves())
        if (m.frame && *m.frame <= tape.frames.size()) o.anchors.push_back(*m.frame);
    std::string svg = tape::render_svg(tape.frames, o);
    return "<h2>The tape</h2>\n" + svg.substr(std::min(svg.find("<svg"), svg.size()));
}

void write_plot(const PlotArgs& a, const MotionRead& read, const tape::Toolpath& path,
                const std::vector<std::uint64_t>& doubtful) {
    std::string_view format = tape::plot_format_for_path(a.output);
    tape::PlotOptions o = plot_options(a, read.name);
    o.per_block = format == "html";
    std::string bytes;
    try {
        tape::PlotPlan plan = tape::plan_plot(path, o);
        if (format == "html") {
            std::string appendix = tape_appendix(a, read, path, doubtful);
            auto link = [&](std::uint64_t frame) { return appendix.empty() ? "" : "#f" + std::to_string(frame); };
            bytes = tape::plot_html(plan, path, o.title, link, appendix);
        } else {
            auto drawn = tape::draw_plot(plan, format);
            bytes.assign(drawn.begin(), drawn.end());
        }
        if (globals().verbosity > 0)
            say(read.name, std::to_string(path.moves().size()) + " moves, " + std::to_string(plan.moves_drawn) +
                               " drawn (the rest under a pixel or over one drawn), " +
                               std::to_string(plan.strokes.size()) + " strokes; " +
                               std::to_string(plan.unplaced + path.unknown_moves()) +
                               " not drawn from a place not known (the first move, an axis not set yet, or after a "
                               "block not simulated)");
    } catch (const tape::Error& e) {
        fail(e.code() == tape::Errc::io ? "" : read.name, e);
    }
    write_output(a.output, bytes, format == "png" || format == "pdf", a.force);
}

void run(const PlotArgs& a) {
    std::string_view format = tape::plot_format_for_path(a.output);
    if (format.empty()) fail(a.output, tape::Errc::usage, "name the output .svg, .png, .pdf or .html");
    if (format != "html" && !tape::plot_available())
        fail("", tape::Errc::io, std::string(tape::plot_unavailable_message()));
    tape::Toolpath path(format == "html");
    MotionRead read =
        read_motion(a.input, a.source, a.motion, path, [&path](const tape::Block& b) { path.note_block(b); });
    std::vector<std::uint64_t> doubtful = plot_doubt_frames(a, read);
    path.mark_doubtful(doubtful);
    say_not_simulated(read.name, path.not_simulated(), path.not_simulated_count(), read.from_tape);
    write_plot(a, read, path, doubtful);
    end_motion(read);
}

}  // namespace

void add_plot(CLI::App& app) {
    auto a = std::make_shared<PlotArgs>();
    auto* sub = app.add_subcommand(
        "plot", "Draw a program's toolpath (text or tape) as SVG, PNG, PDF, or an HTML page naming each move's block");
    sub->add_option("input", a->input, "Program text or tape image; - or nothing for stdin");
    sub->add_option("-o,--output", a->output, "Picture to write: .svg, .png, .pdf or .html (- is not allowed)")
        ->required();
    add_program_source_options(sub, a->source);
    add_motion_options(sub, a->motion);
    sub->add_option("--view", a->view, "A mill seen from above (xy), the front (xz) or the side (yz)")
        ->check(CLI::IsMember({"xy", "xz", "yz"}))
        ->capture_default_str();
    sub->add_flag("--front-post", a->front_post, "Lathe: the tool in front of the spindle axis (+X drawn down)");
    sub->add_flag("--diameter", a->diameter, "Lathe: X drawn as the diameter (the profile stretched across)");
    sub->add_option("--width", a->width, "Picture width in pixels (PNG) or points (SVG, PDF, HTML)")
        ->check(whole_number(100, 20000))
        ->capture_default_str();
    sub->add_option("--height", a->height, "Picture height")->check(whole_number(100, 20000))->capture_default_str();
    sub->add_option("--title", a->title, "Written in the picture's corner (default: the input's name)");
    sub->add_flag("--force", a->force, "Replace the output if it exists");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
