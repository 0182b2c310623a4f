// The toolpath as an HTML page (tape/toolpath.hpp): the module's SVG inline, and over it each stroke
// again, invisible and wide, naming its blocks on hover and linking to the tape picture.
#include <cmath>
#include <cstdio>

#include "tape/render.hpp"
#include "tape/toolpath.hpp"

namespace tape {
namespace {

void put_number(std::string& out, double v) {
    char buf[32];
    int n = std::snprintf(buf, sizeof buf, "%.2f", v);
    out.append(buf, static_cast<std::size_t>(n));
}

void put_path(std::string& out, const PlotPlan& plan, const PlotStroke& s) {
    out += "<path d=\"";
    if (s.arc) {
        // An SVG arc cannot be a whole turn: drawn as two halves.
        double mid = (s.a0 + s.a1) / 2;
        auto at = [&](double a, char cmd) {
            out += cmd;
            put_number(out, s.cx + s.r * std::cos(a));
            out += ' ';
            put_number(out, s.cy + s.r * std::sin(a));
        };
        at(s.a0, 'M');
        for (double to : {mid, s.a1}) {
            out += " A";
            put_number(out, s.r);
            out += ' ';
            put_number(out, s.r);
            out += s.a1 > s.a0 ? " 0 0 1 " : " 0 0 0 ";
            at(to, ' ');
        }
    } else {
        const float* p = plan.points.data() + 2 * static_cast<std::size_t>(s.first);
        for (std::uint32_t k = 0; k < s.count; ++k) {
            out += k ? " L" : "M";
            put_number(out, p[2 * k]);
            out += ' ';
            put_number(out, p[2 * k + 1]);
        }
    }
    out += "\"/>";
}

// "N70 G02 X70. Y30. I0 J20. (line 9, frames 120-141)", and the last block when the stroke goes on.
std::string title_of(const Toolpath& path, const PlotStroke& s) {
    auto one = [&](std::uint32_t i) {
        const PathMove& m = path.moves()[i];
        std::string t(path.block_text(i));
        t += " (line " + std::to_string(m.line);
        if (m.frame)
            t += ", frame" + (m.last_frame && *m.last_frame != *m.frame
                                  ? "s " + std::to_string(*m.frame) + "-" + std::to_string(*m.last_frame)
                                  : " " + std::to_string(*m.frame));
        return t + (m.doubt ? ", in doubt)" : ")");
    };
    std::string t = one(s.move);
    if (path.moves()[s.last_move].block != path.moves()[s.move].block) t += "\n... " + one(s.last_move);
    return t;
}

}  // namespace

std::string plot_html(const PlotPlan& plan, const Toolpath& path, const std::string& title,
                      const std::function<std::string(std::uint64_t frame)>& link, std::string_view appendix) {
    std::vector<std::uint8_t> svg = draw_plot(plan, "svg");
    std::string_view picture(reinterpret_cast<const char*>(svg.data()), svg.size());
    if (auto at = picture.find("<svg"); at != std::string_view::npos)
        picture.remove_prefix(at);  // no <?xml ?> inside HTML
    std::string out = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + xml_escaped(title) +
                      "</title>\n<style>body{font-family:sans-serif;margin:0}h2{margin:16px}"
                      ".plot{position:relative}.plot>svg{position:absolute;left:0;top:0}"
                      ".hits path{fill:none;stroke:#000;stroke-opacity:0;stroke-width:7;pointer-events:stroke}"
                      ".hits path:hover{stroke:#ff0;stroke-opacity:0.6}:target{outline:3px solid #e0302a}"
                      "</style></head><body>\n";
    // The page's scale and origin, for the tests and scripts that look for a point of the part.
    char where[160];
    std::snprintf(where, sizeof where, " data-x0=\"%.6f\" data-y0=\"%.6f\" data-scale=\"%.6f\"", plan.x0, plan.y0,
                  plan.scale);
    out += "<div class=\"plot\"" + std::string(where) + " style=\"width:" + std::to_string(plan.width) +
           "px;height:" + std::to_string(plan.height) + "px\">\n";
    out.append(picture);
    out += "\n<svg class=\"hits\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(plan.width) +
           "\" height=\"" + std::to_string(plan.height) + "\">\n";
    for (const auto& s : plan.strokes) {
        const PathMove& m = path.moves()[s.move];
        std::string href = link && m.frame ? link(*m.frame) : std::string();
        if (!href.empty()) out += "<a href=\"" + xml_escaped(href) + "\">";
        out += "<g><title>" + xml_escaped(title_of(path, s)) + "</title>";
        put_path(out, plan, s);
        out += href.empty() ? "</g>\n" : "</g></a>\n";
    }
    out += "</svg></div>\n";
    out.append(appendix);
    out += "</body></html>\n";
    return out;
}

}  // namespace tape
