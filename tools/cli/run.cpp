#include "cli/run.hpp"

#include <iostream>

#include "cli/globals.hpp"

namespace cli {

int status_for(tape::Errc code) {
    if (code == tape::Errc::io) return io_failure;
    if (code == tape::Errc::usage || code == tape::Errc::exists) return usage;
    return bad_data;
}

int parse_and_run(CLI::App& app, int argc, char** argv, const std::string& help) {
    const std::string& program = globals().program;
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {  // --help, --help-all, --version
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << program << ": " << e.what() << "\n"
                  << program << ": run " << (help.empty() ? "'" + program + " --help'" : help) << " for the options\n";
        return usage;
    } catch (const Exit& e) {
        return e.status;
    }
    return ok;
}

}  // namespace cli
