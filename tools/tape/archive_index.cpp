// tape archive index: one HTML page for a folder of bags, to browse a collection offline: each bag's
// label, identifier, format, completeness, doubts, and the start of its tape drawn.
#include <algorithm>
#include <filesystem>

#include "archive_bag.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/outputs.hpp"
#include "tape/file_io.hpp"
#include "tape/render.hpp"

namespace cli {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t thumbnail_frames = 60;  // about 15 cm of tape from its first punched frame

std::string info_value(const std::vector<tape::BagInfoEntry>& info, const char* label) {
    return tape::bag_info_value(info, label).value_or("");
}

// The start of the last restoration's tape, drawn as one strip: a picture that needs no file beside the page.
std::string thumbnail(const fs::path& bag, const std::string& image) {
    TapeInput t = read_tape((bag / "data" / image).string(), "");
    if (t.frames.empty()) return "";
    auto first = std::find_if(t.frames.begin(), t.frames.end(), [](tape::Frame f) { return f != 0; });
    tape::RenderOptions o;
    o.from = first == t.frames.end() ? 1 : static_cast<std::uint64_t>(first - t.frames.begin()) + 1;
    o.to = std::min<std::uint64_t>(t.frames.size(), o.from + thumbnail_frames - 1);
    o.strip_mm = 1000;
    std::string svg = tape::render_svg(t.frames, o);
    svg.erase(0, svg.find("<svg"));
    return "<div class=\"thumb\">" + svg + "</div>";
}

std::string bag_row(const fs::path& dir, const fs::path& bag) {
    std::string info_path = (bag / "bag-info.txt").string();
    auto bytes = tape::path_exists(info_path) ? tape::read_file(info_path) : std::vector<std::uint8_t>{};
    auto info = tape::parse_bag_info(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    std::vector<BagRestoration> rs = bag_restorations(bag.string());
    std::string restorations;
    for (const auto& e : info)
        if (e.label == "Tape-Restoration") restorations += tape::xml_escaped(e.value) + "<br>";
    std::string link = bag.lexically_relative(dir).generic_string();
    std::string s =
        "<tr><td><a href=\"" + tape::xml_escaped(link) + "/data/" +
        (rs.empty() ? std::string("") : tape::xml_escaped(fs::path(rs.back().image).stem().string()) + ".html") +
        "\">" + tape::xml_escaped(link) + "</a></td><td>" + tape::xml_escaped(info_value(info, "Tape-Label")) +
        "</td><td>" + tape::xml_escaped(info_value(info, "External-Identifier")) + "</td><td>" +
        tape::xml_escaped(info_value(info, "Tape-Contents")) + "</td><td>" + restorations + "</td><td>" +
        tape::xml_escaped(info_value(info, "Payload-Oxum")) + " (bytes.files); bagged " +
        tape::xml_escaped(info_value(info, "Bagging-Date")) + "</td><td>";
    return s + (rs.empty() ? std::string() : thumbnail(bag, rs.back().image)) + "</td></tr>\n";
}

}  // namespace

void archive_index(const std::string& dir, const std::string& output, bool force) {
    std::string out = output.empty() ? (fs::path(dir) / "index.html").string() : output;
    refuse_existing(out, force);
    std::vector<fs::path> bags;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.is_directory() && fs::is_regular_file(e.path() / "bagit.txt")) bags.push_back(e.path());
    if (ec) fail(dir, tape::Errc::io, ec.message());
    std::sort(bags.begin(), bags.end());
    std::string s =
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'\">\n"
        "<title>Tapes in " +
        tape::xml_escaped(dir) +
        "</title>\n<style>body{font-family:sans-serif;margin:1.5em}table{border-collapse:collapse}td,th{border:1px "
        "solid #bbb;padding:.3em .5em;text-align:left;vertical-align:top}th{background:#eee}.thumb svg{width:24em;"
        "height:auto}</style>\n</head>\n<body>\n<h1>Tapes in " +
        tape::xml_escaped(dir) + "</h1>\n<p>" + std::to_string(bags.size()) +
        " bag(s). Their checksums are not checked here: <code>tape archive verify BAG</code> does.</p>\n"
        "<table>\n<tr><th>bag</th><th>label</th><th>identifier</th><th>contents</th><th>restorations</th>"
        "<th>payload</th><th>the tape's start</th></tr>\n";
    for (const auto& b : bags) s += bag_row(dir, b);
    s += "</table>\n</body>\n</html>\n";
    write_output(out, s, false, force);
    say(out, "index of " + std::to_string(bags.size()) + " bag(s) written");
}

}  // namespace cli
