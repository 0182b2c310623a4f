// tape restore --html: the report as a page to look at, the tape drawn with its problem frames marked.
#include "restore_html.hpp"

#include <cstdio>

#include "cli/inputs.hpp"
#include "tape/label.hpp"
#include "tape/render.hpp"

namespace cli {
namespace {

// Decided frames are right now; the others are what a person must look at.
tape::MarkKind mark_for(tape::FrameStatus s) {
    return s == tape::FrameStatus::voted || s == tape::FrameStatus::inferred ? tape::MarkKind::restored
                                                                             : tape::MarkKind::doubtful;
}

std::string percent(double share) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f%%", share * 100);
    return buf;
}

std::string centimetres(std::uint64_t frame) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f cm", tape::frame_distance_cm(frame));
    return buf;
}

constexpr std::string_view style = R"(body{font-family:sans-serif;margin:1.5em;color:#222}
table{border-collapse:collapse;margin:.8em 0}td,th{border:1px solid #bbb;padding:.2em .5em;text-align:left}
th{background:#eee}tr.restored td.status{background:#cfe8d5}tr.doubtful td.status{background:#f6dcb0}
code{font-family:"DejaVu Sans Mono",monospace;white-space:pre}.tape{overflow-x:auto}
:target{outline:3px solid #1565c0}tr:target td{background:#dbe9fb}
)";

}  // namespace

std::string restore_report_html(const RestoreReportInput& in) {
    const tape::RestoreResult& r = *in.result;
    std::string title = "Restored tape from " + std::to_string(in.names.size()) + " read(s)";
    std::string s = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    // Nothing may be fetched or run: the page is read where no network is.
    s += "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'\">\n";
    s += "<title>" + tape::xml_escaped(title) + "</title>\n<style>\n" + std::string(style) +
         "</style>\n</head>\n<body>\n";
    s += "<h1>" + tape::xml_escaped(title) + "</h1>\n<section id=\"summary\">\n<p>" + std::to_string(r.frames.size()) +
         " frames restored, code " + tape::xml_escaped(in.code_text) + ", aligned to read " +
         std::to_string(r.reference + 1) + ". " +
         (r.complete() ? "Every frame is clean, voted or inferred."
                       : "<strong>Not every frame could be decided:</strong> see the doubtful frames below.") +
         "</p>\n<table id=\"reads\">\n<tr><th>read</th><th>file</th><th>frames</th><th>shared with the "
         "reference</th></tr>\n";
    for (std::size_t i = 0; i < in.names.size(); ++i)
        s += "<tr><td>" + std::to_string(i + 1) + "</td><td>" + tape::xml_escaped(display_name(in.names[i])) +
             "</td><td>" + std::to_string(in.sizes[i]) + "</td><td>" + percent(r.shared[i]) + "</td></tr>\n";
    s += "</table>\n<table id=\"counts\">\n<tr>";
    for (std::size_t k = 0; k < tape::frame_status_count; ++k)
        s += "<th>" + std::string(tape::status_name(static_cast<tape::FrameStatus>(k))) + "</th>";
    s += "</tr>\n<tr>";
    for (std::size_t k = 0; k < tape::frame_status_count; ++k)
        s += "<td>" + std::to_string(r.count(static_cast<tape::FrameStatus>(k))) + "</td>";
    s += "</tr>\n</table>\n</section>\n";

    // The tape, each problem frame marked with its status and reason as the mark's tooltip.
    auto on_tape = [&](std::uint64_t frame) { return frame >= 1 && frame <= r.frames.size(); };
    tape::RenderOptions o;
    o.code = in.code ? &*in.code : nullptr;
    for (const auto& p : r.problems)
        if (p.frame && on_tape(*p.frame))
            o.marks.push_back({*p.frame, mark_for(p.status), std::string(tape::status_name(p.status)) + ": " + p.reason,
                               "#p" + std::to_string(*p.frame)});
    if (auto label = tape::find_label(r.frames)) {
        o.label_first = label->first + 1;
        o.label_frames = label->frames;
    }
    std::string svg = tape::render_svg(r.frames, o);
    svg.erase(0, svg.find("<svg"));  // the XML declaration has no place inside HTML
    s += "<h2>The restored tape</h2>\n<div class=\"tape\" id=\"tape\">\n" + svg + "</div>\n";

    s += "<h2>Problem frames</h2>\n<table id=\"problems\">\n<tr><th>frame</th><th>line</th><th>from the start</th>"
         "<th>status</th>";
    for (std::size_t i = 0; i < in.names.size(); ++i) s += "<th>read " + std::to_string(i + 1) + "</th>";
    s += "<th>written</th><th>reason</th></tr>\n";
    for (const auto& p : r.problems) {
        std::string where = p.frame ? std::to_string(*p.frame) : "after " + std::to_string(p.after);
        std::uint64_t target = p.frame ? *p.frame : p.after;
        s += "<tr class=\"" +
             std::string(p.status == tape::FrameStatus::extra             ? "extra"
                         : mark_for(p.status) == tape::MarkKind::restored ? "restored"
                                                                          : "doubtful") +
             "\"" + (p.frame && on_tape(*p.frame) ? " id=\"p" + std::to_string(*p.frame) + "\"" : "") + "><td>";
        s += on_tape(target) ? "<a href=\"#f" + std::to_string(target) + "\">" + tape::xml_escaped(where) + "</a>"
                             : tape::xml_escaped(where);
        s += "</td><td>" + (p.line ? std::to_string(*p.line) : "") + "</td><td>" +
             (p.frame ? centimetres(*p.frame) : "") + "</td><td class=\"status\">" +
             std::string(tape::status_name(p.status)) + "</td>";
        for (std::size_t i = 0; i < p.seen.size(); ++i)
            s += "<td><code>" +
                 (p.seen[i]      ? tape::xml_escaped(frame_text(in.code, *p.seen[i]))
                  : p.covered[i] ? "none"
                                 : "not read") +
                 "</code></td>";
        s += "<td><code>" +
             (p.status == tape::FrameStatus::missing ? std::string("-")
                                                     : tape::xml_escaped(frame_text(in.code, p.written))) +
             "</code></td><td>" + tape::xml_escaped(p.reason) + "</td></tr>\n";
    }
    s += "</table>\n";
    if (r.problems.empty()) s += "<p>No problem frames.</p>\n";
    s += "</body>\n</html>\n";
    return s;
}

}  // namespace cli
