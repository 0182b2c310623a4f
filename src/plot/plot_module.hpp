// The plot module: the drawing of a plan (tape/toolpath.hpp) with cairo, a shared object of its own loaded
// on first use, so that no command but plot maps cairo and the libraries it pulls in (fontconfig,
// freetype, libpng, pixman, X11's). It shares no code with the library, only the plan's types (in the
// header, inline), and throws nothing across its table.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "tape/toolpath.hpp"

namespace tape::plot_module {

/// Changes whenever the table below or PlotPlan does: a module of another build is refused, not called.
inline constexpr std::uint32_t abi_version = 1;

struct Api {
    std::uint32_t abi = abi_version;
    /// The plan drawn as "svg", "png" or "pdf": the file's bytes into out; on failure, what failed
    /// (empty on success).
    std::string (*draw)(const PlotPlan& plan, std::string_view format, std::vector<std::uint8_t>& out);
};

}  // namespace tape::plot_module

/// The module's one exported symbol.
extern "C" const tape::plot_module::Api* tape_plot_module_api();
