// tape dnc: the shop's DNC service (foreground; systemd runs it), and tape dnc status asking it how
// its lines are doing through the control socket.
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <thread>

#include "cli/globals.hpp"
#include "cli/messages.hpp"
#include "commands.hpp"
#include "dnc_config.hpp"
#include "tape/utf8_text.hpp"

namespace cli {
namespace {

using namespace std::chrono_literals;
namespace dnc = tape::dnc;

std::atomic<bool> stop_requested{false}, reload_requested{false};

extern "C" void on_signal(int sig) {
    if (sig == SIGHUP)
        reload_requested = true;
    else
        stop_requested = true;
}

void install_service_signals() {
    struct sigaction sa {};
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    for (int sig : {SIGTERM, SIGINT, SIGHUP}) ::sigaction(sig, &sa, nullptr);
    ::signal(SIGPIPE, SIG_IGN);  // a status client gone before its answer
}

// One line on stderr with its sd-daemon(3) priority, written at once: journald keeps the priority.
void log_line(dnc::Priority p, const std::string& message) {
    static std::mutex mutex;
    std::string line = "<" + std::to_string(static_cast<int>(p)) + ">" + tape::visible(message) + "\n";
    std::lock_guard lock(mutex);
    [[maybe_unused]] auto n = ::write(STDERR_FILENO, line.data(), line.size());
}

dnc::ServiceConfig config_or_fail(const std::string& path) {
    try {
        return load_dnc_config(path);
    } catch (const tape::Error& e) {
        fail(path, e);
    }
}

void reload(dnc::Service& service, const std::string& path) {
    try {
        dnc::ServiceConfig config = load_dnc_config(path);
        service.reload(config);
        log_line(dnc::Priority::notice, "tape dnc: reloaded " + path + ": " + std::to_string(config.machines.size()) +
                                            " machine(s); those whose settings did not change kept their transfers");
    } catch (const tape::Error& e) {
        std::string where = e.where().line ? "line " + std::to_string(*e.where().line) + ": " : "";
        log_line(dnc::Priority::err,
                 "tape dnc: " + path + ": " + where + e.what() + ": the running configuration stays in force");
    }
}

void run_service(const std::string& path) {
    dnc::ServiceConfig config = config_or_fail(path);  // a bad config ends here, before any line is opened
    install_service_signals();
    // The socket first: one it cannot have (another service answers there, a path too long) is said
    // before any line is opened too. It answers an empty list until the machines start.
    std::atomic<dnc::Service*> serving{nullptr};
    std::unique_ptr<dnc::ControlSocket> socket;
    try {
        socket = std::make_unique<dnc::ControlSocket>(dnc::control_socket_path(config), [&serving] {
            dnc::Service* s = serving.load();
            return status_lines(s ? s->status() : std::vector<dnc::MachineStatus>{});
        });
    } catch (const tape::Error& e) {
        fail("", e);
    }
    dnc::Service service(config, log_line);
    serving = &service;
    log_line(dnc::Priority::notice, "tape dnc: serving " + std::to_string(config.machines.size()) +
                                        " machine(s) from " + path + "; status: tape dnc status --config " + path);
    while (!stop_requested) {
        std::this_thread::sleep_for(100ms);
        if (reload_requested.exchange(false)) reload(service, path);
    }
    socket.reset();
    auto blocked = service.stop(1500ms);
    for (const auto& name : blocked)
        log_line(dnc::Priority::warning, name + ": still blocked on its line; the service ends without it");
    log_line(dnc::Priority::notice, "tape dnc: stopped");
    if (!blocked.empty()) {
        std::fflush(nullptr);
        std::_Exit(0);  // a thread blocked in write() or tcdrain() on a dead line ends with the process
    }
}

std::string progress_text(const dnc::MachineStatus& m) {
    if (m.program.empty()) return "-";
    std::string text = std::to_string(m.frames);
    if (m.total) text += "/" + std::to_string(m.total) + " (" + std::to_string(m.frames * 100 / m.total) + "%)";
    return text;
}

// The control socket: given, or read from the config (its runtime_directory only).
std::string socket_of(const std::string& config, const std::string& socket) {
    if (!socket.empty()) return socket;
    try {
        return dnc_control_socket(config);
    } catch (const tape::Error& e) {
        fail(config, e);
    }
}

void print_status(const std::string& socket_path) {
    std::string reply;
    try {
        reply = dnc::query_control_socket(socket_path, 2s);
    } catch (const tape::Error& e) {
        fail("", tape::Errc::io, std::string(e.what()) + " (is tape dnc running with this config, as this user?)");
    }
    std::printf("%-16s %-10s %-20s %-20s %6s %6s %6s  %s\n", "MACHINE", "STATE", "TRANSFER", "PROGRESS", "SENT",
                "FILED", "FAILED", "DEVICE");
    for (const auto& m : dnc::parse_status_lines(reply)) {
        std::printf("%-16s %-10s %-20s %-20s %6llu %6llu %6llu  %s\n", m.name.c_str(),
                    std::string(line_state_name(m.state)).c_str(), (m.program.empty() ? "-" : m.program).c_str(),
                    progress_text(m).c_str(), static_cast<unsigned long long>(m.sent),
                    static_cast<unsigned long long>(m.filed), static_cast<unsigned long long>(m.failed),
                    m.device.c_str());
        if (globals().verbosity > 0 && !m.last.empty()) std::printf("    last: %s\n", tape::visible(m.last).c_str());
    }
}

}  // namespace

void add_dnc(CLI::App& app) {
    auto config = std::make_shared<std::string>();
    auto* sub = app.add_subcommand("dnc",
                                   "The shop's DNC service: serve every controller's line at once (requests, "
                                   "punch-outs filed, restarts); runs in the foreground, SIGHUP reloads, SIGTERM ends");
    sub->add_option("--config", *config, "The service's TOML configuration (required; see packaging/dnc.toml)");
    auto* status = sub->add_subcommand("status", "List the machines of a running tape dnc: state, transfer, progress");
    auto socket = std::make_shared<std::string>();
    auto* by_config = status->add_option("--config", *config,
                                         "The running service's configuration (only its runtime_directory is read)");
    auto* by_socket = status->add_option("--socket", *socket, "The service's control socket (control.sock)");
    by_config->excludes(by_socket);
    sub->require_subcommand(0, 1);
    status->callback([config, socket] {
        if (config->empty() && socket->empty())
            fail("", tape::Errc::usage, "tape dnc status needs --config FILE or --socket PATH");
        print_status(socket_of(*config, *socket));
    });
    sub->callback([config, status] {
        if (status->parsed()) return;
        if (config->empty()) fail("", tape::Errc::usage, "--config is required: tape dnc --config FILE");
        run_service(*config);
    });
}

}  // namespace cli
