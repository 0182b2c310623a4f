// The plot module (plot/plot_module.hpp): a plan drawn with cairo to SVG, PDF or PNG, from one drawing.
#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <memory>

#include "plot/plot_module.hpp"

namespace {

using tape::PlotPlan;

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(closure);
    out->insert(out->end(), data, data + length);
    return CAIRO_STATUS_SUCCESS;
}

void set_colour(cairo_t* cr, std::uint32_t rgb) {
    cairo_set_source_rgb(cr, ((rgb >> 16) & 255) / 255.0, ((rgb >> 8) & 255) / 255.0, (rgb & 255) / 255.0);
}

void set_style(cairo_t* cr, const tape::PlotStyle& s) {
    set_colour(cr, s.rgb);
    cairo_set_line_width(cr, s.width);
    const double dash[] = {5.0 * s.width, 3.5 * s.width};
    cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0);
}

void add_stroke(cairo_t* cr, const PlotPlan& plan, const tape::PlotStroke& s) {
    cairo_new_sub_path(cr);
    if (s.arc) {
        (s.a1 >= s.a0 ? cairo_arc : cairo_arc_negative)(cr, s.cx, s.cy, s.r, s.a0, s.a1);
        return;
    }
    const float* p = plan.points.data() + 2 * static_cast<std::size_t>(s.first);
    cairo_move_to(cr, p[0], p[1]);
    for (std::uint32_t k = 1; k < s.count; ++k) cairo_line_to(cr, p[2 * k], p[2 * k + 1]);
}

// Strokes of one style one after the other are one path: stroked at once, and every few thousand
// segments, so that no path grows without bound.
void draw_strokes(cairo_t* cr, const PlotPlan& plan) {
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    std::size_t in_path = 0;
    for (std::size_t i = 0; i < plan.strokes.size(); ++i) {
        const auto& s = plan.strokes[i];
        if (i == 0 || s.style != plan.strokes[i - 1].style) set_style(cr, plan.styles[s.style]);
        add_stroke(cr, plan, s);
        in_path += s.arc ? 8 : s.count;
        bool last = i + 1 == plan.strokes.size() || plan.strokes[i + 1].style != s.style;
        if (last || in_path > 4096) {
            cairo_stroke(cr);
            in_path = 0;
        }
    }
}

void draw_marks(cairo_t* cr, const PlotPlan& plan) {
    cairo_set_dash(cr, nullptr, 0, 0);
    if (plan.scale_bar.size() == 2) {
        auto [x0, y] = plan.scale_bar[0];
        double x1 = plan.scale_bar[1].first;
        set_colour(cr, 0x333333);
        cairo_set_line_width(cr, 1.5);
        cairo_move_to(cr, x0, y - 4);
        cairo_line_to(cr, x0, y);
        cairo_line_to(cr, x1, y);
        cairo_line_to(cr, x1, y - 4);
        cairo_stroke(cr);
    }
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    for (const auto& t : plan.texts) {
        set_colour(cr, t.rgb);
        cairo_set_font_size(cr, t.size);
        cairo_move_to(cr, t.x, t.y);
        cairo_show_text(cr, t.text.c_str());
    }
}

std::string draw_on(cairo_surface_t* surface, const PlotPlan& plan) {
    cairo_t* cr = cairo_create(surface);
    set_colour(cr, 0xffffff);
    cairo_paint(cr);
    draw_strokes(cr, plan);
    draw_marks(cr, plan);
    cairo_status_t status = cairo_status(cr);
    cairo_destroy(cr);
    return status == CAIRO_STATUS_SUCCESS ? "" : std::string("cairo: ") + cairo_status_to_string(status);
}

std::string draw(const PlotPlan& plan, std::string_view format, std::vector<std::uint8_t>& out) {
    try {
        out.clear();
        cairo_surface_t* surface = nullptr;
        if (format == "svg") {
            surface = cairo_svg_surface_create_for_stream(append, &out, plan.width, plan.height);
            cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PX);  // a page's pixels, not print points
        } else if (format == "pdf")
            surface = cairo_pdf_surface_create_for_stream(append, &out, plan.width, plan.height);
        else if (format == "png")
            surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, plan.width, plan.height);
        else
            return "no such picture format: " + std::string(format);
        std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> owner(surface, cairo_surface_destroy);
        std::string failed = draw_on(surface, plan);
        if (failed.empty() && format == "png") {
            if (cairo_surface_write_to_png_stream(surface, append, &out) != CAIRO_STATUS_SUCCESS)
                failed = "cairo could not write the PNG";
        }
        cairo_surface_finish(surface);  // the SVG and PDF are written here
        if (failed.empty() && cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS)
            failed = std::string("cairo: ") + cairo_status_to_string(cairo_surface_status(surface));
        return failed;
    } catch (const std::exception& e) {
        return e.what();
    }
}

}  // namespace

extern "C" __attribute__((visibility("default"))) const tape::plot_module::Api* tape_plot_module_api() {
    static const tape::plot_module::Api api{tape::plot_module::abi_version, draw};
    return &api;
}
