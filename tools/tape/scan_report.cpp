// What tape scan says about a read (scan_report.hpp): messages on stderr, the report as text or JSON
// (schema tape-scan/1), and the pictures with what was found drawn over them.
#include "scan_report.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/options.hpp"
#include "cli/outputs.hpp"

namespace cli {
namespace {

std::string fixed(double v, int decimals) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

// The read's frames that picture m gave, and its doubtful ones among them.
std::string direction_text(const tape::DirectionChoice& d) {
    if (d.basis == tape::DirectionBasis::none) return "direction not decided: " + d.reason;
    return "direction by the " + std::string(tape::direction_basis_name(d.basis)) + (d.weak ? " (weakly)" : "") + ": " +
           d.reason;
}

std::string strip_text(const tape::StripScan& s) {
    return std::to_string(s.frames.size()) + " frames, " + fixed(s.pitch_px, 2) + " px a frame (" + fixed(s.dpi, 0) +
           " dpi), skew " + fixed(s.skew_deg, 2) + "°, bow " + fixed(s.bow_mm, 2) + " mm, holes " +
           (s.holes_dark ? "dark" : "light") + ", seen from the " + (s.mirrored ? "back" : "front") + ", read " +
           (s.reversed ? "against" : "along") + " the picture's order; track order from " + s.track_order_basis;
}

nlohmann::json strip_json(const tape::ImageScan& im) {
    const tape::StripScan& s = *im.strip;
    nlohmann::json doubtful = nlohmann::json::array();
    for (std::size_t i = 0; i < s.frames.size(); ++i)
        if (!s.frames[i].doubt.empty()) doubtful.push_back({{"frame", i + 1}, {"why", s.frames[i].doubt}});
    return {{"frames", s.frames.size()},
            {"first_frame", im.first_frame},
            {"frames_used", im.frames_used},
            {"pitch_px", s.pitch_px},
            {"dpi", s.dpi},
            {"skew_deg", s.skew_deg},
            {"bow_mm", s.bow_mm},
            {"bend_deg", s.bend_deg},
            {"holes", s.holes_dark ? "dark" : "light"},
            {"mirrored", s.mirrored},
            {"reversed", s.reversed},
            {"track_order", s.track_order_basis},
            {"start_cut", s.start_cut},
            {"end_cut", s.end_cut},
            {"doubtful", doubtful}};
}

}  // namespace

void say_scan_findings(const tape::ScanResult& r, const std::string& output) {
    for (const auto& im : r.images) {
        if (!im.strip) say(im.name, "not read: " + im.refusal);
        for (const auto& n : im.notes) say(im.name, n);
    }
    for (const auto& g : r.gaps)
        say(output, "frame " + std::to_string(g.after) + ": a gap follows: " + g.before_image + " and " +
                        g.after_image + " do not overlap; the frames between them are missing (how many is unknown)");
    if (r.direction.basis == tape::DirectionBasis::none || r.direction.weak)
        say(output, direction_text(r.direction) + " (give --start to say where the tape starts)");
    say_frame_doubts(output, r.doubts);
}

void say_frame_doubts(const std::string& name, const tape::FrameDoubts& doubts) {
    std::uint64_t shown = 0, unshown = doubts.unkept;
    for (const auto& d : doubts.runs) {
        if (globals().max_errors && shown >= globals().max_errors) {
            unshown += d.last - d.first + 1;
            continue;
        }
        ++shown;
        std::string run = d.last > d.first ? "doubtful, to frame " + std::to_string(d.last) + ": " : "doubtful: ";
        say_diagnostic(name,
                       tape::Diagnostic{.code = tape::Errc::doubtful_frame,
                                        .where = tape::Position{.frame = d.first},
                                        .message = run + d.what,
                                        .severity = tape::Severity::warning},
                       false);
    }
    if (unshown) say_unlisted(name, unshown, "doubtful frame(s)");
}

std::string scan_report_text(const tape::ScanResult& r) {
    std::uint64_t doubtful = 0;
    for (const auto& d : r.doubts.runs) doubtful += d.last - d.first + 1;
    std::string out = "tape scan: " + std::to_string(r.frames.size()) + " frames from " +
                      std::to_string(r.images.size()) + " picture(s), " + std::to_string(doubtful) + " doubtful, " +
                      std::to_string(r.gaps.size()) + " gap(s); " + direction_text(r.direction) + "\n";
    for (const auto& im : r.images) {
        out += im.name + ": " + std::to_string(im.width) + "x" + std::to_string(im.height) + " px: ";
        out += im.strip
                   ? strip_text(*im.strip) + "; frames " + std::to_string(im.first_frame) + "-" +
                         std::to_string(im.first_frame + im.frames_used - (im.frames_used ? 1 : 0)) + " of the read\n"
                   : "not read: " + im.refusal + "\n";
        for (const auto& n : im.notes) out += "  " + n + "\n";
        if (!im.strip) continue;
        for (std::size_t i = 0; i < im.strip->frames.size(); ++i)
            if (!im.strip->frames[i].doubt.empty())
                out += "  frame " + std::to_string(i + 1) + " of the picture: " + im.strip->frames[i].doubt + "\n";
    }
    for (const auto& g : r.gaps)
        out += "gap after frame " + std::to_string(g.after) + ": " + g.before_image + " and " + g.after_image +
               " do not overlap\n";
    return out;
}

std::string scan_report_json(const tape::ScanResult& r) {
    nlohmann::json j;
    j["schema"] = "tape-scan/1";
    j["frames"] = r.frames.size();
    j["complete"] = r.complete();
    j["direction"] = {{"basis", tape::direction_basis_name(r.direction.basis)},
                      {"weak", r.direction.weak},
                      {"reason", r.direction.reason}};
    j["doubtful"] = nlohmann::json::array();
    for (const auto& d : r.doubts.runs)
        j["doubtful"].push_back({{"first", d.first}, {"last", d.last}, {"why", d.what}});
    j["gaps"] = nlohmann::json::array();
    for (const auto& g : r.gaps)
        j["gaps"].push_back({{"after", g.after}, {"before_image", g.before_image}, {"after_image", g.after_image}});
    j["images"] = nlohmann::json::array();
    for (const auto& im : r.images) {
        nlohmann::json e = {{"name", im.name}, {"width", im.width}, {"height", im.height}, {"notes", im.notes}};
        if (im.strip)
            e["strip"] = strip_json(im);
        else
            e["refusal"] = im.refusal;
        j["images"].push_back(e);
    }
    return j.dump(2) + "\n";
}

void write_debug_pictures(const tape::ScanResult& r, const std::string& path, bool force) {
    namespace fs = std::filesystem;
    for (std::size_t m = 0; m < r.images.size(); ++m) {
        std::string out = path;
        if (r.images.size() > 1) {
            fs::path p(path);
            out =
                (p.parent_path() / (p.stem().string() + "-" + std::to_string(m + 1) + p.extension().string())).string();
        }
        // The picture is linked by its path from the SVG's folder, so the two can move together.
        std::error_code ec;
        fs::path base = fs::absolute(fs::path(out).parent_path(), ec);
        std::string href = fs::relative(fs::absolute(r.images[m].name, ec), base, ec).string();
        if (href.empty()) href = fs::absolute(r.images[m].name, ec).string();
        write_output(out, tape::scan_debug_svg(r.images[m], href), false, force);
    }
}

}  // namespace cli
