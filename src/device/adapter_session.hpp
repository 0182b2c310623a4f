// The host's side of the tape adapter protocol (firmware/core/protocol.hpp), once for every transport:
// the CDC, libusb and hidapi backends differ only in the PacketPipe they give it.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/packet.hpp"
#include "core/protocol.hpp"
#include "device_query.hpp"
#include "tape/adapter.hpp"
#include "tape/device.hpp"
#include "tape/error.hpp"

namespace tape::adapter {

/// How packets reach one adapter: COBS on a byte stream (CDC), or one packet per transfer (bulk, HID).
class PacketPipe {
public:
    virtual ~PacketPipe() = default;
    /// Sends one packet. Throws Error(Errc::io) when the adapter is gone.
    virtual void send(const tapefw::Packet& p) = 0;
    /// Waits up to timeout for one packet: nullopt on time-out. Packets failing their CRC or framing
    /// are counted (bad_packets) and skipped. Throws Error(Errc::io) when the adapter is gone.
    virtual std::optional<tapefw::Packet> receive(std::chrono::milliseconds timeout) = 0;
    virtual std::uint64_t bad_packets() const = 0;
    /// As the device string gave it, for messages.
    virtual std::string name() const = 0;
};

/// The vendor and product id a usb: or hid: device string starts with, "1209:0001" in hex.
struct UsbId {
    std::uint16_t vendor = 0, product = 0;
    /// "1209:0001"
    std::string text() const;
};
/// "usb:1209:0001?serial=S" (no "?serial=" for an empty serial): the device string reaching one adapter.
std::string device_string(std::string_view backend, const UsbId& id, std::string_view serial);
/// Error(Errc::usage) when the query's path is no VID:PID. backend: "usb" or "hid", for the message.
UsbId usb_id(std::string_view backend, const DeviceQuery& query);

/// A pipe carrying one packet per transfer (vendor bulk, HID reports): the receive loop and the count of
/// transfers that were no packet, once for both.
class TransferPipe : public PacketPipe {
public:
    std::optional<tapefw::Packet> receive(std::chrono::milliseconds timeout) final;
    std::uint64_t bad_packets() const final { return bad_; }

protected:
    /// Waits up to wait for one transfer into in (room for tapefw::report_size bytes): its bytes, 0 on
    /// time-out, -1 for a transfer that cannot be a packet. Throws Error(Errc::io) when the adapter is gone.
    virtual int receive_transfer(std::uint8_t* in, std::chrono::milliseconds wait) = 0;

private:
    std::uint64_t bad_ = 0;
};

/// Error(Errc::io) "NAME: the adapter is gone (unplugged?)", with why when the library said more.
Error adapter_gone(const std::string& name, const std::string& why = {});
/// Error(Errc::io) "NAME: no adapter VID:PID [with serial S] is attached (attached: A B)": seen are the
/// serials of the adapters with that id that did not match.
Error none_attached(const std::string& name, const UsbId& id, std::optional<std::string_view> serial,
                    const std::vector<std::string>& seen);

/// The pipe to the adapter a device string names (adapter:PATH, usb:VID:PID, hid:VID:PID). Throws
/// Error(Errc::usage) for a string that names no adapter, Error(Errc::io) when it cannot be opened.
std::unique_ptr<PacketPipe> open_pipe(std::string_view device);

/// The settings after '?' every adapter backend takes: which adapter (its serial string), which way
/// its reader reads (direction=forward|reverse), and the unit's line settings, sent as CONFIG when any
/// is given.
inline constexpr std::string_view settings_keys[] = {"serial", "direction", "tracks",
                                                     "invert", "watchdog",  "sprocket-timeout"};

/// What a device string's settings ask of an adapter.
struct Settings {
    std::optional<std::string> serial;     ///< the adapter meant
    tapefw::ReadStart start{};             ///< which way its reader reads
    std::optional<tapefw::Config> config;  ///< sent as CONFIG: some line setting was given
};
/// The query's settings, checked before anything is opened: Error(Errc::usage) for one out of range
/// (adapter_config_problem) or a direction for a punch.
Settings settings_of(const DeviceQuery& query, DeviceUse use);
/// The user's line settings as the CONFIG message carries them.
tapefw::Config to_wire(const AdapterConfig& config);

/// The adapter as a Transport, over pipe, for use: reads are the reader's rows, writes the punch's.
/// Refuses (Error(Errc::io)) an adapter whose serial is not settings.serial, or that cannot read the
/// way asked; sends settings.config.
std::unique_ptr<Transport> open_transport(std::unique_ptr<PacketPipe> pipe, const Settings& settings, DeviceUse use);

/// The pipe to the adapter device names, and its settings (checked before anything is opened).
std::unique_ptr<PacketPipe> open_pipe(std::string_view device, DeviceUse use, Settings& settings);

class Session;
/// Refuses (Error(Errc::io)) an adapter whose serial is not settings.serial, or without the reader
/// (use read) or the punch (use write) asked for; sends settings.config.
void apply_settings(Session& session, const Settings& settings, DeviceUse use);

/// Timing of the host's side; tests shorten nothing, they are the protocol's own numbers.
struct SessionTiming {
    std::chrono::milliseconds reply{300};         ///< wait for a reply before asking again
    int tries = 3;                                ///< requests are sent at most this often
    std::chrono::milliseconds ack_every{50};      ///< ACK (and keep-alive) period while reading or punching
    std::chrono::milliseconds resend_after{150};  ///< a gap not filled after this long is asked for again
    int resend_tries = 5;                         ///< at least so many requests, and
    std::chrono::milliseconds lost_after{750};    ///< this long since the first: then the frames count as lost
    std::chrono::milliseconds silent{2000};       ///< an adapter silent this long while it should talk is dead
};

/// One adapter, opened: reset and asked for its info at once (a protocol mismatch is refused there).
/// Reading and punching as the Transport interface wants them. All failures throw Error(Errc::io)
/// with a message "NAME: frame N: what", where N counts from 1.
class Session {
public:
    explicit Session(std::unique_ptr<PacketPipe> pipe, SessionTiming timing = {});
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    const tapefw::Info& info() const { return info_; }
    std::string name() const { return pipe_->name(); }

