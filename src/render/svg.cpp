// The tape drawn to scale as SVG (tape/render.hpp). The user unit is a hundredth of a millimetre, so
// that every coordinate is a whole number: written fast and the same on every machine.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

#include "tape/error.hpp"
#include "tape/render.hpp"

namespace tape {

std::string_view mark_name(MarkKind kind) {
    switch (kind) {
        case MarkKind::parity:
            return "parity error";
        case MarkKind::restored:
            return "restored";
        case MarkKind::doubtful:
            return "doubtful";
    }
    return "?";
}

namespace svg_geometry {

std::uint64_t frames_per_strip(double strip_mm) {
    double n = std::floor(strip_mm * 100 / pitch);
    return n < 1 ? 1 : static_cast<std::uint64_t>(n);
}

Point hole_centre(std::uint64_t n, int track, std::uint64_t per_strip, bool mirror) {
    // Rows from the top edge, 1..9: tracks 8..4, the feed holes, tracks 3..1 (mirror: the other way).
    int row = track == 0 ? 6 : track >= 4 ? 9 - track : 10 - track;
    if (mirror) row = 10 - row;
    auto strip = static_cast<std::int64_t>(n / per_strip), at = static_cast<std::int64_t>(n % per_strip);
    return {left + at * pitch + pitch / 2, legend + strip * strip_pitch + numbers + row * pitch};
}

}  // namespace svg_geometry

namespace {

using namespace svg_geometry;

constexpr std::string_view mark_colour[] = {"#e0302a", "#2a9d4a", "#e69a1c"};  // by MarkKind

void put(std::string& out, std::int64_t v) {
    char buf[24];
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

// Hundredths of a millimetre as millimetres: 2540 -> "25.40".
void put_mm(std::string& out, std::int64_t v) {
    put(out, v / 100);
    out += '.';
    out += static_cast<char>('0' + v % 100 / 10);
    out += static_cast<char>('0' + v % 10);
}

void put_escaped(std::string& out, std::string_view s) {
    for (char c : s) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
}

// What is written beside a frame: the character, a control's name, '!' or '?' for a bad frame.
std::string frame_text(const FrameCode& code, Frame f) {
    switch (code.kind(f)) {
        case FrameKind::character: {
            char c = code.character(f);
            if (c > ' ' && c < 0x7F) return std::string(1, c);
            return char_label(c);
        }
        case FrameKind::parity_error:
            return "!";
        case FrameKind::not_in_code:
            return "?";
        default:
            return "";
    }
}

}  // namespace

std::string xml_escaped(std::string_view s) {
    std::string out;
    put_escaped(out, s);
    return out;
}

std::string render_svg(std::span<const Frame> frames, const RenderOptions& o) {
    std::uint64_t last = o.to ? o.to : frames.size();
    if (o.from > last && last <= frames.size())
        throw Error(Errc::usage, "the first frame drawn (" + std::to_string(o.from) + ") is after the last (" +
                                     std::to_string(last) + ")");
    if (o.from < 1 || last > frames.size())
        throw Error(Errc::usage, "frames " + std::to_string(o.from) + " to " + std::to_string(last) +
                                     ": the tape has " + std::to_string(frames.size()) + " frames");
    auto drawn = frames.subspan(o.from - 1, last + 1 - o.from);
    const std::uint64_t per = frames_per_strip(o.strip_mm);
    const std::uint64_t strips = drawn.empty() ? 1 : (drawn.size() + per - 1) / per;
    const std::int64_t strip_frames =
        static_cast<std::int64_t>(std::min<std::uint64_t>(per, std::max<std::size_t>(drawn.size(), 1)));
    const std::int64_t width = std::max<std::int64_t>(left + strip_frames * pitch + 300, 19000);
    const std::int64_t height = legend + static_cast<std::int64_t>(strips) * strip_pitch;

    auto in_label = [&](std::uint64_t frame) {
        return frame >= o.label_first && frame < o.label_first + o.label_frames;
    };
    // The marks of the frames drawn, by frame: the caller's, then the bad frames the code shows.
    std::multimap<std::uint64_t, const FrameMark*> marks;
    for (const auto& m : o.marks)
        if (m.frame >= o.from && m.frame <= last) marks.emplace(m.frame, &m);
    std::vector<FrameMark> found;
    if (o.code) {
        for (std::size_t i = 0; i < drawn.size(); ++i) {
            auto k = o.code->kind(drawn[i]);
            // A frame the caller marked is said by its mark (a restoration's verdict says more).
            if (is_bad_frame(k) && !marks.contains(o.from + i) && !in_label(o.from + i))
                found.push_back({o.from + i, MarkKind::parity,
                                 k == FrameKind::parity_error ? "parity error" : "not a character of the code"});
        }
        for (const auto& m : found) marks.emplace(m.frame, &m);
    }

    std::string out;
    out.reserve(2048 + drawn.size() * 200);
    out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
    put_mm(out, width);
    out += "mm\" height=\"";
    put_mm(out, height);
    out += "mm\" viewBox=\"0 0 ";
    put(out, width);
    out += ' ';
    put(out, height);
    out += "\" font-family=\"DejaVu Sans Mono, monospace\">\n<title>punched tape, frames ";
    put(out, static_cast<std::int64_t>(o.from));
    out += '-';
    put(out, static_cast<std::int64_t>(last));
    out += "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";

    // The legend: what the shading means and which way the tape is seen.
    out += "<g id=\"legend\" font-size=\"280\">\n";
    std::int64_t lx = 300;
    for (int k = 0; k < 3; ++k) {
        out += "<rect x=\"";
        put(out, lx);
        out += "\" y=\"200\" width=\"300\" height=\"300\" fill=\"";
        out += mark_colour[k];
        out += "\" fill-opacity=\"0.45\"/><text x=\"";
        put(out, lx + 400);
        out += "\" y=\"460\">";
        out += mark_name(static_cast<MarkKind>(k));
        out += "</text>\n";
        lx += 4000;
    }
    out += "<text x=\"";
    put(out, lx);
    out += "\" y=\"460\">";
    out += o.mirror ? "track 1 on top (mirrored)" : "track 8 on top";
    out += ", 2.54 mm a frame</text>\n</g>\n";

    // Each strip: the paper, the shading of marked frames, the holes, the numbers and characters.
    for (std::uint64_t s = 0; s < strips; ++s) {
        std::uint64_t begin = s * per, end = std::min<std::uint64_t>(begin + per, drawn.size());
        std::int64_t top = legend + static_cast<std::int64_t>(s) * strip_pitch + numbers;
        out += "<rect class=\"tape\" x=\"";
        put(out, left);
        out += "\" y=\"";
        put(out, top);
        out += "\" width=\"";
        put(out, static_cast<std::int64_t>(std::max<std::uint64_t>(end - begin, 1)) * pitch);
        out += "\" height=\"2540\" fill=\"#f3e6bf\" stroke=\"#a8925a\" stroke-width=\"20\"/>\n";
        for (auto it = marks.lower_bound(o.from + begin); it != marks.end() && it->first < o.from + end; ++it) {
            const FrameMark& m = *it->second;
            if (!m.link.empty()) {
                out += "<a href=\"";
                put_escaped(out, m.link);
                out += "\">";
            }
            out += "<rect id=\"f";
            put(out, static_cast<std::int64_t>(m.frame));
            if (it != marks.begin() && std::prev(it)->first == it->first) {  // ids stay unique
                out += '-';
                out += mark_name(m.kind).substr(0, 1);
            }
            out += "\" class=\"mark ";
            out += m.kind == MarkKind::parity ? "parity" : m.kind == MarkKind::restored ? "restored" : "doubtful";
            out += "\" x=\"";
            put(out, left + static_cast<std::int64_t>(m.frame - o.from - begin) * pitch);
            out += "\" y=\"";
            put(out, top);
            out += "\" width=\"254\" height=\"2540\" fill=\"";
            out += mark_colour[static_cast<int>(m.kind)];
            out += "\" fill-opacity=\"0.45\"><title>frame ";
            put(out, static_cast<std::int64_t>(m.frame));
            out += ": ";
            put_escaped(out, m.note.empty() ? mark_name(m.kind) : std::string_view(m.note));
            out += "</title></rect>";
            out += m.link.empty() ? "\n" : "</a>\n";
        }
        out += "<g fill=\"#1b1b1b\">\n";
        for (std::uint64_t n = begin; n < end; ++n) {
            Frame f = drawn[n];
            for (int t = 0; t <= 8; ++t) {
                if (t > 0 && !has_track(f, t)) continue;
                auto c = hole_centre(n, t, per, o.mirror);
                out += "<circle cx=\"";
                put(out, c.x);
                out += "\" cy=\"";
                put(out, c.y);
                out += t == 0 ? "\" r=\"58.5\"/>" : "\" r=\"91.5\"/>";
            }
            out += '\n';
        }
        out += "</g>\n<g font-size=\"250\" text-anchor=\"middle\" fill=\"#333333\">\n";
        for (std::uint64_t n = begin; n < end; ++n) {
            std::uint64_t number = o.from + n;
            if (number % 10 != 0 && n != begin) continue;
            auto x = left + static_cast<std::int64_t>(n - begin) * pitch + pitch / 2;
            out += "<text x=\"";
            put(out, x);
            out += "\" y=\"";
            put(out, top - 150);
            out += "\">";
            put(out, static_cast<std::int64_t>(number));
            out += "</text>\n";
        }
        out += "</g>\n";
        if (o.code) {
            out += "<g font-size=\"200\" text-anchor=\"middle\">\n";
            for (std::uint64_t n = begin; n < end; ++n) {
                std::string t = in_label(o.from + n) ? std::string() : frame_text(*o.code, drawn[n]);
                if (t.empty()) continue;
                out += "<text x=\"";
                put(out, left + static_cast<std::int64_t>(n - begin) * pitch + pitch / 2);
                out += "\" y=\"";
                put(out, top + tape_width + 300);
                out += t.size() > 1 ? "\" font-size=\"110\">" : "\">";
                put_escaped(out, t);
                out += "</text>\n";
            }
            out += "</g>\n";
        }
    }
    out += "</svg>\n";
    return out;
}

}  // namespace tape
