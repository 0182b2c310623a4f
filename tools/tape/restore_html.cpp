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
.tape svg g#legend{display:none}.legend span{display:inline-block;width:1em;height:1em;margin:0 .3em 0 1em;
vertical-align:middle;opacity:.6}section.place{border-top:1px solid #ccc;margin-top:1em}
)";

// The one legend of the page: the drawings' own are hidden (each snippet would repeat it).
constexpr std::string_view legend_html =
    "<p class=\"legend\" id=\"legend\">On the drawings:<span style=\"background:#e0302a\"></span>parity error"
    "<span style=\"background:#2a9d4a\"></span>restored (voted or repaired: now right)"
    "<span style=\"background:#e69a1c\"></span>doubtful (to check); track 8 on top, 2.54 mm a frame.</p>\n";

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

// Stretches of the tape drawn on the page so far (first, last frame): a frame has one id on the page.
using Drawn = std::vector<std::pair<std::uint64_t, std::uint64_t>>;

bool is_drawn(const Drawn& drawn, std::uint64_t frame) {
    return std::any_of(drawn.begin(), drawn.end(),
                       [&](const auto& d) { return frame >= d.first && frame <= d.second; });
}

constexpr std::uint64_t line_reach = 80;  // frames looked at each way for a program line's ends

// Frames from..to (1-based) of the restored tape as the code reads them, the problem's own marked.
std::string frames_html(const RestoreReportInput& in, const tape::RestoreProblem& p, std::uint64_t from,
                        std::uint64_t to) {
    const auto& frames = in.result->frames;
    std::uint64_t at = p.frame ? *p.frame : p.after;  // 1-based; for a frame left out, the one before it
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

// The frames around a problem: context on each side.
std::string context_html(const RestoreReportInput& in, const tape::RestoreProblem& p) {
    const auto& frames = in.result->frames;
    if (frames.empty()) return "";
    std::uint64_t at = p.frame ? *p.frame : p.after;
    std::uint64_t from = at > context ? at - context : 1, to = std::min<std::uint64_t>(at + context, frames.size());
    return frames_html(in, p, from, to);
}

// The program line a problem falls in: from the end of block before it to the one after (line_reach frames
// each way at most); without a code, the frames around it.
std::string line_html(const RestoreReportInput& in, const tape::RestoreProblem& p) {
    const auto& frames = in.result->frames;
    std::uint64_t at = p.frame ? *p.frame : p.after;
    if (!in.code || at == 0 || at > frames.size()) return context_html(in, p);
    auto end_of_block = [&](std::uint64_t f) {
        tape::Frame x = frames[f - 1];
        return in.code->kind(x) == tape::FrameKind::character && in.code->character(x) == '\n';
    };
    std::uint64_t from = at, to = at;
    while (from > 1 && at - from < line_reach && !end_of_block(from - 1)) --from;
    while (to < frames.size() && to - at < line_reach && !end_of_block(to)) ++to;
    return frames_html(in, p, from, to);
}

std::string seen_text(const RestoreReportInput& in, const tape::RestoreProblem& p, std::size_t i) {
    return p.seen[i] ? tape::xml_escaped(frame_text(in.code, *p.seen[i])) : p.covered[i] ? "none" : "not read";
}

// A row of the folded table of restored places, linked to its frame drawn on the page, else on the picture
// of the whole tape when there is one.
std::string problem_row(const RestoreReportInput& in, const tape::RestoreProblem& p, const Drawn& drawn) {
    std::uint64_t target = p.frame ? *p.frame : p.after;
    bool on_page = target >= 1 && is_drawn(drawn, target);
    std::string tape = on_page ? "" : in.tape_picture;
    bool linked = (on_page || !tape.empty()) && target >= 1 && target <= in.result->frames.size();
    std::string where = problem_place(p);
    std::string s =
        "<tr class=\"" + row_class(p.status) + "\"" + (p.frame ? " id=\"p" + std::to_string(*p.frame) + "\"" : "") +
        "><td>" +
        (linked ? "<a href=\"" + tape + "#f" + std::to_string(target) + "\">" + tape::xml_escaped(where) + "</a>"
                : tape::xml_escaped(where)) +
        "</td><td>" + (p.line ? std::to_string(*p.line) : "") + "</td><td>" + (p.frame ? centimetres(*p.frame) : "") +
        "</td><td class=\"status\">" + std::string(tape::status_name(p.status)) + "</td>";
    for (std::size_t i = 0; i < p.seen.size(); ++i) s += "<td><code>" + seen_text(in, p, i) + "</code></td>";
    bool written = p.frame && p.status != tape::FrameStatus::missing;
    s += "<td><code>" + (written ? tape::xml_escaped(frame_text(in.code, p.written)) : std::string("-")) +
         "</code></td><td>" + context_html(in, p) + "</td><td>" + tape::xml_escaped(p.reason) + "</td></tr>\n";
    return s;
}

// The restored tape drawn around one place, every problem frame in it marked and linked to its place (#pN);
// "" when the place is drawn already (the stretch is cut short of the stretches drawn before).
std::string drawing_html(const RestoreReportInput& in, const tape::RestoreProblem& p, Drawn& drawn) {
    const tape::RestoreResult& r = *in.result;
    const std::uint64_t n = r.frames.size();
    std::uint64_t at = p.frame ? *p.frame : std::max<std::uint64_t>(p.after, 1);
    if (n == 0 || at > n || is_drawn(drawn, at)) return "";
    tape::RenderOptions o;
    o.code = in.code ? &*in.code : nullptr;
    o.from = at > context ? at - context : 1, o.to = std::min(at + context, n);
    for (const auto& d : drawn) {
        if (d.second < at && d.second >= o.from) o.from = d.second + 1;
        if (d.first > at && d.first <= o.to) o.to = d.first - 1;
    }
    drawn.emplace_back(o.from, o.to);
    for (const auto& q : r.problems)
        if (q.frame && *q.frame >= o.from && *q.frame <= o.to)
            o.marks.push_back({*q.frame, mark_for(q.status), std::string(tape::status_name(q.status)) + ": " + q.reason,
                               "#p" + std::to_string(*q.frame)});
    if (auto label = tape::find_label(r.frames)) o.label_first = label->first + 1, o.label_frames = label->frames;
    std::string svg = tape::render_svg(r.frames, o);
    svg.erase(0, svg.find("<svg"));  // the XML declaration has no place inside HTML
    return "<div class=\"tape\" id=\"tape" + std::to_string(drawn.size()) + "\" data-from=\"" + std::to_string(o.from) +
           "\" data-to=\"" + std::to_string(o.to) + "\">\n" + svg + "</div>\n";
}

// A place to check: what each read has there, the program line, what was written, the alternatives and the
// rule that left it open, the tape drawn around it (drawing, when drawn here), and links to the tape.
std::string place_html(const RestoreReportInput& in, const tape::RestoreProblem& p, const std::string& drawing,
                       bool on_page) {
    std::uint64_t target = p.frame ? *p.frame : p.after;
    std::string where = tape::xml_escaped(problem_place(p));
    std::string s =
        "<section class=\"place doubtful\"" + (p.frame ? " id=\"p" + std::to_string(*p.frame) + "\"" : "") + "><h3>" +
        (on_page && target ? "<a href=\"#f" + std::to_string(target) + "\">" + where + "</a>" : where) +
        (p.line ? ", line " + std::to_string(*p.line) : "") + (p.frame ? ", " + centimetres(*p.frame) : "") + ": " +
        std::string(tape::status_name(p.status)) + "</h3>\n<p>Left open because: " + tape::xml_escaped(p.reason) +
        "</p>\n<p>In the program line: " + line_html(in, p) +
        "</p>\n<table class=\"reads\">\n<tr><th>read</th><th>file</th><th>its frame here</th></tr>\n";
    for (std::size_t i = 0; i < p.seen.size(); ++i)
        s += "<tr><td>" + std::to_string(i + 1) + "</td><td>" + tape::xml_escaped(display_name(in.names[i])) +
             "</td><td><code>" + seen_text(in, p, i) + "</code></td></tr>\n";
    bool written = p.frame && p.status != tape::FrameStatus::missing;
    s += "<tr><th colspan=\"2\">" + std::string(written ? "written" : "not written") + "</th><td><code>" +
         (p.status == tape::FrameStatus::missing ? std::string("-")
                                                 : tape::xml_escaped(frame_text(in.code, p.written))) +
         "</code></td></tr>\n";
    for (std::size_t c = 0; c < p.candidates.size(); ++c)
        s += "<tr><th colspan=\"2\">alternative " + std::to_string(c + 1) + "</th><td><code>" +
             tape::xml_escaped(frame_text(in.code, p.candidates[c])) + "</code></td></tr>\n";
    s += "</table>\n" + drawing;
    if (!in.tape_picture.empty() && target >= 1 && target <= in.result->frames.size())
        s += "<p><a href=\"" + tape::xml_escaped(in.tape_picture) + "#f" + std::to_string(target) +
             "\">This place on the whole tape</a></p>\n";
    return s + "</section>\n";
}

}  // namespace

