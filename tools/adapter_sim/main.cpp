// tape-adapter-sim: the USB tape adapter's firmware core on the host, with a simulated ФС-1501-class
// reader and ПЛ-150-class punch backed by tape images, on a pseudo-terminal standing for its CDC
// port: the whole toolkit can be tried, and tested, without hardware. Faults can be injected.
// The options are in sim_options.cpp, the board in board.cpp, its port in port.cpp.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "adapter_sim/board.hpp"
#include "adapter_sim/port.hpp"
#include "adapter_sim/sim_args.hpp"
#include "cli/files.hpp"
#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "cli/run.hpp"
#include "cli/signals.hpp"

namespace tapesim {

[[noreturn]] void die(const std::string& what) {
    std::cerr << "tape-adapter-sim: " << what << "\n";
    throw cli::Exit{cli::io_failure};
}

}  // namespace tapesim

namespace {

std::vector<std::uint8_t> reader_tape(const tapesim::SimArgs& a) {
    if (a.reader.empty()) return {};
    auto in = cli::read_tape(a.reader, "");
    return {in.frames.begin(), in.frames.end()};
}

// An output file of the run: standard output is taken by the device string, and no two outputs (or an
// output and the reader's tape) may be one file.
std::FILE* create(const std::string& path, const std::string& option) {
    if (path.empty()) return nullptr;
    if (path == "-")
        cli::fail(option + " -", tape::Errc::usage, "standard output carries the device string: give a file");
    cli::claim_output(path);
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) tapesim::die(path + ": cannot create: " + std::strerror(errno));
    return f;
}

int run(const tapesim::SimArgs& a) {
    const std::vector<std::uint8_t> tape = reader_tape(a);
    std::FILE* punched_out = create(a.punch, "--punch");
    std::FILE* control_out = create(a.control, "--control");
    tapesim::Board board(a, tape);
    {
        tapesim::Port port(a.link);
        std::cout << "adapter:" << port.path() << std::endl;
        board.run(port, punched_out, control_out);
    }
    for (auto* f : {punched_out, control_out})
        if (f) std::fclose(f);
    board.print_faults();
    if (a.stats) board.print_stats();
    return cli::ok;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "tape-adapter-sim: a USB tape adapter with a ФС-1501-class reader and a ПЛ-150-class punch, simulated on a "
        "pseudo-terminal.\nPrints the device string (adapter:/dev/pts/N) on stdout, then runs until Ctrl-C.",
        "tape-adapter-sim"};
    app.set_version_flag("--version", std::string("tape-adapter-sim ") + TAPE_VERSION);
    app.footer("See tape-usb(7) and docs/adapter-protocol.md.");
    cli::globals().program = "tape-adapter-sim";
    tapesim::SimArgs a;
    tapesim::add_unit_options(app, a);
    tapesim::add_fault_options(app, a);
    app.callback([&a] { throw cli::Exit{run(a)}; });
    cli::install_interrupt_handler();
    return cli::parse_and_run(app, argc, argv);
}
