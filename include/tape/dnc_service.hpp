// The shop's DNC service: every controller's line served at once. A control asks for programs by
// punching out a request, punches out programs to be filed, and asks for a restart after a tool break;
// each line has its own thread, so a line that hangs, floods or stalls delays no other.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tape/clock.hpp"
#include "tape/code.hpp"
#include "tape/device.hpp"
#include "tape/dialect.hpp"
#include "tape/encode.hpp"
#include "tape/line_state.hpp"

namespace tape::dnc {

/// How one machine's line is served: its device and everything tape feed and tape receive take.
struct MachineSettings {
    std::string name;        ///< letters, digits, '_' and '-': in log lines and FAILED-<name>-<time>.nc
    std::string device;      ///< any device string
    std::uint64_t line = 0;  ///< where the machine stands in the config file (for messages; not a setting)
    Code code = Code::iso;
    Parity parity = Parity::even;
    std::size_t leader = default_leader, trailer = default_trailer;
    bool crlf = false;
    bool percent = true;  ///< a '%' first and last where a program lacks them
    Dialect dialect = Dialect::automatic;
    double rate = 0;                           ///< frames per second; 0: the line's speed
    std::chrono::milliseconds block_delay{0};  ///< a pause after each end of block
    std::optional<Flow> flow{};                ///< default: the device string's
    bool wait_xon = false;                     ///< send nothing before the control's DC1
    std::chrono::milliseconds xon_timeout{0};  ///< with wait_xon: give up after this long (0: never)
    std::uint8_t xon = dc1, xoff = dc3;
    std::size_t burst = 8;                             ///< frames per wake-up (SendOptions::burst)
    std::chrono::milliseconds receive_timeout{10000};  ///< a punch-out quiet this long has ended
    std::uint64_t max_punch_out = 16u << 20;           ///< bytes; longer is a flood, kept as FAILED
    bool answer_unknown = false;                       ///< answer an unknown name with a short comment program
    bool lathe = false;  ///< a lathe: a restart's approach goes X clear, then Z, then X (tape/restart.hpp)

    /// Equal settings: a reload leaves such a machine's transfer alone.
    bool same_settings(const MachineSettings& other) const;
};

struct Library {
    std::string programs;  ///< what may be sent: looked up by file stem or program number
    std::string received;  ///< where punch-outs are filed
    bool operator==(const Library&) const = default;
};

struct ServiceConfig {
    std::string path;  ///< the file it was read from
    Library library;
    std::string runtime_directory;  ///< where the control socket goes; empty: default_runtime_directory()
    std::vector<MachineSettings> machines;
};

/// The folder for the control socket: $RUNTIME_DIRECTORY (systemd's), else $XDG_RUNTIME_DIR/tape-dnc,
/// else /tmp/tape-dnc-UID.
std::string default_runtime_directory();
/// The control socket of a service run with config.
std::string control_socket_path(const ServiceConfig& config);

/// What a machine's line is doing.
enum class LineState { opening, listening, receiving, sending, waiting, stopped };
std::string_view line_state_name(LineState s);

struct MachineStatus {
    std::string name{}, device{};
    LineState state = LineState::opening;
    std::string program{};                          ///< the transfer's program (or "punch-out"), empty when none runs
    std::uint64_t frames = 0, total = 0;            ///< done so far, to do (0: unknown, as for a punch-out)
    std::uint64_t sent = 0, filed = 0, failed = 0;  ///< transfers since the start
    std::string last{};                             ///< the last transfer's log line
};

/// Log priorities of sd-daemon(3), as journald keeps them.
enum class Priority { err = 3, warning = 4, notice = 5, info = 6, debug = 7 };
/// One log line: "mill-1: sent O1234 (...): 1543 frames in 1.6 s: done". Called from every machine's
/// thread at once: the sink must be thread-safe.
using LogSink = std::function<void(Priority, const std::string&)>;

/// The running service. Not copyable; every call from one thread (the CLI's main loop).
class Service {
public:
    Service(const ServiceConfig& config, LogSink log, Clock& clock = system_clock());
    ~Service();
    Service(const Service&) = delete;
    Service& operator=(const Service&) = delete;

    /// A config read again: machines removed or whose settings changed are stopped (a transfer cut
    /// is kept as FAILED) and started anew; new ones start; the others keep their transfers.
    void reload(const ServiceConfig& config);
    /// Stops every machine: receptions are cut and kept as FAILED, sendings stop after the current
    /// burst. Waits up to grace; returns the names of machines still blocked then (a write or drain
    /// on a line that takes nothing), which are left to end with the process.
    std::vector<std::string> stop(std::chrono::milliseconds grace);
    std::vector<MachineStatus> status() const;

private:
    struct State;
    std::unique_ptr<State> s_;
};

/// The status as lines of tab-separated fields (what the control socket answers), and back.
std::string status_lines(const std::vector<MachineStatus>& machines);
std::vector<MachineStatus> parse_status_lines(std::string_view text);

/// Serves status on a Unix socket at path (its folder made owner-only, the socket mode 0600, peers of
/// another user refused) from a thread of its own, until destroyed. Throws Error(Errc::io) when the
/// socket cannot be made, Error(Errc::usage) when another service answers there.
class ControlSocket {
public:
    ControlSocket(const std::string& path, std::function<std::string()> answer);
    ~ControlSocket();
    ControlSocket(const ControlSocket&) = delete;
    ControlSocket& operator=(const ControlSocket&) = delete;

private:
    struct State;
    std::unique_ptr<State> s_;
};

/// What the control socket answers a peer that sent `request` (complete: the peer sent all it will):
/// the status lines for "status" (its line's end, LF or CR LF, optional at the end), "" (nothing, the
/// connection closed) for anything else, nullopt while a request may still be coming (no line end yet,
/// under 64 bytes). Never throws but what status throws.
std::optional<std::string> control_reply(std::string_view request, bool complete,
                                         const std::function<std::string()>& status);

/// Asks the service at path for its status lines. Throws Error(Errc::io) when none answers.
std::string query_control_socket(const std::string& path, std::chrono::milliseconds timeout);

}  // namespace tape::dnc
