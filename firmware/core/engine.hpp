// The adapter's protocol engine: takes packets from the host, drives the reader and the punch through
// Hardware, and sends rows, credits and status back. No heap, no exceptions: fixed buffers sized here.
//
// Reading: rows from the sprocket interrupt go into a ring numbered by a running frame counter. They
// are sent in ROWS packets and kept until the host acknowledges them (ACK), so that a RESEND after a
// bad or lost packet can send them again. When the ring is nearly full the reader is stopped (a
// start-stop reader stops within a frame or two), and started again when the host has caught up.
// Punching: PUNCH rows are queued and answered by CREDIT (the next row expected and the free space);
// the queue drains one row per punch cycle. Emulating (standing in for a reader toward a control):
// FRAMES are queued by credit as for the punch, and the board's frame clock takes them one a slot
// (next_frame) while the control's start line is on; its stop is obeyed here, within Wiring::braking
// frames, and every frame taken is counted and reported (TAKEN). A watchdog stops the reader, the punch
// and the emulated reader when the host has been silent for Config::watchdog_ms, and says so again
// after the next RESET (the host that was gone hears it when it comes back).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/hardware.hpp"
#include "core/packet.hpp"
#include "core/protocol.hpp"

namespace tapefw {

/// How packets travel on the endpoint.
enum class Framing : std::uint8_t {
    stream,   ///< COBS-framed on a byte stream (CDC)
    packets,  ///< one packet per transfer (HID reports, bulk)
};

struct Identity {
    std::uint8_t firmware[3] = {0, 1, 0};
    std::uint8_t capabilities = caps::reader | caps::punch;
    std::uint8_t tracks = 0x0F;  ///< 5..8 tracks
    std::uint16_t max_read_rate = 1500;
    std::uint16_t max_punch_rate = 150;
    const char* serial = "0000";
};

class Engine {
public:
    static constexpr std::size_t read_ring = 1024;            ///< rows held for resending (a power of two)
    static constexpr std::size_t punch_ring = 256;            ///< rows queued for the punch (a power of two)
    static constexpr std::size_t stop_margin = 128;           ///< free rows left when the reader is stopped
    static constexpr std::uint32_t rows_flush_us = 10000;     ///< a partial ROWS packet waits at most this
    static constexpr std::uint32_t credit_every_us = 100000;  ///< CREDIT while the punch drains
    static constexpr std::size_t emulate_ring = 1024;         ///< frames queued for the control (a power of two)
    static constexpr std::uint32_t taken_every_us = 20000;    ///< TAKEN while the control takes frames
    static constexpr std::uint32_t taken_idle_us = 100000;    ///< TAKEN while nothing changes (a heartbeat)

    /// defaults: the line settings until the host sends a CONFIG (a board may keep its unit's in flash).
    Engine(Hardware& hw, const Identity& id, Framing framing = Framing::stream, const Config& defaults = {});

    /// Bytes from the OUT endpoint: a stream piece (Framing::stream) or one whole packet.
    void receive(const std::uint8_t* bytes, std::size_t n);
    /// A row sampled at a sprocket (levels of the data lines), from the interrupt.
    void on_row(std::uint8_t lines, std::uint8_t flags = 0);
    /// The main loop's turn: sends what is due, drives the punch, watches time-outs.
    void poll();
    /// The control's drive lines changed (drive_bit bits), from the board's edge interrupt.
    void on_drive(std::uint8_t lines);
    /// A frame slot of the emulate role, from the board's frame clock: the data-line levels to strobe.
    Slot next_frame(std::uint8_t& levels);

    const Config& config() const { return config_; }
    bool reading() const { return reading_; }
    std::uint32_t rows_read() const { return head_; }
    std::uint32_t rows_punched() const { return punched_; }
    /// Packets that failed their CRC or framing.
    std::uint32_t bad_packets() const { return bad_packets_; }
    bool emulating() const { return emulating_; }
    std::uint32_t frames_taken() const { return emu_taken_; }
    const Wiring& wiring() const { return wiring_; }

private:
    Hardware& hw_;
    Identity id_;
    Framing framing_;
    Config config_{};
    StreamDecoder decoder_{};
    std::uint8_t seq_ = 0;
    std::uint32_t last_host_us_ = 0;
    bool host_seen_ = false;
    std::uint32_t bad_packets_ = 0;

