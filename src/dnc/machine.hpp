// One machine's line, served from a thread of its own: listening for punch-outs, filing them,
// answering requests. Private to the service.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

#include "tape/dnc.hpp"
#include "tape/dnc_request.hpp"
#include "tape/dnc_service.hpp"
#include "tape/input.hpp"

namespace tape::dnc {

class PunchOutFile;
struct Reception;

/// What every machine reads: the library (replaced on reload), the log, the clock. Held by each
/// machine, so that one left blocked at the end still has it.
struct Shared {
    LogSink log;
    Clock* clock = nullptr;

    std::shared_ptr<const Library> library() const {
        std::lock_guard lock(mutex);
        return library_;
    }
    void set_library(const Library& l) {
        std::lock_guard lock(mutex);
        library_ = std::make_shared<const Library>(l);
    }

private:
    mutable std::mutex mutex;
    std::shared_ptr<const Library> library_;
};

class Machine {
public:
    Machine(MachineSettings settings, std::shared_ptr<Shared> shared);
    ~Machine();  ///< joins the thread: call only once it ended (finished()) or was never started
    Machine(const Machine&) = delete;
    Machine& operator=(const Machine&) = delete;

    void start();
    /// Asks the thread to end: a punch-out is cut and kept as FAILED, a sending stops.
    void request_stop() { stop_ = true; }
    bool finished() const { return finished_; }
    /// Lets the thread go on alone (blocked on a line that takes nothing) when the service ends.
    void abandon();

    const MachineSettings& settings() const { return s_; }
    MachineStatus status() const;

private:
    void run();
    void serve(Transport& line);
    bool listen(Transport& line);
    void finish_punch_out(Transport& line, Reception& rx, ReceiveResult::End end, double seconds);
    void keep_failed(Transport& line, Reception& rx, const std::string& reason, double seconds);
    void after_write_failure(Transport& line, Reception& rx, ReceiveResult::End end);
    void file_program(PunchOutFile& file, std::uint64_t frames, double seconds);
    void keep_pending(std::span<const std::uint8_t> bytes);
    void answer(Transport& line, const Request& request);
    void answer_restart(Transport& line, const Request& request);
    void send(Transport& line, Input& input, const std::string& program, const std::string& source);
    void send_text(Transport& line, const std::string& text, const std::string& program, const std::string& source);
    void say_unknown(Transport& line, const std::string& message, const std::string& comment);
    std::uint64_t discard_until_quiet(Transport& line);
    void pause(std::chrono::milliseconds how_long);

    void log(Priority p, const std::string& message) const { shared_->log(p, s_.name + ": " + message); }
    void set_state(LineState state, const std::string& program = "", std::uint64_t total = 0);
    void set_frames(std::uint64_t frames);
    void count(std::uint64_t MachineStatus::*counter, const std::string& line);
    double since(Clock::time_point start) const;

    MachineSettings s_;
    std::shared_ptr<Shared> shared_;
    std::atomic<bool> stop_{false}, finished_{false};
    std::thread thread_;
    // What was read from the line but is no part of the punch-out or request just handled: the start of
    // the next, read with the last one's end or while answering it. Only the machine's thread uses it.
    std::vector<std::uint8_t> pending_;
    bool pending_overflow_ = false;
    mutable std::mutex status_mutex_;
    MachineStatus status_;
};

}  // namespace tape::dnc
