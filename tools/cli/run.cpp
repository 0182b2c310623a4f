#include "cli/run.hpp"

#include <iostream>
#include <new>

#include "cli/globals.hpp"
#include "cli/messages.hpp"

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
    } catch (const tape::Error& e) {
        // What a command did not catch and name itself still ends in a message, never in abort().
        say("", with_hint(e.what(), e.hint()));
        return status_for(e.code());
    } catch (const std::bad_alloc&) {
        say("", "out of memory");
        return io_failure;
    } catch (const std::exception& e) {
        say("", std::string("internal error: ") + e.what());
        return io_failure;
    } catch (...) {
        say("", "internal error");
        return io_failure;
    }
    return ok;
}

}  // namespace cli
