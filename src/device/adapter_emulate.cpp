// tape emulate through a USB tape adapter standing in for the control's reader: the adapter's queue
// kept full from the tape, every frame the control took followed by its frame counter, the program's
// end, the control's turns (direction, rewind) and stops followed as a reader would.
#include <algorithm>

#include "adapter_session.hpp"
#include "tape/adapter.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

using namespace std::chrono_literals;
namespace db = tapefw::drive_bit;

/// Frames held ahead of the control: more than the adapter's queue holds.
constexpr std::size_t window_frames = 2048;

class AdapterReader {
public:
    AdapterReader(adapter::Session& s, std::span<const Frame> tape, const EmulatorOptions& o,
                  const std::function<void(const LineProgress&)>& progress)
        : s_(s), tape_(tape), o_(o), progress_(progress), code_(FrameCode::make(o.code, o.parity, o.eia_table)) {}

    EmulatorResult run() {
        if (o_.skip_leader)
            while (head_ < tape_.size() && tape_[head_] == blank_frame) ++head_;
        cursor_ = head_;
        s_.start_emulation();
        log("loaded, waiting for the control's start");
        auto began = std::chrono::steady_clock::now();
        while (!(o_.stop && o_.stop->load())) {
            fill();
            s_.offer(base_, {frames_.data() + at_, frames_.size() - at_});
            s_.pump_emulation(10ms);
            follow(s_.taken());
            report(began);
        }
        s_.stop_emulation();
        return r_;
    }

private:
    adapter::Session& s_;
    std::span<const Frame> tape_;
    const EmulatorOptions& o_;
    const std::function<void(const LineProgress&)>& progress_;
    FrameCode code_;
    // Frames numbered base_.. held for the adapter (from at_ in frames_), with their places on the tape.
    std::vector<std::uint8_t> frames_;
    std::vector<std::size_t> places_;
    std::size_t at_ = 0;
    std::uint32_t base_ = 0;
    std::size_t head_ = 0;    ///< where the tape stands after the frames taken (between frames)
    std::size_t cursor_ = 0;  ///< where the next frame held comes from
    bool backwards_ = false;
    bool was_backwards_ = false;   ///< the way last said
    bool at_program_end_ = false;  ///< frames held up to the program's end: none after it
    bool ended_said_ = false;
    ProgramEndWatch taken_watch_, held_watch_;
    tapefw::Taken seen_{};
    EmulatorResult r_;
    std::chrono::steady_clock::time_point last_report_{};

    void log(const std::string& what) {
        if (o_.log) o_.log(head_ + 1, what);
    }

    bool held_ends_program(Frame f) {
        return code_.kind(f) == FrameKind::character &&
               held_watch_.feed(code_.character(f)) == ProgramEndWatch::Event::program_end;
    }

    // Frames from the cursor, as many as the window holds; forwards only up to the program's end.
    void fill() {
        if (at_program_end_) return;
        if (at_ > window_frames) {
            frames_.erase(frames_.begin(), frames_.begin() + static_cast<std::ptrdiff_t>(at_));
            places_.erase(places_.begin(), places_.begin() + static_cast<std::ptrdiff_t>(at_));
            at_ = 0;
        }
        while (frames_.size() - at_ < window_frames && (backwards_ ? cursor_ > 0 : cursor_ < tape_.size())) {
            std::size_t place = backwards_ ? --cursor_ : cursor_++;
            frames_.push_back(tape_[place]);
            places_.push_back(place);
            if (!backwards_ && held_ends_program(tape_[place])) {
                at_program_end_ = true;
                return;
            }
        }
    }

