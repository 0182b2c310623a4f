// The plot module (plot/plot_module.hpp) loaded on first use as common/module_loader.hpp loads any module,
// and draw_plot through it; TAPE_PLOT_MODULE names another file, for tests and packagers.
#include "common/module_loader.hpp"
#include "plot/plot_module.hpp"
#include "tape/error.hpp"

#ifndef TAPE_PLOT_MODULE_BUILT
#error "CMakeLists.txt says whether the plot module is built, and where it is installed"
#endif

namespace tape {
namespace {

struct Loaded {
    const plot_module::Api* api = nullptr;
    std::string why;  // empty when api is there
};

Loaded load() {
    if (!TAPE_PLOT_MODULE_BUILT)
        return {nullptr,
                "built without cairo: drawing toolpaths needs it (install libcairo2-dev, or run "
                "scripts/install-deps.sh features, then build again)"};
    static const modules::ModuleSpec spec{"the plot module, which draws toolpaths through cairo",
                                          "TAPE_PLOT_MODULE",
                                          TAPE_PLOT_MODULE_RELATIVE,
                                          TAPE_PLOT_MODULE_INSTALLED,
                                          "tape_plot_module_api",
                                          "it needs the cairo library; Debian: libcairo2"};
    modules::Opened m = modules::open_module(spec);
    auto table = static_cast<const plot_module::Api*>(m.table);
    if (table && table->abi != plot_module::abi_version)
        return {nullptr, m.path + " is not the plot module of this build of tape (reinstall tape)"};
    return {table, m.why};
}

const Loaded& loaded() {
    static const Loaded module = load();
    return module;
}

}  // namespace

bool plot_available() { return loaded().why.empty(); }

std::string_view plot_unavailable_message() { return loaded().why; }

std::vector<std::uint8_t> draw_plot(const PlotPlan& plan, std::string_view format) {
    const Loaded& m = loaded();
    if (!m.api) throw Error(Errc::io, m.why);
    std::vector<std::uint8_t> out;
    if (std::string failed = m.api->draw(plan, format, out); !failed.empty()) throw Error(Errc::io, failed);
    return out;
}

}  // namespace tape