    /// Sends a CONFIG and waits for its OK.
    void configure(const tapefw::Config& config);

    /// Rows read, in order, each once; starts the reader on the first call. Waits up to timeout for
    /// the first row. end = true once the tape is out or max_rows are read and every row before is here.
    ReadResult read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout,
                    const tapefw::ReadStart& start = {});
    /// Queues rows to punch; blocks while the adapter's queue is full.
    void punch(std::span<const std::uint8_t> rows);
    /// Blank frames, after everything queued.
    void feed(std::uint16_t count);
    /// Waits until every row queued is punched.
    void drain();
    /// While punching, what a reader of the line would see: nothing, but credits and faults are taken
    /// (a fault throws). Waits up to timeout.
    ReadResult punch_input(std::chrono::milliseconds timeout);
    /// The payload echoed back, or an error. For the link self-test.
    std::vector<std::uint8_t> echo(std::span<const std::uint8_t> payload);

    // Emulating: the adapter stands in for a reader toward a control (docs/adapter-protocol.md).
    /// Sends the wiring (WIRING) and waits for its OK.
    void set_wiring(const tapefw::Wiring& wiring);
    /// Starts an EMULATE session, frames numbered from 0. Throws when the adapter has no emulate role.
    void start_emulation();
    /// Ends it (RESET): the control sees the reader stand.
    void stop_emulation();
    /// What the adapter last said of the control: frames taken, room, its drive lines and turns.
    const tapefw::Taken& taken() const { return taken_; }
    /// Sends the frames numbered first.. (those not yet taken) as far as the adapter has room; frames
    /// already sent go again only when their TAKEN did not come.
    void offer(std::uint32_t first, std::span<const std::uint8_t> frames);
    /// Drops the frames queued from `from` on that the control has not taken; waits for the adapter's TAKEN.
    /// until_start: frames sent after wait for the control's next start (unless it started after from-1).
    void discard(std::uint32_t from, bool until_start = false);
    /// Takes the adapter's news for up to wait, keeping its watchdog quiet. A fault (the watchdog's stop,
    /// an adapter no longer emulating, silence) throws Error(Errc::io).
    void pump_emulation(std::chrono::milliseconds wait);
    /// A run the adapter's watchdog ended while no host listened, as it said after this session's RESET.
    const std::optional<tapefw::Status>& orphaned() const { return orphaned_; }

