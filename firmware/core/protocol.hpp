// The tape adapter protocol: message types, their payloads, status bits and error codes. One header,
// shared word for word by the adapter firmware and the host (src/device/adapter_*.cpp); the layout of
// every payload is in docs/adapter-protocol.md. Numbers are little-endian. Each message type has a
// struct with encode (into a Packet) and decode (false when the payload has the wrong size).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/packet.hpp"

namespace tapefw {

/// Bumped on any change a peer could misread; the host refuses an adapter with another version.
inline constexpr std::uint8_t protocol_version = 1;

/// The open-source vendor id (pid.codes) and a product id from its test range, until one is assigned.
inline constexpr std::uint16_t usb_vendor_id = 0x1209;
inline constexpr std::uint16_t usb_product_id = 0x0001;

/// Message types: host to adapter below 0x80, adapter to host from 0x80.
enum class Msg : std::uint8_t {
    get_info = 0x01,    ///< -> info
    config = 0x02,      ///< Config -> ok
    read_start = 0x03,  ///< ReadStart -> ok, then rows as they are read
    read_stop = 0x04,   ///< -> ok; rows read while the reader brakes still follow
    punch = 0x05,       ///< Punch -> credit
    feed = 0x06,        ///< Feed (blank frames) -> ok
    ack = 0x07,         ///< FrameNumber: rows before it may be forgotten; also keeps the watchdog quiet
    resend = 0x08,      ///< FrameNumber: send the rows again from there (after a gap or a bad packet)
    reset = 0x09,       ///< -> ok; reader and punch stopped, counters and buffers cleared, config kept
    echo = 0x0A,        ///< any payload -> echo_reply with the same payload (link self-test)
    wiring = 0x0B,      ///< Wiring: the emulate role's lines and timing -> ok
    emulate = 0x0C,     ///< -> ok; the adapter stands in for a reader toward the control, frames from 0
    frames = 0x0D,      ///< Frames for the control -> taken
    discard = 0x0E,     ///< Discard: frames queued and not yet taken are dropped -> taken
    info = 0x81,        ///< Info
    ok = 0x82,          ///< Ok: the request (same seq) was done
    rows = 0x83,        ///< Rows
    credit = 0x84,      ///< Credit
    taken = 0x87,       ///< Taken: what the control took, the queue's room and the control's drive lines
    status = 0x85,      ///< Status
    error = 0x86,       ///< ErrorReply (same seq as the request, or 0 for an event)
    echo_reply = 0x8A,  ///< the echo's payload
};

/// Stable error codes; names in error_name().
enum class ErrorCode : std::uint8_t {
    none = 0,
    unknown_message = 1,  ///< a type the adapter does not know
    bad_payload = 2,      ///< a payload of the wrong size or with a value out of range
    no_reader = 3,        ///< reading asked of an adapter without a reader
    no_punch = 4,         ///< punching asked of an adapter without a punch
    busy = 5,             ///< the reader already runs, or the punch has rows queued
    out_of_order = 6,     ///< a PUNCH starting past the next frame expected (frame: the one expected)
    resend_gone = 7,      ///< a RESEND for rows already forgotten (frame: the oldest still held)
    overrun = 8,          ///< rows arrived with the buffer full: rows lost (frame: the first lost)
    bad_packet = 9,       ///< a packet failed its CRC or framing (sent once per bad packet)
    no_emulator = 10,     ///< the emulate role asked of an adapter without it
    not_emulating = 11,   ///< FRAMES or DISCARD outside an EMULATE session (frame: frames taken before it ended)
};
const char* error_name(ErrorCode code);

/// Status bits, as STATUS reports them (an event bit is set in the one report of the event).
namespace status {
inline constexpr std::uint16_t tape_out = 1 << 0;         ///< no tape in the reader: its end has passed the head
inline constexpr std::uint16_t torn = 1 << 1;             ///< event: no sprocket within the time-out while driving
inline constexpr std::uint16_t low_tape = 1 << 2;         ///< the punch's supply roll is nearly empty
inline constexpr std::uint16_t chad_full = 1 << 3;        ///< the punch's chad box is full
inline constexpr std::uint16_t motor_fault = 1 << 4;      ///< a motor did not come up to speed
inline constexpr std::uint16_t offline = 1 << 5;          ///< the unit is switched off-line
inline constexpr std::uint16_t watchdog = 1 << 6;         ///< event: the host was silent; reader and punch stopped
inline constexpr std::uint16_t reading = 1 << 7;          ///< the reader is driving tape
inline constexpr std::uint16_t punching = 1 << 8;         ///< the punch has rows to punch
inline constexpr std::uint16_t read_done = 1 << 9;        ///< event: max_rows read, the reader stopped
inline constexpr std::uint16_t punch_tape_out = 1 << 10;  ///< the punch's supply roll ran out
inline constexpr std::uint16_t emulating = 1 << 11;       ///< the adapter stands in for a reader (EMULATE)
/// The bits that stop a run.
inline constexpr std::uint16_t faults = tape_out | torn | chad_full | motor_fault | offline | watchdog | punch_tape_out;
}  // namespace status

/// Capability bits in Info::capabilities.
namespace caps {
inline constexpr std::uint8_t reader = 1 << 0;
inline constexpr std::uint8_t punch = 1 << 1;
inline constexpr std::uint8_t reverse = 1 << 2;    ///< the reader can read backwards
inline constexpr std::uint8_t row_flags = 1 << 3;  ///< rows carry timing and level flags
inline constexpr std::uint8_t emulate = 1 << 4;    ///< stands in for a reader toward a control (EMULATE)
}  // namespace caps

/// Per-row flags in Rows.
namespace row_flag {
inline constexpr std::uint8_t no_sprocket = 1 << 0;  ///< the row was sampled by time, no sprocket seen
inline constexpr std::uint8_t timing = 1 << 1;       ///< the sprocket came early or late
inline constexpr std::uint8_t marginal = 1 << 2;     ///< a data line was near its threshold
}  // namespace row_flag

/// Bits of Config::lines.
namespace line_bit {
inline constexpr std::uint8_t sprocket_low = 1 << 0;      ///< the sprocket signal is active low
inline constexpr std::uint8_t strobe_falling = 1 << 1;    ///< sample on the falling edge of the sprocket
inline constexpr std::uint8_t drive_pulse = 1 << 2;       ///< start and stop are pulses, not a level
inline constexpr std::uint8_t drive_low = 1 << 3;         ///< start/stop and direction lines are active low
inline constexpr std::uint8_t status_low = 1 << 4;        ///< tape-out and fault inputs are active low
inline constexpr std::uint8_t punch_ready_low = 1 << 5;   ///< the punch's ready (sync) input is active low
inline constexpr std::uint8_t punch_magnet_low = 1 << 6;  ///< the punch magnets are driven by a low level
}  // namespace line_bit

/// The control's drive lines toward the reader the adapter stands in for, as Taken::drive carries them
/// and Engine::on_drive takes them (the board has applied their polarity).
namespace drive_bit {
inline constexpr std::uint8_t run = 1 << 0;      ///< start: the control wants frames (clear: stop)
inline constexpr std::uint8_t reverse = 1 << 1;  ///< the control reads backwards
inline constexpr std::uint8_t rewind = 1 << 2;   ///< the control asks for the tape rewound
}  // namespace drive_bit

/// Bits of Wiring::lines: the polarity of the emulate role's lines.
namespace wiring_bit {
inline constexpr std::uint8_t strobe_low = 1 << 0;   ///< the sprocket strobe toward the control is active low
inline constexpr std::uint8_t run_low = 1 << 1;      ///< the control's start/stop line is active low
inline constexpr std::uint8_t reverse_low = 1 << 2;  ///< its direction line is active low
inline constexpr std::uint8_t rewind_low = 1 << 3;   ///< its rewind line is active low
}  // namespace wiring_bit

struct Info {
    std::uint8_t protocol = protocol_version;
    std::uint8_t firmware[3] = {0, 0, 0};  ///< major, minor, patch
    std::uint8_t capabilities = 0;         ///< caps bits
    std::uint8_t tracks = 0;               ///< bit n-5 set: reads or punches n-track tape (5..8)
    std::uint16_t max_read_rate = 0;       ///< frames per second
    std::uint16_t max_punch_rate = 0;
    std::uint16_t read_buffer = 0;   ///< rows the adapter holds for resending
    std::uint16_t punch_buffer = 0;  ///< rows the punch queue holds
    char serial[17] = {};            ///< the USB serial string, NUL-terminated
    bool encode(Packet& p) const;
    bool decode(const Packet& p);
};

struct Config {
    std::uint8_t data_invert = 0;            ///< bit n: data line n is active low (a hole reads as 0)
    std::uint8_t lines = 0;                  ///< line_bit bits
    std::uint8_t tracks = 8;                 ///< 5..8: rows are masked to that many tracks
    std::uint16_t sample_delay_us = 50;      ///< from the sprocket edge to sampling the data lines
    std::uint16_t punch_pulse_us = 2500;     ///< how long the punch magnets are held
    std::uint16_t drive_pulse_us = 1000;     ///< start and stop pulse length, with line_bit::drive_pulse
    std::uint16_t sprocket_timeout_ms = 50;  ///< no sprocket for this long while driving: torn tape
    std::uint16_t watchdog_ms = 500;         ///< host silent for this long: reader and punch stopped (0: never)
    bool encode(Packet& p) const;
    bool decode(const Packet& p);
};

struct ReadStart {
    std::uint8_t reverse = 0;    ///< 1: read backwards
    std::uint16_t rate = 0;      ///< frames per second the host wants at most (0: the reader's speed)
    std::uint32_t max_rows = 0;  ///< stop after this many rows (0: until the tape ends)
    bool encode(Packet& p) const;
    bool decode(const Packet& p);
};

/// The emulate role's wiring and timing (WIRING). Pins are the board's own numbers (GPIO n); no_pin for
/// a line the control does not have. A frame slot: data set, setup_us later the strobe for strobe_us,
/// the data held hold_us after it; slots follow at rate frames per second.
struct Wiring {
    static constexpr std::uint8_t no_pin = 0xFF;
    static constexpr std::uint8_t max_pin = 63;
    static constexpr std::uint8_t max_braking = 2;
    std::uint8_t data_pins[8] = {0, 1, 2, 3, 4, 5, 6, 7};  ///< track 1..8 (tracks past Wiring::tracks unused)
    std::uint8_t strobe_pin = 8;
    std::uint8_t run_pin = 9;
    std::uint8_t reverse_pin = no_pin;
    std::uint8_t rewind_pin = no_pin;
    std::uint8_t data_invert = 0;  ///< bit n: data line n is driven low for a hole
    std::uint8_t lines = 0;        ///< wiring_bit bits
    std::uint8_t tracks = 8;       ///< 5..8
    std::uint8_t braking = 1;      ///< frames the control may still see after its stop, 0..2 (a ФС-1501: 1)
    std::uint16_t rate = 1500;     ///< frames per second, 1..4000
    std::uint16_t strobe_us = 100;
    std::uint16_t setup_us = 50;          ///< data on the lines before the strobe
    std::uint16_t hold_us = 50;           ///< data kept after the strobe
    std::uint16_t start_delay_us = 1000;  ///< from the control's start to the first frame slot
    bool encode(Packet& p) const;
    bool decode(const Packet& p);
    /// Why these settings cannot work ("setup, strobe and hold take longer than a frame"), or nullptr.
    const char* problem() const;
    std::uint32_t period_us() const { return 1000000u / rate; }
};

/// Frames for the control, numbered from 0 since EMULATE; a repeated frame (a resend) is taken once.
struct Frames {
    static constexpr std::size_t max_frames = max_payload - 5;
    std::uint32_t first = 0;
    std::uint8_t turn = 0;  ///< the Taken::turn the host had seen: frames for an older turn are dropped
    std::uint8_t count = 0;
    std::uint8_t frames[max_frames] = {};
    bool encode(Packet& p) const;
    bool decode(const Packet& p);
};

/// DISCARD: frames queued from `from` on and not yet taken are dropped (the host rewound or searched).
/// With until_start, the frames queued after it wait for the control's next start, unless it started
/// again after taking frame from-1 (a program's end: the control stops there and is started again).
struct Discard {
    std::uint32_t from = 0;
    std::uint8_t until_start = 0;
    bool encode(Packet& p) const;
    bool decode(const Packet& p);
};

/// TAKEN: every frame before `taken` the control has taken (strobed), in order, once.
struct Taken {
    std::uint32_t next = 0;    ///< the next frame the adapter expects (all before it are queued or taken)
    std::uint32_t taken = 0;   ///< frames the control took
    std::uint16_t free = 0;    ///< frames the queue can still take
    std::uint8_t drive = 0;    ///< drive_bit bits: the control's lines now
    std::uint8_t turn = 0;     ///< counts the control's turns (direction or rewind changed): queue dropped
    std::uint16_t stops = 0;   ///< the control's stops so far (wraps)
    std::uint8_t rewinds = 0;  ///< the control's rewinds so far (its rewind line set; wraps)
    bool encode(Packet& p) const;
    bool decode(const Packet& p);
};

/// ACK and RESEND.
struct FrameNumber {
    std::uint32_t frame = 0;
    bool encode(Packet& p, Msg type) const;
    bool decode(const Packet& p);
};

/// Rows read, numbered from 0 since READ_START by a running counter: a gap or an overlap shows at once.
struct Rows {
    static constexpr std::size_t max_rows = max_payload - 5;
    std::uint32_t first = 0;
    std::uint8_t count = 0;
    std::uint8_t rows[max_rows] = {};
    std::uint8_t flags[max_rows] = {};  ///< row_flag bits; sent as (index, flags) pairs after the rows
    /// False when count and the flagged rows do not fit one packet (flags of the last rows are then dropped).
    bool encode(Packet& p) const;
    bool decode(const Packet& p);
};

/// Rows to punch, numbered from 0 since the last RESET; a repeated row (a resend) is taken once.
struct Punch {
    static constexpr std::size_t max_rows = max_payload - 4;
    std::uint32_t first = 0;
    std::uint8_t count = 0;
    std::uint8_t rows[max_rows] = {};
    bool encode(Packet& p) const;
    bool decode(const Packet& p);
};

struct Credit {
    std::uint32_t next = 0;     ///< the next punch row the adapter expects (all before it are queued)
    std::uint32_t punched = 0;  ///< rows punched
    std::uint16_t free = 0;     ///< rows the queue can still take
    bool encode(Packet& p) const;
    bool decode(const Packet& p);
};

struct Feed {
    std::uint16_t count = 0;
    bool encode(Packet& p) const;
    bool decode(const Packet& p);
};

struct Status {
    std::uint16_t bits = 0;
    std::uint32_t frame = 0;  ///< rows read (reading) or punched (punching) when it happened
    bool encode(Packet& p) const;
    bool decode(const Packet& p);
};

struct ErrorReply {
    ErrorCode code = ErrorCode::none;
    std::uint8_t about = 0;  ///< the type of the request
    std::uint32_t frame = 0;
    bool encode(Packet& p) const;
    bool decode(const Packet& p);
};

struct Ok {
    std::uint8_t about = 0;  ///< the type of the request done
    bool encode(Packet& p) const;
    bool decode(const Packet& p);
};

}  // namespace tapefw