    // Reading. Frame numbers: base_ <= sent_ <= head_; rows base_..head_-1 are held.
    std::uint8_t rows_[read_ring] = {};
    std::uint8_t flags_[read_ring] = {};
    volatile std::uint32_t head_ = 0;
    std::uint32_t base_ = 0, sent_ = 0;
    bool reading_ = false;  ///< the host wants rows (READ_START until READ_STOP or an end)
    bool driving_ = false;  ///< the reader's motor is told to run
    bool paused_ = false;   ///< stopped for lack of room, to go on when the host catches up
    std::uint8_t reverse_ = 0;
    std::uint32_t max_rows_ = 0, start_frame_ = 0;
    volatile std::uint32_t last_row_us_ = 0;  ///< set by the sprocket interrupt (on_row)
    std::uint32_t last_rows_sent_us_ = 0;
    std::uint16_t rate_ = 0;
    std::uint32_t window_start_us_ = 0, window_rows_ = 0;  ///< rows in the current second, for rate
    bool overrun_ = false;
    std::uint32_t overrun_frame_ = 0;

    // Punching. punch_next_ is the next host row expected; queued rows are punch_tail_..punch_next_-1.
    std::uint8_t punch_rows_[punch_ring] = {};
    std::uint32_t punch_next_ = 0, punch_tail_ = 0, punched_ = 0;
    std::uint32_t feed_left_ = 0;
    std::uint32_t last_credit_us_ = 0, credited_punched_ = 0;

    // Emulating. Frames emu_taken_..emu_next_-1 are queued; the frame clock takes from emu_taken_.
    Wiring wiring_{};
    std::uint8_t emu_frames_[emulate_ring] = {};
    volatile std::uint32_t emu_taken_ = 0;
    std::uint32_t emu_next_ = 0;
    bool emulating_ = false;
    volatile std::uint8_t drive_in_ = 0;      ///< the control's lines, drive_bit bits
    volatile std::uint8_t braking_left_ = 0;  ///< frames still allowed after the control's stop
    volatile std::uint8_t turn_ = 0;          ///< the control's turns (direction, rewind): the queue dropped
    volatile std::uint16_t stops_ = 0;
    volatile std::uint8_t rewinds_ = 0;
    volatile std::uint32_t started_at_ = 0;  ///< frames taken at the control's last start
    volatile bool until_start_ = false;      ///< frames wait for the control's next start (DISCARD)
    Taken reported_{};                       ///< the last TAKEN sent
    std::uint32_t last_taken_us_ = 0;
    Status orphan_{};  ///< a run the watchdog ended, told again after the next RESET

    static constexpr std::size_t outbox_size = 4;
    Packet outbox_[outbox_size] = {};
    std::size_t outbox_n_ = 0;

    std::uint16_t last_status_ = 0;
    Status last_event_{};  ///< the last STATUS sent, sent again on a RESEND after the run ended

    void watch_reading(std::uint32_t now, std::uint16_t lines);
    std::uint32_t since_row(std::uint32_t now) const;
    void drive_punch(std::uint16_t lines);
    void handle(const Packet& p);
    // The host's requests, one function each.
    void send_info(const Packet& request);
    void configure(const Packet& p);
    void start_reading(const Packet& p);
    void queue_punch(const Packet& p);
    void queue_feed(const Packet& p);
    void take_ack(const Packet& p);
    void resend(const Packet& p);
    void reset(const Packet& p);
    void set_wiring(const Packet& p);
    void start_emulation(const Packet& p);
    void queue_frames(const Packet& p);
    void discard_frames(const Packet& p);
    /// TAKEN when the control's lines or turn changed, frames were taken, or as a heartbeat.
    void report_taken(std::uint32_t now);
    bool send_taken(std::uint8_t seq);
    bool busy() const { return reading_ || punch_queued() || feed_left_ || emulating_; }
    bool send_packet(const Packet& p);
    /// Replies and STATUS: sent now, or from the outbox as soon as the endpoint takes them.
    void post(const Packet& p);
    void flush_outbox();
    void reply_ok(const Packet& request);
    void reply_error(const Packet& request, ErrorCode code, std::uint32_t frame);
    void send_status(std::uint16_t event_bits, std::uint32_t frame);
    void send_packet_status(const Status& s);
    void send_credit(std::uint8_t seq);
    void send_rows(bool partial);
    void set_drive(bool on);
    void stop_all();
    /// Ends a read run: the reader stopped, the rows held sent, then STATUS with event_bits.
    void end_read(std::uint16_t event_bits);
    std::uint16_t status_bits();
    std::uint32_t read_free() const { return static_cast<std::uint32_t>(read_ring) - (head_ - base_); }
    std::uint32_t punch_queued() const { return punch_next_ - punch_tail_; }
};

}  // namespace tapefw