    /// Rows read or punched so far.
    std::uint64_t rows_read() const { return expected_; }
    std::uint64_t rows_punched() const { return punched_; }
    /// A run of rows the adapter flagged alike (tapefw::row_flag bits), frames counted from 1.
    struct Doubt {
        std::uint64_t first = 0, last = 0;
        std::uint8_t flags = 0;
    };
    /// The runs of flagged rows since the last call, and how many flagged rows were only counted
    /// (beyond max_doubts runs kept, so that a tape flagged throughout takes bounded memory).
    std::vector<Doubt> take_doubts() { return std::exchange(doubts_, {}); }
    std::uint64_t take_unkept_doubts() { return std::exchange(unkept_doubts_, 0); }
    static constexpr std::size_t max_doubts = 10000;
    /// Frame ranges (from, to, counted from 1) that were missing or damaged and then came again.
    const std::vector<std::pair<std::uint64_t, std::uint64_t>>& recovered() const { return recovered_; }
    /// Packets from the adapter that failed their CRC, and ours it reported as such.
    std::uint64_t bad_packets_in() const { return pipe_->bad_packets(); }
    std::uint64_t bad_packets_out() const { return bad_out_; }

private:
    using clock = std::chrono::steady_clock;
    std::unique_ptr<PacketPipe> pipe_;
    SessionTiming t_;
    tapefw::Info info_{};
    std::uint8_t seq_ = 0;
    std::uint64_t bad_out_ = 0;
    clock::time_point last_sent_{}, last_heard_{};
    std::uint64_t bad_when_heard_ = 0;  ///< the pipe's bad packets when a good one last came

    // Reading.
    bool reading_ = false;
    std::uint32_t expected_ = 0;
    std::uint32_t acked_ = 0;  ///< the last ACK sent
    std::deque<std::uint8_t> ready_;
    std::optional<std::uint32_t> end_at_;   ///< the tape ended (or max_rows) after this many rows
    std::optional<std::uint32_t> gap_end_;  ///< rows expected_.. gap_end_-1 are missing
    clock::time_point gap_asked_{};
    int gap_tries_ = 0;
    std::uint32_t gap_first_ = 0;
    clock::time_point gap_since_{};  ///< when the first request for the open gap went out
    std::vector<std::pair<std::uint64_t, std::uint64_t>> recovered_;
    std::uint64_t bad_seen_ = 0;
    std::vector<Doubt> doubts_;
    std::uint64_t unkept_doubts_ = 0;
    void note_flags(std::uint32_t row, std::uint8_t flags);
    /// A fault that ends the run once every row before its frame is here.
    struct Pending {
        std::uint32_t frame;
        std::string what;
    };
    std::optional<Pending> pending_;

    // Punching: rows_ holds the rows queued from frame rows_base_ on (those the adapter has not taken
    // into its queue yet, to send again if need be), so that a tape of any length takes bounded memory.
    std::deque<std::uint8_t> rows_;
    std::uint32_t rows_base_ = 0;
    bool punching_ = false;
    std::uint32_t sent_to_ = 0, credit_next_ = 0, punched_ = 0;
    std::uint32_t credit_free_ = 0;
    clock::time_point last_credit_{};
    std::uint32_t feeds_ = 0;

    // Emulating.
    bool emulating_ = false;
    tapefw::Taken taken_{};
    std::uint32_t emu_sent_to_ = 0;
    clock::time_point last_taken_{};  ///< when the adapter's next frame expected last moved
    std::optional<tapefw::Status> orphaned_;
    void handle_taken(const tapefw::Packet& p);

    std::uint8_t send(tapefw::Packet p);
    std::optional<tapefw::Packet> receive(std::chrono::milliseconds timeout);
    std::uint64_t position() const;
    [[noreturn]] void rethrow(const Error& e) const;
    tapefw::Packet request(const tapefw::Packet& p, tapefw::Msg reply);
    void handle(const tapefw::Packet& p);
    void handle_rows(const tapefw::Packet& p);
    void handle_status(const tapefw::Packet& p);
    void pump(std::chrono::milliseconds wait);
    void keep_alive();
    void check_gap();
    /// The first request to resend from expected_ for a gap from there.
    void start_gap();
    /// RESEND from expected_, timed for check_gap's next try.
    void ask_resend();
    [[noreturn]] void fail(std::uint64_t frame, const std::string& what) const;
    /// A reply that breaks the protocol: Error(Errc::io) "protocol error: what".
    [[noreturn]] void protocol_error(std::uint64_t frame, const std::string& what) const;
    /// Why the adapter is not heard: silent, or every packet it sends fails its CRC.
    std::string silence(const std::string& what) const;
    /// A good packet came: the adapter is heard.
    void heard();
    void handle_credit(const tapefw::Packet& p);
    std::uint32_t rows_queued() const { return rows_base_ + static_cast<std::uint32_t>(rows_.size()); }
};

}  // namespace tape::adapter
