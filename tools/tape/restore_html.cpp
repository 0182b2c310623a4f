// tape restore --html: the report as a page to look at, the tape drawn around its problem frames.
#include "restore_html.hpp"

#include <algorithm>
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

std::string row_class(tape::FrameStatus s) {
    return s == tape::FrameStatus::extra ? "extra" : mark_for(s) == tape::MarkKind::restored ? "restored" : "doubtful";
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
code{font-family:"DejaVu Sans Mono",monospace;white-space:pre}.tape{overflow-x:auto}mark{background:#f6dcb0}
:target{outline:3px solid #1565c0}tr:target td{background:#dbe9fb}
)";

constexpr std::uint64_t context = 8;  // frames drawn and quoted on each side of a problem

std::string summary_html(const RestoreReportInput& in) {
    const tape::RestoreResult& r = *in.result;
    std::string s =
        "<section id=\"summary\">\n<p>" + std::to_string(r.frames.size()) + " frames restored, code " +
        tape::xml_escaped(in.code_text) + ", aligned to read " + std::to_string(r.reference + 1) + ". " +
        (r.complete() ? "Every frame is clean, voted or inferred."
                      : "<strong>Not every frame could be decided:</strong> see the doubtful frames below.") +
        "</p>\n<table id=\"reads\">\n<tr><th>read</th><th>file</th><th>frames</th><th>shared with the "
        "reference</th></tr>\n";
    for (std::size_t i = 0; i < in.names.size(); ++i)
        s += "<tr><td>" + std::to_string(i + 1) + "</td><td>" + tape::xml_escaped(display_name(in.names[i])) +
             "</td><td>" + std::to_string(in.sizes[i]) + "</td><td>" +
             (r.related[i] ? percent(r.shared[i]) : "left out: another tape") + "</td></tr>\n";
    s += "</table>\n<table id=\"counts\">\n<tr>";
    for (std::size_t k = 0; k < tape::frame_status_count; ++k)
        s += "<th>" + std::string(tape::status_name(static_cast<tape::FrameStatus>(k))) + "</th>";
    s += "<th>voted on a run length</th></tr>\n<tr>";
    for (std::size_t k = 0; k < tape::frame_status_count; ++k)
        s += "<td>" + std::to_string(r.count(static_cast<tape::FrameStatus>(k))) + "</td>";
    return s + "<td>" + std::to_string(r.run_length_votes) + "</td></tr>\n</table>\n</section>\n";
}

// The frames around a problem as the code reads them, the problem's own marked.
std::string context_html(const RestoreReportInput& in, const tape::RestoreProblem& p) {
    const auto& frames = in.result->frames;
    if (frames.empty()) return "";
    std::uint64_t at = p.frame ? *p.frame : p.after;  // 1-based; for a frame left out, the one before it
    std::uint64_t from = at > context ? at - context : 1, to = std::min<std::uint64_t>(at + context, frames.size());
    std::string s;
    for (std::uint64_t f = from; f <= to; ++f) {
        tape::Frame x = frames[f - 1];
        std::string c = !in.code                                         ? tape::frame_hex(x).substr(2) + " "
                        : in.code->kind(x) == tape::FrameKind::character ? tape::char_label(in.code->character(x))
                        : is_bad_frame(in.code->kind(x))                 ? "?"
                                                                         : "";
        if (c == "LF" || c == "CR") c = "\u21b5";
        s += f == at && p.frame ? "<mark>" + tape::xml_escaped(c) + "</mark>" : tape::xml_escaped(c);
        if (f == at && !p.frame) s += "<mark>^</mark>";
    }
    return "<code>" + s + "</code>";
}

std::string problem_row(const RestoreReportInput& in, const tape::RestoreProblem& p, bool drawn) {
    std::uint64_t target = p.frame ? *p.frame : p.after;
    bool linked = drawn && target >= 1 && target <= in.result->frames.size();
    std::string where = problem_place(p);
    std::string s = "<tr class=\"" + row_class(p.status) + "\"" +
                    (p.frame && linked ? " id=\"p" + std::to_string(*p.frame) + "\"" : "") + "><td>" +
                    (linked ? "<a href=\"#f" + std::to_string(target) + "\">" + tape::xml_escaped(where) + "</a>"
                            : tape::xml_escaped(where)) +
                    "</td><td>" + (p.line ? std::to_string(*p.line) : "") + "</td><td>" +
                    (p.frame ? centimetres(*p.frame) : "") + "</td><td class=\"status\">" +
                    std::string(tape::status_name(p.status)) + "</td>";
    for (std::size_t i = 0; i < p.seen.size(); ++i)
        s += "<td><code>" +
             (p.seen[i]      ? tape::xml_escaped(frame_text(in.code, *p.seen[i]))
              : p.covered[i] ? "none"
                             : "not read") +
             "</code></td>";
    bool written = p.frame && p.status != tape::FrameStatus::missing;
    s += "<td><code>" + (written ? tape::xml_escaped(frame_text(in.code, p.written)) : std::string("-")) +
         "</code></td><td>" + context_html(in, p) + "</td><td>" + tape::xml_escaped(p.reason) + "</td></tr>\n";
    return s;
}

// Stretches of the tape around the problems, close ones joined: (first, last) frames, 1-based.
std::vector<std::pair<std::uint64_t, std::uint64_t>> stretches(const tape::RestoreResult& r) {
    std::vector<std::pair<std::uint64_t, std::uint64_t>> out;
    const std::uint64_t n = r.frames.size();
    for (const auto& p : r.problems) {
        std::uint64_t at = p.frame ? *p.frame : std::max<std::uint64_t>(p.after, 1);
        if (n == 0 || at > n) continue;
        std::uint64_t from = at > context ? at - context : 1, to = std::min(at + context, n);
        if (!out.empty() && from <= out.back().second + 1)
            out.back().second = std::max(out.back().second, to);
        else
            out.emplace_back(from, to);
    }
    return out;
}

std::string tape_html(const RestoreReportInput& in, std::size_t& drawn_to) {
    const tape::RestoreResult& r = *in.result;
    auto parts = stretches(r);
    drawn_to = 0;
    std::string s = "<h2>The restored tape around its problems</h2>\n";
    if (parts.size() > most_drawn)
        s += "<p>Drawn around the first " + std::to_string(most_drawn) + " of " + std::to_string(parts.size()) +
             " stretches with problems; the table lists them all.</p>\n";
    auto label = tape::find_label(r.frames);
    for (std::size_t k = 0; k < std::min(parts.size(), most_drawn); ++k) {
        tape::RenderOptions o;
        o.code = in.code ? &*in.code : nullptr;
        o.from = parts[k].first, o.to = parts[k].second;
        for (const auto& p : r.problems)
            if (p.frame && *p.frame >= o.from && *p.frame <= o.to)
                o.marks.push_back({*p.frame, mark_for(p.status),
                                   std::string(tape::status_name(p.status)) + ": " + p.reason,
                                   "#p" + std::to_string(*p.frame)});
        if (label) o.label_first = label->first + 1, o.label_frames = label->frames;
        std::string svg = tape::render_svg(r.frames, o);
        svg.erase(0, svg.find("<svg"));  // the XML declaration has no place inside HTML
        s += "<div class=\"tape\" id=\"tape" + std::to_string(k + 1) + "\" data-from=\"" + std::to_string(o.from) +
             "\" data-to=\"" + std::to_string(o.to) + "\">\n" + svg + "</div>\n";
        drawn_to = parts[k].second;
    }
    return s;
}

}  // namespace

std::string restore_report_html(const RestoreReportInput& in) {
    const tape::RestoreResult& r = *in.result;
    std::string title = "Restored tape from " + std::to_string(in.names.size()) + " read(s)";
    std::string s = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    // Nothing may be fetched or run: the page is read where no network is.
    s += "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'\">\n";
    s += "<title>" + tape::xml_escaped(title) + "</title>\n<style>\n" + std::string(style) +
         "</style>\n</head>\n<body>\n<h1>" + tape::xml_escaped(title) + "</h1>\n" + summary_html(in);
    std::size_t drawn_to = 0;
    s += tape_html(in, drawn_to);
    s += "<h2>Problem frames</h2>\n<table id=\"problems\">\n<tr><th>frame</th><th>line</th><th>from the start</th>"
         "<th>status</th>";
    for (std::size_t i = 0; i < in.names.size(); ++i) s += "<th>read " + std::to_string(i + 1) + "</th>";
    s += "<th>written</th><th>around it</th><th>reason</th></tr>\n";
    std::size_t rows = 0;
    for (const auto& p : r.problems) {
        if (rows++ == most_rows) break;
        std::uint64_t at = p.frame ? *p.frame : p.after;
        s += problem_row(in, p, at <= drawn_to);
    }
    s += "</table>\n";
    if (r.problems.size() > most_rows)
        s += "<p>" + std::to_string(r.problems.size() - most_rows) +
             " more problem frames: see the text or JSON report.</p>\n";
    if (r.problems.empty()) s += "<p>No problem frames.</p>\n";
    s += "</body>\n</html>\n";
    return s;
}

}  // namespace cli
