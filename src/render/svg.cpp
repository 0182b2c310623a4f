// The tape drawn to scale as SVG (tape/render.hpp). The user unit is a hundredth of a millimetre, so
// that every coordinate is a whole number: written fast and the same on every machine.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <map>

#include "tape/error.hpp"
#include "tape/render.hpp"
#include "tape/utf8_text.hpp"

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

// Text from outside (a doubts file's reasons, a label) as XML: controls (ESC, BEL: no XML document may
// hold them) and bytes that are no UTF-8 shown as decode's messages show them (\x1B), then escaped.
void put_escaped(std::string& out, std::string_view text) {
    for (char c : visible(text)) {
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

namespace {

// Writes one SVG document a strip at a time: each strip's marks are found as it is drawn, so memory
// stays that of one strip whatever the length of the tape.
class SvgWriter {
public:
    SvgWriter(std::span<const Frame> frames, const RenderOptions& o, const std::function<void(std::string_view)>& sink)
        : o_(o), sink_(sink) {
        std::uint64_t last = o.to ? o.to : frames.size();
        if (o.from > last && last <= frames.size())
            throw Error(Errc::usage, "the first frame drawn (" + std::to_string(o.from) + ") is after the last (" +
                                         std::to_string(last) + ")");
        if (o.from < 1 || last > frames.size())
            throw Error(Errc::usage, "frames " + std::to_string(o.from) + " to " + std::to_string(last) +
                                         ": the tape has " + std::to_string(frames.size()) + " frames");
        last_ = last;
        drawn_ = frames.subspan(o.from - 1, last + 1 - o.from);
        per_ = frames_per_strip(o.strip_mm);
        strips_ = drawn_.empty() ? 1 : (drawn_.size() + per_ - 1) / per_;
        for (const auto& m : o.marks)
            if (m.frame >= o.from && m.frame <= last) marks_.emplace(m.frame, &m);
        anchors_ = o.anchors;
        std::sort(anchors_.begin(), anchors_.end());
        anchors_.erase(std::unique(anchors_.begin(), anchors_.end()), anchors_.end());
    }

    void write() {
        header();
        for (std::uint64_t s = 0; s < strips_; ++s) strip(s);
        out_ += "</svg>\n";
        flush();
    }

private:
    bool in_label(std::uint64_t frame) const {
        return frame >= o_.label_first && frame < o_.label_first + o_.label_frames;
    }
    void flush() {
        sink_(out_);
        out_.clear();
    }
    void header();
    void strip(std::uint64_t s);
    void strip_marks(std::uint64_t begin, std::uint64_t end, std::int64_t top);
    void mark(const FrameMark& m, bool repeated, std::uint64_t begin, std::int64_t top);
    void holes(std::uint64_t begin, std::uint64_t end);
    void frame_numbers(std::uint64_t begin, std::uint64_t end, std::int64_t top);
    void frame_characters(std::uint64_t begin, std::uint64_t end, std::int64_t top);

    const RenderOptions& o_;
    const std::function<void(std::string_view)>& sink_;
    std::span<const Frame> drawn_;
    std::uint64_t last_ = 0, per_ = 1, strips_ = 1;
    std::multimap<std::uint64_t, const FrameMark*> marks_;  // the caller's
    std::vector<std::uint64_t> anchors_;                    // sorted, once each
    std::string out_;
};

void SvgWriter::header() {
    const std::int64_t strip_frames =
        static_cast<std::int64_t>(std::min<std::uint64_t>(per_, std::max<std::size_t>(drawn_.size(), 1)));
    const std::int64_t width = std::max<std::int64_t>(left + strip_frames * pitch + 300, 19000);
    const std::int64_t height = legend + static_cast<std::int64_t>(strips_) * strip_pitch;
    out_ += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
    put_mm(out_, width);
    out_ += "mm\" height=\"";
    put_mm(out_, height);
    out_ += "mm\" viewBox=\"0 0 ";
    put(out_, width);
    out_ += ' ';
    put(out_, height);
    out_ += "\" font-family=\"DejaVu Sans Mono, monospace\">\n<title>punched tape, frames ";
    put(out_, static_cast<std::int64_t>(o_.from));
    out_ += '-';
    put(out_, static_cast<std::int64_t>(last_));
    out_ += "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    // The legend: what the shading means and which way the tape is seen.
    out_ += "<g id=\"legend\" font-size=\"280\">\n";
    std::int64_t lx = 300;
    for (int k = 0; k < 3; ++k) {
        out_ += "<rect x=\"";
        put(out_, lx);
        out_ += "\" y=\"200\" width=\"300\" height=\"300\" fill=\"";
        out_ += mark_colour[k];
        out_ += "\" fill-opacity=\"0.45\"/><text x=\"";
        put(out_, lx + 400);
        out_ += "\" y=\"460\">";
        out_ += mark_name(static_cast<MarkKind>(k));
        out_ += "</text>\n";
        lx += 4000;
    }
    out_ += "<text x=\"";
    put(out_, lx);
    out_ += "\" y=\"460\">";
    out_ += o_.mirror ? "track 1 on top (mirrored)" : "track 8 on top";
    out_ += ", 2.54 mm a frame</text>\n</g>\n";
}

// Each strip: the paper, the shading of marked frames, the holes, the numbers and characters.
void SvgWriter::strip(std::uint64_t s) {
    std::uint64_t begin = s * per_, end = std::min<std::uint64_t>(begin + per_, drawn_.size());
    std::int64_t top = legend + static_cast<std::int64_t>(s) * strip_pitch + numbers;
    out_ += "<rect class=\"tape\" x=\"";
    put(out_, left);
    out_ += "\" y=\"";
    put(out_, top);
    out_ += "\" width=\"";
    put(out_, static_cast<std::int64_t>(std::max<std::uint64_t>(end - begin, 1)) * pitch);
    out_ += "\" height=\"2540\" fill=\"#f3e6bf\" stroke=\"#a8925a\" stroke-width=\"20\"/>\n";
    strip_marks(begin, end, top);
    holes(begin, end);
    frame_numbers(begin, end, top);
    if (o_.code) frame_characters(begin, end, top);
    flush();
}

// The caller's marks on the strip's frames, then the bad frames the code shows where the caller has none
// (a restoration's verdict says more), in frame order.
void SvgWriter::strip_marks(std::uint64_t begin, std::uint64_t end, std::int64_t top) {
    std::multimap<std::uint64_t, const FrameMark*> here(marks_.lower_bound(o_.from + begin),
                                                        marks_.lower_bound(o_.from + end));
    std::vector<FrameMark> found;
    if (o_.code) {
        for (std::uint64_t i = begin; i < end; ++i) {
            auto k = o_.code->kind(drawn_[i]);
            if (is_bad_frame(k) && !marks_.contains(o_.from + i) && !in_label(o_.from + i))
                found.push_back({o_.from + i, MarkKind::parity,
                                 k == FrameKind::parity_error ? "parity error" : "not a character of the code"});
        }
        for (const auto& m : found) here.emplace(m.frame, &m);
    }
    for (auto it = here.begin(); it != here.end(); ++it)
        mark(*it->second, it != here.begin() && std::prev(it)->first == it->first, begin, top);
    // Anchors for links, where no mark has the frame's id already.
    for (auto a = std::lower_bound(anchors_.begin(), anchors_.end(), o_.from + begin);
         a != anchors_.end() && *a < o_.from + end; ++a) {
        if (here.contains(*a)) continue;
        out_ += "<rect id=\"f";
        put(out_, static_cast<std::int64_t>(*a));
        out_ += "\" class=\"anchor\" x=\"";
        put(out_, left + static_cast<std::int64_t>(*a - o_.from - begin) * pitch);
        out_ += "\" y=\"";
        put(out_, top);
        out_ += "\" width=\"254\" height=\"2540\" fill=\"none\"/>\n";
    }
}

void SvgWriter::mark(const FrameMark& m, bool repeated, std::uint64_t begin, std::int64_t top) {
    if (!m.link.empty()) {
        out_ += "<a href=\"";
        put_escaped(out_, m.link);
        out_ += "\">";
    }
    out_ += "<rect id=\"f";
    put(out_, static_cast<std::int64_t>(m.frame));
    if (repeated) {  // ids stay unique
        out_ += '-';
        out_ += mark_name(m.kind).substr(0, 1);
    }
    out_ += "\" class=\"mark ";
    out_ += m.kind == MarkKind::parity ? "parity" : m.kind == MarkKind::restored ? "restored" : "doubtful";
    out_ += "\" x=\"";
    put(out_, left + static_cast<std::int64_t>(m.frame - o_.from - begin) * pitch);
    out_ += "\" y=\"";
    put(out_, top);
    out_ += "\" width=\"254\" height=\"2540\" fill=\"";
    out_ += mark_colour[static_cast<int>(m.kind)];
    out_ += "\" fill-opacity=\"0.45\"><title>frame ";
    put(out_, static_cast<std::int64_t>(m.frame));
    out_ += ": ";
    put_escaped(out_, m.note.empty() ? mark_name(m.kind) : std::string_view(m.note));
    out_ += "</title></rect>";
    out_ += m.link.empty() ? "\n" : "</a>\n";
}

void SvgWriter::holes(std::uint64_t begin, std::uint64_t end) {
    out_ += "<g fill=\"#1b1b1b\">\n";
    for (std::uint64_t n = begin; n < end; ++n) {
        Frame f = drawn_[n];
        for (int t = 0; t <= 8; ++t) {
            if (t > 0 && !has_track(f, t)) continue;
            auto c = hole_centre(n, t, per_, o_.mirror);
            out_ += "<circle cx=\"";
            put(out_, c.x);
            out_ += "\" cy=\"";
            put(out_, c.y);
            out_ += t == 0 ? "\" r=\"58.5\"/>" : "\" r=\"91.5\"/>";
        }
        out_ += '\n';
    }
    out_ += "</g>\n";
}

std::int64_t digits(std::uint64_t n) { return static_cast<std::int64_t>(std::to_string(n).size()); }

// Frame numbers: the strip's first, and every tenth frame whose number does not run into the first's.
void SvgWriter::frame_numbers(std::uint64_t begin, std::uint64_t end, std::int64_t top) {
    constexpr std::int64_t digit_width = 150;  // of a digit at font-size 250, monospace, with room
    out_ += "<g font-size=\"250\" text-anchor=\"middle\" fill=\"#333333\">\n";
    for (std::uint64_t n = begin; n < end; ++n) {
        std::uint64_t number = o_.from + n;
        if (number % 10 != 0 && n != begin) continue;
        auto apart = static_cast<std::int64_t>(n - begin) * pitch;
        if (n != begin && 2 * apart < (digits(number) + digits(o_.from + begin)) * digit_width + 100) continue;
        out_ += "<text x=\"";
        put(out_, left + apart + pitch / 2);
        out_ += "\" y=\"";
        put(out_, top - 150);
        out_ += "\">";
        put(out_, static_cast<std::int64_t>(number));
        out_ += "</text>\n";
    }
    out_ += "</g>\n";
}

void SvgWriter::frame_characters(std::uint64_t begin, std::uint64_t end, std::int64_t top) {
    out_ += "<g font-size=\"200\" text-anchor=\"middle\">\n";
    for (std::uint64_t n = begin; n < end; ++n) {
        std::string t = in_label(o_.from + n) ? std::string() : frame_text(*o_.code, drawn_[n]);
        if (t.empty()) continue;
        out_ += "<text x=\"";
        put(out_, left + static_cast<std::int64_t>(n - begin) * pitch + pitch / 2);
        out_ += "\" y=\"";
        put(out_, top + tape_width + 300);
        out_ += t.size() > 1 ? "\" font-size=\"110\">" : "\">";
        put_escaped(out_, t);
        out_ += "</text>\n";
    }
    out_ += "</g>\n";
}

}  // namespace

void render_svg(std::span<const Frame> frames, const RenderOptions& options,
                const std::function<void(std::string_view)>& sink) {
    SvgWriter(frames, options, sink).write();
}

std::string render_svg(std::span<const Frame> frames, const RenderOptions& options) {
    std::string out;
    render_svg(frames, options, [&out](std::string_view piece) { out += piece; });
    return out;
}

}  // namespace tape
