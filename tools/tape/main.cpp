// tape: punched paper tape for NC machine tools — encode, decode, show, inspect.
#include <limits>

#include "cli/completion.hpp"
#include "cli/globals.hpp"
#include "cli/numbers.hpp"
#include "cli/run.hpp"
#include "cli/signals.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
    CLI::App app{
        "tape: punched paper tape (перфолента) for NC machine tools.\n"
        "Turns part programs into 8-track tape images and back, ISO 7-bit or EIA RS-244.",
        "tape"};
    app.set_version_flag("--version", std::string("tape ") + TAPE_VERSION);
    app.require_subcommand(1);
    app.fallthrough();
    auto& g = cli::globals();
    app.add_flag_function(
        "-v,--verbose", [&g](std::int64_t n) { g.verbosity += static_cast<int>(n); },
        "Say more on stderr (the detected code, counts)");
    app.add_flag_function(
        "-q,--quiet", [&g](std::int64_t n) { g.verbosity -= static_cast<int>(n); }, "Say less on stderr");
    app.add_option("--max-errors", g.max_errors,
                   "Messages of one kind (parity errors, a lint rule) before the rest are only counted; 0: all")
        ->check(cli::whole_number(0, std::numeric_limits<std::uint32_t>::max()))
        ->capture_default_str();
    app.add_option("--eia-table", g.eia_table, "A corrected EIA code table (format of data/eia-rs244.tab)")
        ->envname("TAPE_EIA_TABLE");
    app.footer(
        "Exit status: 0 ok, 1 bad data in the input, 2 usage error, 3 I/O or device failure,\n"
        "130 feed, receive or punch stopped with Ctrl-C (read and emulate end 0 on Ctrl-C).\n"
        "See tape(1), tape-image(5), tape-devices(7).");
    cli::add_encode(app);
    cli::add_decode(app);
    cli::add_show(app);
    cli::add_info(app);
    cli::add_blocks(app);
    cli::add_lint(app);
    cli::add_format(app);
    cli::add_search(app);
    cli::add_feed(app);
    cli::add_receive(app);
    cli::add_emulate(app);
    cli::add_read(app);
    cli::add_punch(app);
    cli::add_devices(app);
    cli::add_restore(app);
    cli::add_diff(app);
    cli::add_adapter(app);
    cli::add_label(app);
    cli::add_plot(app);
    cli::add_render(app);
    cli::add_dnc(app);
    cli::add_scan(app);
    cli::add_machines(app);
    cli::add_archive(app);
    cli::add_bash_completion_flag(app, "tape");
    cli::install_output_cleanup();
    return cli::parse_and_run(app, argc, argv, "'tape --help' or 'tape SUBCOMMAND --help'");
}
