// The page a toolpath is drawn on: the part's coordinates seen from one side (u across, v up, in mm) and
// fitted to the page (x across, y down, in pixels or points).
#pragma once

#include <string_view>

#include "tape/toolpath.hpp"

namespace tape::plot {

struct Uv {
    double u = 0, v = 0;
};
struct Xy {
    double x = 0, y = 0;
};

class Page {
public:
    explicit Page(const PlotOptions& options) : o_(options) {}

    Uv view(const Point& p) const {
        switch (o_.view) {
            case PlotView::xz:
                return {p.x, p.z};
            case PlotView::yz:
                return {p.y, p.z};
            case PlotView::lathe: {
                double x = o_.diameter ? 2 * p.x : p.x;
                return {p.z, o_.front_post ? -x : x};
            }
            case PlotView::xy:
                break;
        }
        return {p.x, p.y};
    }

    /// Fits the part's bounds (mm, on the view's axes) inside the page's margins, centred.
    void fit(double u0, double u1, double v0, double v1);
    Xy at(const Point& p) const {
        Uv q = view(p);
        return {x0_ + (q.u - u0_) * scale_, y0_ - (q.v - v0_) * scale_};
    }
    double scale() const { return scale_; }  ///< page units per mm
    /// Page x and y of the view's origin (u = v = 0).
    double origin_x() const { return x0_ - u0_ * scale_; }
    double origin_y() const { return y0_ + v0_ * scale_; }

    /// The axes a move needs known to be drawn from this side (AxisBit).
    unsigned axes() const {
        switch (o_.view) {
            case PlotView::xz:
            case PlotView::lathe:
                return axis_x | axis_z;
            case PlotView::yz:
                return axis_y | axis_z;
            case PlotView::xy:
                break;
        }
        return axis_x | axis_y;
    }
    bool shows(const PathMove& m) const { return (m.known & axes()) == axes(); }
    /// An arc of plane is seen face on (as a true arc) from this side, at an even scale.
    bool face_on(Plane plane) const;
    /// An arc's sweep (counterclockwise positive, seen from its plane's normal) as the page's angle
    /// goes (y down: positive is clockwise on the page).
    double page_sweep(double sweep) const { return flipped() ? sweep : -sweep; }
    /// "XY, from +Z: X across, Y up" and the like.
    std::string_view axes_text() const;

private:
    // The view's axes are the plane's taken the other way round (the part seen from behind its normal).
    bool flipped() const { return o_.view == PlotView::xz || (o_.view == PlotView::lathe && o_.front_post); }

    PlotOptions o_;
    double scale_ = 1, u0_ = 0, v0_ = 0, x0_ = 0, y0_ = 0;
};

}  // namespace tape::plot
