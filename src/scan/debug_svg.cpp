// The picture with what tape scan found drawn over it (tape/scan.hpp), for people to check by eye:
// the feed line, each feed hole (seen, or placed between its neighbours), each track's place coloured
// by its reading, and a mark on every round blob that was looked at.
#include <cstdio>
#include <string>

#include "tape/render.hpp"
#include "tape/scan.hpp"

namespace tape {
namespace {

constexpr std::size_t most_blobs = 20000;  // a picture full of noise still makes a picture one can open

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", v);
    return buf;
}

std::string circle(ScanPoint c, double r, std::string_view style, std::string_view title = {}) {
    std::string s =
        "<circle cx=\"" + num(c.x) + "\" cy=\"" + num(c.y) + "\" r=\"" + num(r) + "\" " + std::string(style);
    if (title.empty()) return s + "/>\n";
    return s + "><title>" + xml_escaped(title) + "</title></circle>\n";
}

void draw_frames(const StripScan& s, std::string& out) {
    const double r_code = 0.36 * s.pitch_px, r_feed = 0.23 * s.pitch_px;
    const int tracks = 8;
    out += "<polyline class=\"feed-line\" fill=\"none\" stroke=\"#00a0ff\" stroke-width=\"1\" points=\"";
    for (const auto& f : s.frames) out += num(f.feed.x) + "," + num(f.feed.y) + " ";
    out += "\"/>\n";
    for (std::size_t i = 0; i < s.frames.size(); ++i) {
        const ScannedFrame& f = s.frames[i];
        std::string title = "frame " + std::to_string(i + 1) + ": " + frame_hex(f.frame) +
                            (f.doubt.empty() ? "" : " doubtful: " + f.doubt);
        out += circle(f.feed, r_feed,
                      f.feed_seen ? "class=\"feed\" fill=\"none\" stroke=\"#00c040\" stroke-width=\"2\""
                                  : "class=\"feed placed\" fill=\"none\" stroke=\"#ff8000\" stroke-width=\"2\"",
                      title);
        for (int t = 0; t < tracks; ++t) {
            if (f.hole[t].x == 0 && f.hole[t].y == 0) continue;
            bool doubtful = f.hole_confidence[t] < 0.5F, punched = has_track(f.frame, t + 1);
            std::string_view style = doubtful ? "class=\"doubtful\" fill=\"none\" stroke=\"#ff0000\" stroke-width=\"3\""
                                     : punched ? "class=\"punched\" fill=\"none\" stroke=\"#0050ff\" stroke-width=\"2\""
                                               : "class=\"blank\" fill=\"none\" stroke=\"#a0a0a0\" stroke-width=\"1\"";
            out += circle(f.hole[t], doubtful || punched ? r_code : r_code / 3, style,
                          "frame " + std::to_string(i + 1) + ", track " + std::to_string(t + 1));
        }
    }
}

}  // namespace

std::string scan_debug_svg(const ImageScan& image, std::string_view image_href) {
    std::string w = std::to_string(image.width), h = std::to_string(image.height);
    std::string out =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
        "xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"" +
        w + "\" height=\"" + h + "\" viewBox=\"0 0 " + w + " " + h + "\">\n<title>" + xml_escaped(image.name) +
        ": what tape scan found</title>\n<image href=\"" + xml_escaped(image_href) + "\" xlink:href=\"" +
        xml_escaped(image_href) + "\" x=\"0\" y=\"0\" width=\"" + w + "\" height=\"" + h + "\"/>\n";
    out += "<g class=\"blobs\" fill=\"#ff00ff\">\n";
    for (std::size_t i = 0; i < image.blobs.size() && i < most_blobs; ++i)
        out += "<rect x=\"" + num(image.blobs[i].x - 1) + "\" y=\"" + num(image.blobs[i].y - 1) +
               "\" width=\"2\" height=\"2\"/>\n";
    out += "</g>\n";
    if (image.strip) draw_frames(*image.strip, out);
    if (!image.refusal.empty())
        out += "<text x=\"10\" y=\"30\" font-size=\"24\" fill=\"#ff0000\">" +
               xml_escaped("not read: " + image.refusal) + "</text>\n";
    return out + "</svg>\n";
}

}  // namespace tape
