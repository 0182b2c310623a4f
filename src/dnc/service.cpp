// The service: one Machine per configured line, started, reloaded and stopped together.
#include <unistd.h>

#include <cstdlib>

#include "machine.hpp"

namespace tape::dnc {
namespace {

using namespace std::chrono_literals;

}  // namespace

bool MachineSettings::same_settings(const MachineSettings& other) const {
    MachineSettings a = *this, b = other;
    a.line = b.line = 0;
    auto key = [](const MachineSettings& m) {
        return std::tie(m.name, m.device, m.code, m.parity, m.leader, m.trailer, m.crlf, m.percent, m.dialect, m.rate,
                        m.block_delay, m.flow, m.wait_xon, m.xon_timeout, m.xon, m.xoff, m.burst, m.receive_timeout,
                        m.max_punch_out, m.answer_unknown, m.lathe);
    };
    return key(a) == key(b);
}

struct Service::State {
    std::shared_ptr<Shared> shared = std::make_shared<Shared>();
    std::vector<std::unique_ptr<Machine>> machines;

    void start(const MachineSettings& m) {
        machines.push_back(std::make_unique<Machine>(m, shared));
        machines.back()->start();
    }
    // Stops the machines for which stopping is true; returns the names of those still blocked at grace.
    template <class Pred>
    std::vector<std::string> stop_where(Pred stopping, std::chrono::milliseconds grace) {
        std::vector<std::unique_ptr<Machine>> going, staying;
        for (auto& m : machines) (stopping(*m) ? going : staying).push_back(std::move(m));
        machines = std::move(staying);
        for (auto& m : going) m->request_stop();
        auto end = shared->clock->now() + grace;
        auto all_done = [&] {
            for (auto& m : going)
                if (!m->finished()) return false;
            return true;
        };
        while (!all_done() && shared->clock->now() < end) shared->clock->sleep_until(shared->clock->now() + 10ms);
        std::vector<std::string> blocked;
        for (auto& m : going)
            if (!m->finished()) {
                blocked.push_back(m->settings().name);
                m->abandon();
                (void)m.release();  // its thread still uses it: it ends with the process
            }
        return blocked;
    }
};

Service::Service(const ServiceConfig& config, LogSink log, Clock& clock) : s_(std::make_unique<State>()) {
    s_->shared->log = std::move(log);
    s_->shared->clock = &clock;
    s_->shared->set_library(config.library);
    for (const auto& m : config.machines) s_->start(m);
}

Service::~Service() { stop(2s); }

void Service::reload(const ServiceConfig& config) {
    s_->shared->set_library(config.library);
    auto kept = [&](const Machine& m) {
        for (const auto& c : config.machines)
            if (c.same_settings(m.settings())) return true;
        return false;
    };
    auto blocked = s_->stop_where([&](const Machine& m) { return !kept(m); }, 2s);
    for (const auto& name : blocked)
        s_->shared->log(Priority::warning, name + ": still blocked on its line after 2 s; left to end by itself");
    for (const auto& c : config.machines) {
        bool running = false;
        for (const auto& m : s_->machines) running = running || m->settings().same_settings(c);
        if (!running) s_->start(c);
    }
}

std::vector<std::string> Service::stop(std::chrono::milliseconds grace) {
    return s_->stop_where([](const Machine&) { return true; }, grace);
}

std::vector<MachineStatus> Service::status() const {
    std::vector<MachineStatus> all;
    for (const auto& m : s_->machines) all.push_back(m->status());
    return all;
}

std::string_view line_state_name(LineState s) {
    switch (s) {
        case LineState::opening:
            return "opening";
        case LineState::listening:
            return "listening";
        case LineState::receiving:
            return "receiving";
        case LineState::sending:
            return "sending";
        case LineState::waiting:
            return "waiting";
        case LineState::stopped:
            return "stopped";
    }
    return "unknown";
}

std::string default_runtime_directory() {
    if (const char* d = std::getenv("RUNTIME_DIRECTORY"); d && *d)
        return std::string(d).substr(0, std::string(d).find(':'));
    if (const char* d = std::getenv("XDG_RUNTIME_DIR"); d && *d) return std::string(d) + "/tape-dnc";
    return "/tmp/tape-dnc-" + std::to_string(::getuid());
}

std::string control_socket_path(const ServiceConfig& config) {
    return (config.runtime_directory.empty() ? default_runtime_directory() : config.runtime_directory) +
           "/control.sock";
}

}  // namespace tape::dnc