std::string restore_report_html(const RestoreReportInput& in) {
    const tape::RestoreResult& r = *in.result;
    std::string title = "Restored tape from " + std::to_string(in.names.size()) + " read(s)";
    std::string s = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    // Nothing may be fetched or run: the page is read where no network is.
    s += "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'\">\n";
    s += "<title>" + tape::xml_escaped(title) + "</title>\n<style>\n" + std::string(style) +
         "</style>\n</head>\n<body>\n<h1>" + tape::xml_escaped(title) + "</h1>\n" + summary_html(in) +
         std::string(legend_html);
    if (!in.tape_picture.empty())
        s += "<p><a href=\"" + tape::xml_escaped(in.tape_picture) + "\">The whole tape drawn</a></p>\n";
    // The places a person must look at first, each whole; those decided after, folded.
    std::vector<const tape::RestoreProblem*> doubtful, decided;
    for (const auto& p : r.problems) (tape::in_doubt(p.status) ? doubtful : decided).push_back(&p);
    s += "<h2 id=\"doubtful\">Places to check: " + std::to_string(doubtful.size()) + "</h2>\n";
    if (doubtful.empty()) s += "<p>None: every frame is clean, or a vote or a repair decided it.</p>\n";
    Drawn drawn;
    for (std::size_t k = 0; k < std::min(doubtful.size(), most_rows); ++k) {
        const auto& p = *doubtful[k];
        std::string drawing = drawn.size() < most_drawn ? drawing_html(in, p, drawn) : "";
        std::uint64_t at = p.frame ? *p.frame : p.after;
        s += place_html(in, p, drawing, at && is_drawn(drawn, at));
    }
    if (doubtful.size() > most_rows)
        s += "<p>" + std::to_string(doubtful.size() - most_rows) +
             " more places in doubt: see the text or JSON report.</p>\n";
    if (drawn.size() == most_drawn)
        s += "<p>The tape is drawn around the first " + std::to_string(most_drawn) + " places only.</p>\n";
    s += "<h2 id=\"restored\">Places restored: " + std::to_string(decided.size()) + "</h2>\n";
    if (decided.empty()) s += "<p>None.</p>\n";
    if (!decided.empty()) {
        // Folded to keep the places to check in sight; open when there are none to check.
        s += std::string(doubtful.empty() ? "<details open>" : "<details>") + "<summary>" +
             std::to_string(decided.size()) +
             " frames a vote or a repair decided, or read by a minority and not written: folded, as they need no "
             "check</summary>\n";
        for (std::size_t k = 0; k < std::min(decided.size(), most_rows); ++k)
            if (drawn.size() < most_drawn) s += drawing_html(in, *decided[k], drawn);  // doubts drawn first
        s += "<table id=\"problems\">\n<tr><th>frame</th><th>line</th><th>from the start</th><th>status</th>";
        for (std::size_t i = 0; i < in.names.size(); ++i) s += "<th>read " + std::to_string(i + 1) + "</th>";
        s += "<th>written</th><th>around it</th><th>reason</th></tr>\n";
        for (std::size_t k = 0; k < std::min(decided.size(), most_rows); ++k) s += problem_row(in, *decided[k], drawn);
        s += "</table>\n";
        if (decided.size() > most_rows)
            s += "<p>" + std::to_string(decided.size() - most_rows) + " more: see the text or JSON report.</p>\n";
        s += "</details>\n";
    }
    s += "</body>\n</html>\n";
    return s;
}

}  // namespace cli
