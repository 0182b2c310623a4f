// Arc geometry for repair (tape_rules.hpp): a G02/G03 move's start and end lie on one circle. With the
// centre given by I, J, K (from the start, always incremental: the controller manual's excerpt, §4.3),
// both radii agree within the controller's tolerance; with R, the chord is no longer than the diameter.
#include <cmath>

#include "tape_rules.hpp"

namespace tape::detail {
namespace {

struct PlaneAxes {
    int u, v;  // X=0, Y=1, Z=2
    char centre_u, centre_v;
};

PlaneAxes plane_axes(int plane) {
    if (plane == 18) return {2, 0, 'K', 'I'};
    if (plane == 19) return {1, 2, 'J', 'K'};
    return {0, 1, 'I', 'J'};
}

struct ArcWords {
    double cu = 0, cv = 0;
    std::optional<double> r;
    bool any_centre = false, pointed = false, unpointed = false, macro = false;
    int decimals = 0;
};

ArcWords arc_words(const Block& b, const PlaneAxes& axes) {
    ArcWords a;
    for (const auto& w : b.words) {
        bool arc_word = w.address == axes.centre_u || w.address == axes.centre_v || w.address == 'R' ||
                        w.address == 'X' || w.address == 'Y' || w.address == 'Z';
        if (!arc_word) continue;
        auto shape = shape_of(w);
        if (!shape) {
            a.macro = true;
            continue;
        }
        std::string d;
        for (char c : w.text)
            if ((c >= '0' && c <= '9') || c == '.') d += c;
        double value = std::strtod(d.c_str(), nullptr) * (w.sign == '-' ? -1 : 1);
        if (value != 0) (w.has_point() ? a.pointed : a.unpointed) = true;
        if (shape->after > a.decimals) a.decimals = shape->after;
        if (w.address == axes.centre_u) a.cu = value, a.any_centre = true;
        if (w.address == axes.centre_v) a.cv = value, a.any_centre = true;
        if (w.address == 'R') a.r = value;
    }
    return a;
}

}  // namespace

std::optional<bool> arc_agrees(const MotionState& before, const Block& block) {
    MotionState after = before;
    advance(after, block);
    if (after.motion != 2 && after.motion != 3) return std::nullopt;
    PlaneAxes axes = plane_axes(after.plane);
    auto su = before.at[static_cast<std::size_t>(axes.u)], sv = before.at[static_cast<std::size_t>(axes.v)];
    auto eu = after.at[static_cast<std::size_t>(axes.u)], ev = after.at[static_cast<std::size_t>(axes.v)];
    if (!su || !sv || !eu || !ev) return std::nullopt;
    ArcWords a = arc_words(block, axes);
    // Values with and without points in one arc have no common scale (an implied point).
    bool start_pointed =
        before.pointed[static_cast<std::size_t>(axes.u)] || before.pointed[static_cast<std::size_t>(axes.v)];
    if (a.macro || (a.pointed && a.unpointed) || (a.unpointed && start_pointed && (*su != 0 || *sv != 0)))
        return std::nullopt;
    double unit = a.unpointed ? 1 : std::pow(10.0, -std::max(a.decimals, 1));
    double chord = std::hypot(*eu - *su, *ev - *sv);
    if (a.r) return chord <= 2 * std::fabs(*a.r) * (1 + 1e-3) + 2 * unit;
    if (!a.any_centre) return std::nullopt;
    double r1 = std::hypot(a.cu, a.cv);
    double r2 = std::hypot(*eu - (*su + a.cu), *ev - (*sv + a.cv));
    return std::fabs(r1 - r2) <= std::max(1e-3 * std::max(r1, r2), 2 * unit);
}

}  // namespace tape::detail
