// One restoration of a bag's reads, with everything tape archive keeps of it (archive_bag.hpp), and the
// restorations a bag holds.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "archive_bag.hpp"
#include "archive_contents.hpp"
#include "cli/machines.hpp"
#include "cli/messages.hpp"
#include "cli/outputs.hpp"
#include "restore_html.hpp"
#include "restore_run.hpp"
#include "tape/file_io.hpp"
#include "tape/label.hpp"
#include "tape/picture.hpp"
#include "tape/render.hpp"
#include "tape/restore_doubts.hpp"
#include "tape/scan.hpp"
#include "tape_report.hpp"

namespace cli {
namespace {

// The whole tape is drawn up to this many frames (about 50 m of tape, some megabytes of SVG); a longer one,
// its start, and the file says so.
constexpr std::uint64_t most_drawn_frames = 20000;

std::string tape_svg(const RestoreReportInput& in, const std::string& html) {
    const tape::RestoreResult& r = *in.result;
    tape::RenderOptions o;
    o.code = in.code ? &*in.code : nullptr;
    o.to = std::min<std::uint64_t>(r.frames.size(), most_drawn_frames);
    for (const auto& p : r.problems)
        if (p.frame && *p.frame <= o.to)
            o.marks.push_back({*p.frame, tape::in_doubt(p.status) ? tape::MarkKind::doubtful : tape::MarkKind::restored,
                               std::string(tape::status_name(p.status)) + ": " + p.reason,
                               html + "#p" + std::to_string(*p.frame)});
    if (auto label = tape::find_label(r.frames)) o.label_first = label->first + 1, o.label_frames = label->frames;
    return tape::render_svg(r.frames, o);
}

// The start of the tape as it looks, as tape render draws a .png (the picture module's renderer): strips of
// half a metre one under the other at 50 dpi, a picture of some 1000 by 700 pixels that tape scan reads
// back strip by strip. Some metres are enough to show the tape; the SVG draws it frame by frame.
constexpr std::uint64_t most_pictured_frames = 2000;

std::vector<std::uint8_t> tape_png(std::span<const tape::Frame> frames) {
    if (!tape::scan_available()) throw tape::Error(tape::Errc::io, std::string(tape::scan_unavailable_message()));
    tape::RasterOptions r{.dpi = 50, .strip_mm = 500};
    return tape::encode_picture(tape::render_picture(frames.first(std::min(frames.size(), most_pictured_frames)), r),
                                "png");
}

// tapeS.svg and tapeS.png; what they draw, in words for formatS.txt.
std::string add_drawings(tape::BagWriter& bag, const RestoreReportInput& report, const std::string& suffix,
                         const std::string& html) {
    const std::vector<tape::Frame>& frames = report.result->frames;
    if (frames.empty()) return "";
    const std::string svg = "tape" + suffix + ".svg", png = "tape" + suffix + ".png";
    bag.add(svg, tape_svg(report, html));
    std::string words = frames.size() > most_drawn_frames
                            ? svg + " draws its first " + std::to_string(most_drawn_frames) + " frames of " +
                                  std::to_string(frames.size()) + ".\n"
                            : "";
    std::vector<std::uint8_t> bytes;
    try {
        bytes = tape_png(frames);
    } catch (const tape::Error& e) {  // no picture module: the bag is whole without its picture, and says so
        say("data/" + png, std::string("not drawn: ") + e.what());
        return words + png + " is not drawn: " + e.what() + "\n";
    }
    bag.add(png, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    return words + png + " pictures " +
           (frames.size() > most_pictured_frames ? "its first " + std::to_string(most_pictured_frames) + " frames"
                                                 : std::string("the tape")) +
           " as it looks, in strips of 500 mm at 50 dpi.\n";
}

std::uint64_t in_doubt_count(const tape::RestoreResult& r) {
    std::uint64_t n = 0;
    for (std::size_t k = 0; k < tape::frame_status_count; ++k)
        if (tape::in_doubt(static_cast<tape::FrameStatus>(k))) n += r.count(static_cast<tape::FrameStatus>(k));
    return n;
}

std::string shell_quoted(const std::string& s) {
    if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=.,/:@%") ==
                          std::string::npos)
        return s;
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

}  // namespace

std::string RestorationSummary::words() const {
    return image + " from " + std::to_string(reads) + " read(s), code " + code + ": " + std::to_string(frames) +
           " frames, " +
           (complete      ? "complete"
            : unchecked   ? "nothing checked (one read of a tape in no character code: no vote, no parity)"
            : code_misfit ? "not complete (most frames fail the code: only voted)"
                          : std::to_string(in_doubt) + " in doubt, not complete");
}

RestorationSummary add_restoration(tape::BagWriter& bag, const std::string& suffix,
                                   const std::vector<std::string>& paths, const std::vector<std::string>& names,
                                   const tape::MachineProfile* machine) {
    ReadsAndDoubts in = read_tapes_or_pictures(paths);
    RestoreReportInput report;
    report.code = code_for_reads("auto", "", in.reads, report.code_text);
    report.names = names;
    describe_reads(in, report);
    RestoreChoices choices;
    choices.machine = machine;
    tape::RestoreResult result = run_restore(choices, in, report);
    report.result = &result;
    say_about_reads(report, result);
    RestorationSummary s;
    s.image = "restored" + suffix + ".ptp";
    s.code = report.code_text;
    const std::string html = "restored" + suffix + ".html";
    tape::ImageWriteOptions wo;
    if (report.code) wo.annotate = &*report.code;
    report.image_bytes = image_text(output_format("", s.image), result.frames, wo, s.image);
    report.image_name = s.image;
    // The page links each place to the whole tape drawn, where the drawing holds the whole tape.
    if (!result.frames.empty() && result.frames.size() <= most_drawn_frames)
        report.tape_picture = "tape" + suffix + ".svg";
    bag.add(s.image, report.image_bytes);
    // Told before the report is beside the image: tape info would read the report's doubts (megabytes of
    // JSON for a long tape) and say nothing of them.
    const std::string shown = "data/" + s.image, info = tape_info_text(bag.staging() + "/" + shown, shown);
    bag.add(tape::doubts_file_for(s.image), restore_report_json(report));
    bag.add(html, restore_report_html(report));
    std::string drawn = add_drawings(bag, report, suffix, html);
    for (const auto& f : tape_contents(result.frames, report.code, "contents" + suffix, s.contents))
        bag.add(f.path, f.bytes);
    bag.add("format" + suffix + ".txt", "The restored tape " + shown + ", from " + std::to_string(names.size()) +
                                            " read(s), in the words of tape info.\n" +
                                            (s.contents.empty() ? "" : "Contents: " + s.contents + ".\n") + drawn +
                                            "\n" + info);
    s.reads = names.size();
    s.frames = result.frames.size();
    s.in_doubt = in_doubt_count(result);
    s.complete = result.complete();
    s.unchecked = result.unchecked;
    s.code_misfit = result.code_misfit;
    return s;
}

std::optional<tape::MachineProfile> bag_machine(const std::string& bag) {
    std::string path = bag + "/data/" + bag_machine_file;
    if (!tape::path_exists(path)) return std::nullopt;
    return machine_or_fail(path, path);
}

std::string machine_profile_text(const tape::MachineProfile& profile) {
    if (profile.file == "built-in")
        for (const auto& m : tape::bundled_machines())
            if (m.name == profile.name) return std::string(m.text);
    try {
        auto bytes = tape::read_file(profile.file);
        return std::string(bytes.begin(), bytes.end());
    } catch (const tape::Error& e) {
        fail(profile.file, e);
    }
}

std::vector<BagRestoration> bag_restorations(const std::string& bag) {
    std::vector<BagRestoration> out;
    for (int n = 1;; ++n) {
        std::string image = n == 1 ? "restored.ptp" : "restored-" + std::to_string(n) + ".ptp";
        std::string report = bag + "/data/" + tape::doubts_file_for(image);
        if (!tape::path_exists(report)) break;
        BagRestoration r{image, {}};
        try {
            auto bytes = tape::read_file(report);
            auto j = nlohmann::json::parse(bytes.begin(), bytes.end());
            for (const auto& read : j.at("reads")) r.reads.push_back(read.at("file").get<std::string>());
        } catch (const std::exception& e) {
            fail(report, tape::Errc::bad_image, std::string("not a restore report: ") + e.what());
        }
        out.push_back(std::move(r));
    }
    return out;
}

std::string command_line() {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::string s = "tape";
    std::size_t start = all.find('\0');  // the program's own path is said as "tape"
    while (start != std::string::npos && start + 1 < all.size()) {
        std::size_t end = all.find('\0', start + 1);
        s += " " + shell_quoted(all.substr(start + 1, end - start - 1));
        start = end;
    }
    return s;
}

}  // namespace cli
