#include "plot/page.hpp"

#include <algorithm>

namespace tape::plot {
namespace {
// Room for the title above and the scale bar and legend below.
constexpr double margin = 24, top = 60, bottom = 48;
}  // namespace

void Page::fit(double u0, double u1, double v0, double v1) {
    double du = std::max(u1 - u0, 1e-3), dv = std::max(v1 - v0, 1e-3);
    double w = std::max(o_.width - 2 * margin, 1.0), h = std::max(o_.height - top - bottom, 1.0);
    scale_ = std::min(w / du, h / dv);
    u0_ = u0;
    v0_ = v0;
    x0_ = margin + (w - du * scale_) / 2;
    y0_ = top + h - (h - dv * scale_) / 2;
}

bool Page::face_on(Plane plane) const {
    switch (o_.view) {
        case PlotView::xy:
            return plane == Plane::xy;
        case PlotView::xz:
            return plane == Plane::zx;
        case PlotView::yz:
            return plane == Plane::yz;
        case PlotView::lathe:
            return plane == Plane::zx && !o_.diameter;
    }
    return false;
}

std::string_view Page::axes_text() const {
    switch (o_.view) {
        case PlotView::xz:
            return "XZ, from the front (-Y): X across, Z up";
        case PlotView::yz:
            return "YZ, from the side (+X): Y across, Z up";
        case PlotView::lathe:
            if (o_.front_post)
                return o_.diameter ? "lathe, front tool post: Z across, X (diameter) down"
                                   : "lathe, front tool post: Z across, X (radius) down";
            return o_.diameter ? "lathe, back tool post: Z across, X (diameter) up"
                               : "lathe, back tool post: Z across, X (radius) up";
        case PlotView::xy:
            break;
    }
    return "XY, from above (+Z): X across, Y up";
}

}  // namespace tape::plot
