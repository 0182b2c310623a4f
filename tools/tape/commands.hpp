// One function per subcommand file; tape.cpp only wires them.
#pragma once

#include <CLI/CLI.hpp>

namespace cli {

void add_encode(CLI::App& app);
void add_decode(CLI::App& app);
void add_show(CLI::App& app);
void add_info(CLI::App& app);
void add_blocks(CLI::App& app);
void add_lint(CLI::App& app);
void add_format(CLI::App& app);
void add_search(CLI::App& app);
void add_feed(CLI::App& app);
void add_receive(CLI::App& app);
void add_emulate(CLI::App& app);
void add_read(CLI::App& app);
void add_punch(CLI::App& app);
void add_devices(CLI::App& app);
void add_restore(CLI::App& app);
void add_diff(CLI::App& app);
void add_adapter(CLI::App& app);
void add_label(CLI::App& app);
void add_plot(CLI::App& app);
void add_render(CLI::App& app);
void add_dnc(CLI::App& app);
void add_scan(CLI::App& app);
void add_machines(CLI::App& app);
void add_archive(CLI::App& app);

}  // namespace cli
