// Devices over a transport: sending frames (feeding a controller, punching), receiving them (from a
// controller or a reader), and emulating a tape reader a controller pulls from.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "tape/clock.hpp"
#include "tape/code.hpp"
#include "tape/device.hpp"
#include "tape/frame.hpp"
#include "tape/line_state.hpp"

namespace tape {

/// How far a run has come, for progress displays.
struct LineProgress {
    std::uint64_t frames = 0;  ///< sent or received so far
    std::uint64_t total = 0;   ///< to send (0 when unknown)
    std::uint64_t pauses = 0;  ///< XOFFs (DC3) received
    bool paused = false;
    double rate = 0;  ///< frames per second so far
};

/// The slowest pacing a rate may ask for: one frame a day. A slower rate is a mistake, and its period
/// would not fit the clock's durations.
inline constexpr double min_frame_rate = 1.0 / 86400;

/// The time between frames at rate frames per second (zero when that is below the clock's resolution).
/// Throws Error(Errc::usage) unless rate is a finite number from min_frame_rate up.
std::chrono::steady_clock::duration frame_period(double rate);

/// Frames to send, a chunk at a time, so that a tape of any length is sent in bounded memory.
class FrameSource {
public:
    virtual ~FrameSource() = default;
    /// The next frames, valid until the next call; empty at the end. Throws Error for a bad input.
    virtual std::span<const Frame> next() = 0;
    /// The frames in all when known before they are read (for progress displays), else 0.
    virtual std::uint64_t total() const { return 0; }
};

/// Frames already in memory, as a source of one chunk.
class SpanSource : public FrameSource {
public:
    explicit SpanSource(std::span<const Frame> frames) : frames_(frames) {}
    std::span<const Frame> next() override { return std::exchange(frames_, {}); }
    std::uint64_t total() const override { return total_; }

private:
    std::span<const Frame> frames_;
    std::uint64_t total_ = frames_.size();
};

struct SendOptions {
    double rate = 0;                           ///< frames per second; 0: the line's rate, or unpaced for files
    std::optional<Flow> flow{};                ///< default: what the device string says
    bool wait_xon = false;                     ///< send nothing before the first DC1 from the other side
    std::chrono::milliseconds xon_timeout{0};  ///< with wait_xon: give up after this long (0: wait for ever)
    std::uint8_t xon = dc1, xoff = dc3;        ///< the flow characters (Fanuc-style DC1/DC3 by default), bit 8 ignored
    const std::atomic<bool>* stop = nullptr;   ///< set (e.g. by SIGINT) to stop after the current frame
    std::function<void(const LineProgress&)> progress{};  ///< called a few times a second
    /// Frames handed to the line at one wake-up, the later ones ahead of their paced time by less than
    /// the burst (the rate on average stays exact): fewer wake-ups at line speed, where the UART paces. The line is
    /// looked at before each burst, so after DC3 at most one burst more goes out (Fanuc takes up to 10 characters after
    /// DC3).
    std::size_t burst = 1;
    std::chrono::milliseconds block_delay{0};  ///< a pause after each block_end frame, for controls that need it
    Frame block_end = 0x0A;                    ///< the end-of-block frame (ISO LF; EIA's is 0x80)
    /// With XON/XOFF the line is read while sending: what the other side sends besides XON and XOFF (a
    /// control punching out its next request at once) goes here, in order, as it was read. Without it,
    /// it is dropped.
    std::function<void(std::span<const std::uint8_t>)> other_input{};
};

struct SendResult {
    std::uint64_t sent = 0;
    std::uint64_t pauses = 0;
    bool stopped = false;  ///< ended by the stop flag before the last frame
};

/// Sends frames in order, each exactly once: paced, paused by DC3 (or CTS dropped) before the next
/// frame and resumed by DC1, with track 8 dropped on a 7-bit line (the UART adds the parity).
/// Throws Error(Errc::io) naming the frame when the other side hangs up or no DC1 comes in time;
/// Error(Errc::usage), before sending anything, for a rate frame_period refuses, RTS/CTS on a line
/// without modem lines, or the same character for XON and XOFF; and before the chunk that holds it
/// (the first chunk before anything is sent), for a frame a 7-bit line cannot carry. Once the stop
/// flag is set the run ends as stopped, whatever the device says after it (a fault the stop itself
/// caused, such as an adapter's watchdog, does not turn it into a failure); what is queued is not
/// waited for.
SendResult send_frames(Transport& line, FrameSource& frames, const SendOptions& options, Clock& clock = system_clock());
/// The same for frames in memory.
SendResult send_frames(Transport& line, std::span<const Frame> frames, const SendOptions& options,
                       Clock& clock = system_clock());

struct ReceiveOptions {
    std::chrono::milliseconds idle_timeout{0};  ///< end after this long without a frame (0: never)
    bool until_program_end = false;             ///< end at the '%' after M02/M30
    Code code = Code::iso;                      ///< to recognise M02/M30 and '%'
    Parity parity = Parity::even;               ///< ISO only: the track 8 rule, also to restore track 8 on a 7-bit line
    const CodeTable* eia_table = nullptr;       ///< a corrected EIA table; nullptr = built-in
    bool drop_flow_codes = false;               ///< DC1-DC4 are line control, not tape: not kept
    const std::atomic<bool>* stop = nullptr;
    std::function<void(std::span<const Frame>)> sink{};  ///< every frame, as it arrives
    std::function<void(const LineProgress&)> progress{};
    /// Asked of each frame kept, in order, before the frames of its read go to sink: true ends the
    /// run once the frames of this read are kept (End::program_end), for callers that know the end of
    /// what they receive better (a DNC punch-out ends at its closing '%'). Nothing that came is dropped.
    std::function<bool(Frame)> ends_after{};
    /// Bytes already read from this line (by an earlier run, or by a sender while it watched for XOFF):
    /// taken first, by the same rules as a read, before the line is read.
    std::span<const std::uint8_t> first{};
    /// After each read that brought frames, wait this long before the next, so that one read takes
    /// what a slow line brought meanwhile: fewer wake-ups for many lines at once (the kernel keeps it).
    std::chrono::milliseconds gather{0};
};

struct ReceiveResult {
    enum class End { program_end, idle, hangup, stopped };
    std::uint64_t frames = 0;
    End end = End::hangup;
};

/// Receives frames until the end the options ask for. Frames go to sink as they arrive, so nothing
/// already received is lost whatever ends the run. On a line with modem lines RTS is asserted while
/// receiving and dropped at the end. On stop it sends DC3 (and drops RTS) and still takes what the
/// other side sends in the next moments (controllers may send up to 10 characters after DC3), by the
/// same rules. With drop_flow_codes an ISO DC1-DC4 is dropped in either parity (0x13 and 0x93 are
/// both DC3). On a 7-bit line (Transport::seven_bit) track 8 is restored by the parity rule, as the
/// encoder punches it (mark: always; space, none: never; even, odd: by the count of holes; blank tape
/// stays blank); such a line cannot carry EIA (Error(Errc::usage) for Code::eia).
ReceiveResult receive_frames(Transport& line, const ReceiveOptions& options, Clock& clock = system_clock());

struct EmulatorOptions {
    double rate = 1500;                         ///< frames per second (ФС-1501)
    bool skip_leader = true;                    ///< start at the first punched frame
    std::uint8_t start = dc1, stop_code = dc3;  ///< DC1 starts the reader, DC3 stops it
    std::uint8_t search = ':';                  ///< then optional digits: search forward to that main block
    std::uint8_t rewind = '%';                  ///< rewind to the '%' stop before the current position
    Code code = Code::iso;
    Parity parity = Parity::even;             ///< ISO only: the track 8 rule the tape was punched with
    const CodeTable* eia_table = nullptr;     ///< a corrected EIA table; nullptr = built-in
    std::optional<Flow> flow{};               ///< rtscts: CTS starts and stops the reader instead of DC1/DC3
    const std::atomic<bool>* stop = nullptr;  ///< ends the emulation
    std::function<void(std::uint64_t frame, const std::string& what)> log{};  ///< tape position events
};

struct EmulatorResult {
    std::uint64_t frames_sent = 0;  ///< counting each frame again after a rewind
    std::uint64_t starts = 0, stops = 0, rewinds = 0, searches = 0;
};

/// Acts as a tape reader holding tape: on DC1 (or CTS) sends frames at the rate, on DC3 stops before
/// the next frame (the line is looked at right before each one), at the end of a program (the block
/// with M02/M30) rewinds to its '%' and waits, and on request searches forward to a main block or
/// rewinds. Runs until stop is set. A hang-up, while sending or not, throws Error(Errc::io) ending
/// "; N frame(s) sent"; a rate frame_period refuses or RTS/CTS on a line without modem lines throws
/// Error(Errc::usage) before anything is sent.
EmulatorResult emulate_reader(Transport& line, std::span<const Frame> tape, const EmulatorOptions& options,
                              Clock& clock = system_clock());

/// Where a reader searching forward from `from` stops: the next ':' frame (with that block number,
/// when given). nullopt when there is none.
std::optional<std::size_t> seek_main_block(std::span<const Frame> tape, std::size_t from, const FrameCode& code,
                                           std::optional<long long> number = {});
/// Where a reader rewinding from `from` stops: the last '%' frame before it, or 0.
std::size_t seek_rewind_stop(std::span<const Frame> tape, std::size_t from, const FrameCode& code);

}  // namespace tape
