// Which way a tape read from a picture runs (scan_geometry.hpp). A picture shows a strip, not its
// start: the tape's own label reads one way only; text and programs read forwards one way (a block
// starts after its line end, a sign comes before its digits, CR before LF); and a blank leader is
// at the start. In that order: the first that decides is said, with its evidence.
#include <algorithm>
#include <string>

#include "scan/scan_geometry.hpp"
#include "tape/code.hpp"
#include "tape/detect.hpp"
#include "tape/label.hpp"

namespace tape {

std::string_view direction_basis_name(DirectionBasis b) {
    switch (b) {
        case DirectionBasis::label:
            return "label";
        case DirectionBasis::code:
            return "code";
        case DirectionBasis::leader:
            return "leader";
        case DirectionBasis::user:
            return "user";
        case DirectionBasis::none:
            return "none";
    }
    return "?";
}

}  // namespace tape

namespace tape::scan {
namespace {

bool upper(char c) { return c >= 'A' && c <= 'Z'; }
bool lower(char c) { return c >= 'a' && c <= 'z'; }
bool digit(char c) { return c >= '0' && c <= '9'; }
bool line_end(char c) { return c == '\n' || c == '\r'; }

// Pairs of characters that text and programs have read forwards: their count over the characters.
std::size_t forward_signs(const std::string& s) {
    std::size_t n = 0;
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
        char a = s[i], b = s[i + 1];
        n += line_end(a) && (upper(b) || b == '%' || b == ':' || b == '(' || b == '/');  // a block's start
        n += a == '\r' && b == '\n';
        n += (a == '+' || a == '-') && (digit(b) || b == '.');  // a signed number
        n += upper(a) && (digit(b) || b == '+' || b == '-');    // an address and its number
        n += upper(a) && lower(b);                              // a capitalised word
        n += a == '%' && line_end(b);                           // the program start
    }
    if (!s.empty() && line_end(s.back())) ++n;  // text ends with its line end
    return n;
}

// The punched part's characters, where the frames are text or a program in a code that fits them.
std::optional<std::string> characters(std::span<const Frame> frames, std::string& code_name) {
    auto punched = punched_part(frames);
    if (punched.empty()) return std::nullopt;
    CodeDetection d = detect_code(punched);
    if (d.kind == TapeKind::text) {  // frames that are the bytes of a text: ASCII with track 8 clear
        code_name = "ASCII text";
        return std::string(punched.begin(), punched.end());
    }
    if (!d.reading) return std::nullopt;
    FrameCode code = FrameCode::make(d.reading->code, d.reading->parity);
    std::string out;
    std::size_t bad = 0;
    for (Frame f : punched) {
        FrameKind k = code.kind(f);
        if (k == FrameKind::character) out += code.character(f);
        bad += is_bad_frame(k);
    }
    if (bad * 10 > punched.size()) return std::nullopt;
    code_name = reading_name(*d.reading);
    return out;
}

std::size_t blank_run(std::span<const Frame> frames) {
    auto it = std::find_if(frames.begin(), frames.end(), [](Frame f) { return f != blank_frame; });
    return static_cast<std::size_t>(it - frames.begin());
}

}  // namespace

DirectionChoice decide_direction(std::span<const Frame> frames, const DirectionEvidence& e, bool& reverse) {
    std::vector<Frame> back(frames.rbegin(), frames.rend());
    reverse = false;
    auto ahead = find_label(frames), behind = find_label(back);
    if (ahead.has_value() != behind.has_value()) {
        reverse = behind.has_value();
        return {DirectionBasis::label, false,
                "the leader label \"" + (reverse ? behind : ahead)->text + "\" reads this way"};
    }
    std::string code, text_seen = "no text";
    if (auto text = characters(frames, code)) {
        std::string backwards(text->rbegin(), text->rend());
        std::size_t f = forward_signs(*text), b = forward_signs(backwards);
        std::size_t most = std::max(f, b), least = std::min(f, b);
        std::string signs = std::to_string(most) +
                            " signs of text read forwards one way (line ends, block starts, signed numbers, words) "
                            "against " +
                            std::to_string(least) + " the other way";
        if (most >= 2 && most >= 2 * least + 1) {
            reverse = b > f;
            return {DirectionBasis::code, most < 4, "read as " + code + ", " + signs};
        }
        // Text that reads well enough both ways is there all the same: said, with its count.
        text_seen = "text read as " + code + " but too few signs of its direction, " + signs;
    }
    std::size_t lead = blank_run(frames), trail = blank_run(back);
    std::string ends = std::to_string(lead) + " blank frames at the first end" +
                       (e.start_cut ? " (cut by the picture)" : "") + ", " + std::to_string(trail) + " at the other" +
                       (e.end_cut ? " (cut by the picture)" : "");
    if (lead != trail && lead + trail < frames.size()) {
        reverse = trail > lead;
        std::size_t most = std::max(lead, trail), least = std::min(lead, trail);
        return {DirectionBasis::leader, most < 2 * least + 3, "the leader is the longer blank run: " + ends};
    }
    return {DirectionBasis::none, false, "nothing tells the direction (no label, " + text_seen + ", " + ends + ")"};
}

}  // namespace tape::scan