    void follow(const tapefw::Taken& t) {
        while (base_ < t.taken && at_ < frames_.size()) take(places_[at_++]);
        r_.stops += static_cast<std::uint16_t>(t.stops - seen_.stops);
        r_.starts = r_.stops + ((t.drive & db::run) ? 1 : 0);
        if ((t.drive ^ seen_.drive) & db::run) log((t.drive & db::run) ? "start" : "stop");
        bool turned = t.turn != seen_.turn;
        bool rewound = t.rewinds != seen_.rewinds;
        seen_ = t;
        if (turned) turn(t.drive, rewound);
        if (!backwards_ && head_ >= tape_.size() && base_ == t.next && !ended_said_) {
            ended_said_ = true;
            log("end of tape");
        }
    }

    void take(std::size_t place) {
        ++base_;
        ++r_.frames_sent;
        head_ = backwards_ ? place : place + 1;
        if (backwards_ || code_.kind(tape_[place]) != FrameKind::character) return;
        if (taken_watch_.feed(code_.character(tape_[place])) != ProgramEndWatch::Event::program_end) return;
        log("end of program");
        rewind_to_stop();
    }

    // The frames held are not where the tape now stands: dropped (the adapter has dropped them too, at a
    // turn; at the program's end it is asked to, and to give the next frames only at the control's next
    // start, as a reader stopped at the end of a program waits for the start button).
    void restart_from(std::size_t place, bool backwards, bool ask) {
        if (ask) s_.discard(base_, true);
        frames_.erase(frames_.begin() + static_cast<std::ptrdiff_t>(at_), frames_.end());
        places_.erase(places_.begin() + static_cast<std::ptrdiff_t>(at_), places_.end());
        head_ = cursor_ = place;
        backwards_ = backwards;
        at_program_end_ = false;
        ended_said_ = false;
        held_watch_ = taken_watch_ = ProgramEndWatch{};
    }

    void rewind_to_stop() {
        restart_from(seek_rewind_stop(tape_, head_, code_), false, true);
        ++r_.rewinds;
        log("rewound to the '%' stop");
    }

    // The control's direction or rewind line changed: the adapter dropped the frames it held. A rewind
    // (counted by the adapter, so that one set and released between two reports is seen) puts the tape
    // at its '%' stop; the direction line says which way it reads from where it stands.
    void turn(std::uint8_t drive, bool rewound) {
        std::size_t place = head_;
        if (rewound) {
            place = seek_rewind_stop(tape_, head_, code_);
            ++r_.rewinds;
        }
        bool backwards = (drive & db::reverse) != 0;
        restart_from(place, backwards, false);
        if (rewound) log("rewound to the '%' stop (the control's rewind line)");
        if (backwards != was_backwards_) log(backwards ? "reading backwards" : "reading forwards");
        was_backwards_ = backwards;
    }

    void report(std::chrono::steady_clock::time_point began) {
        auto now = std::chrono::steady_clock::now();
        if (!progress_ || now - last_report_ < 250ms) return;
        last_report_ = now;
        LineProgress p;
        p.frames = r_.frames_sent;
        p.pauses = r_.stops;
        p.paused = !(seen_.drive & db::run);
        p.rate =
            static_cast<double>(r_.frames_sent) / std::max(1e-3, std::chrono::duration<double>(now - began).count());
        progress_(p);
    }
};

}  // namespace

bool is_adapter_device(std::string_view device) {
    return device.starts_with("adapter:") || device.starts_with("usb:") || device.starts_with("hid:");
}

EmulatorResult adapter_emulate(std::string_view device, std::span<const Frame> tape, const EmulatorOptions& options,
                               const std::function<void(const LineProgress&)>& progress) {
    adapter::Settings settings;
    auto pipe = adapter::open_pipe(device, DeviceUse::both, settings);
    adapter::Session session(std::move(pipe));
    adapter::apply_settings(session, settings, DeviceUse::both);
    if (const auto& gone = session.orphaned())
        if (options.log)
            options.log(0, "the adapter says its last run was stopped by its watchdog after frame " +
                               std::to_string(gone->frame) + ": the host was gone");
    return AdapterReader(session, tape, options, progress).run();
}

}  // namespace tape
