#include "sim_hardware.hpp"

#include <algorithm>
#include <cmath>

namespace tapesim {

SimHardware::SimHardware(std::vector<std::uint8_t> tape, SimOptions options)
    : tape_(std::move(tape)),
      o_(options),
      period_us_(static_cast<std::uint64_t>(std::llround(1e6 / options.read_rate))),
      punch_period_us_(static_cast<std::uint64_t>(std::llround(1e6 / options.punch_rate))) {
    if (o_.head_at_end) position_ = tape_.size();
    for (const auto& [at, f] : o_.row_flags) row_flags_[at] |= f;
    if (o_.control) control_.emplace(*o_.control);
}

void SimHardware::frame_clock(std::uint32_t first_in_us) {
    clock_on_ = true;
    next_slot_at_ = now_ + first_in_us;
}

void SimHardware::run_control(std::uint64_t t, tapefw::Engine& engine) {
    for (;;) {
        std::uint64_t change = control_->next_change();
        std::uint64_t slot = clock_on_ ? next_slot_at_ : UINT64_MAX;
        if (std::min(change, slot) > t) return;
        if (change <= slot) {
            // The line first when both are due: a stop seen at a slot's moment holds that slot.
            now_ = std::max(now_, change);
            engine.on_drive(control_->change(change));
            continue;
        }
        now_ = std::max(now_, slot);
        std::uint8_t levels = 0;
        switch (engine.next_frame(levels)) {
            case tapefw::Slot::frame:
                // The control reads the lines as this wiring makes them.
                control_->strobe(slot + wiring_.setup_us, static_cast<std::uint8_t>(levels ^ wiring_.data_invert),
                                 wiring_.period_us());
                break;
            case tapefw::Slot::hold:
                break;
            case tapefw::Slot::stop:
                clock_on_ = false;
                continue;
        }
        next_slot_at_ = slot + wiring_.period_us();
    }
}

void SimHardware::drive(tapefw::Drive d) {
    if (d == drive_) return;
    drive_ = d;
    if (d != tapefw::Drive::stop) {
        ++starts_;
        braking_left_ = 0;
        // A reversal goes through a stand-still: the clutch engages afresh.
        if (!moving_ || backwards_ != (d == tapefw::Drive::reverse)) next_row_at_ = now_ + o_.start_us;
        backwards_ = d == tapefw::Drive::reverse;
        moving_ = true;
    } else if (moving_) {
        braking_left_ = o_.stop_frames;
        if (braking_left_ == 0) moving_ = false;
    }
}

void SimHardware::advance_to(std::uint64_t t, tapefw::Engine& engine) {
    if (control_) run_control(t, engine);
    read_rows(t, engine);
}

void SimHardware::read_rows(std::uint64_t t, tapefw::Engine& engine) {
    while (moving_ && next_row_at_ <= t) {
        now_ = next_row_at_;
        const auto& tape = reader_tape();
        // The frame passing the head: the one at position_ forwards, the one before it backwards.
        bool on_tape = backwards_ ? position_ > 0 : position_ < tape.size();
        std::uint64_t frame = backwards_ ? position_ - 1 : position_;
        bool sprocket = on_tape && !(o_.torn_at && frame >= *o_.torn_at);
        if (sprocket) {
            auto flagged = row_flags_.find(frame);
            std::uint8_t flags = flagged == row_flags_.end() ? 0 : flagged->second;
            // The board gives the levels on the lines, as this unit's wiring makes them.
            engine.on_row(static_cast<std::uint8_t>(tape[frame] ^ o_.active_low), flags);
        }
        if (on_tape) {
            if (backwards_)
                --position_;
            else
                ++position_;
        }
        next_row_at_ += period_us_;
        if (drive_ == tapefw::Drive::stop && (braking_left_ == 0 || --braking_left_ == 0)) moving_ = false;
    }
    if (t > now_) now_ = t;
}

std::uint64_t SimHardware::next_event() const {
    std::uint64_t next = now_ + 1000;
    if (moving_ && next_row_at_ < next) next = next_row_at_;
    if (clock_on_ && next_slot_at_ < next) next = std::max(next_slot_at_, now_);
    if (control_ && control_->next_change() < next) next = std::max(control_->next_change(), now_);
    if (punched_once_ && last_punch_ + punch_period_us_ < next && last_punch_ + punch_period_us_ > now_)
        next = last_punch_ + punch_period_us_;
    return next;
}

void SimHardware::after_poll() {
    if (punched_once_ && punch_ready()) punch_idle_ = true;
}

bool SimHardware::punch_ready() { return !punched_once_ || now_ >= last_punch_ + punch_period_us_; }

void SimHardware::punch(std::uint8_t row) {
    if (std::find(o_.miss_hole_at.begin(), o_.miss_hole_at.end(), punched_.size() + 1) != o_.miss_hole_at.end())
        row = static_cast<std::uint8_t>(row & (row - 1));
    if (punch_idle_) ++underruns_;
    punch_idle_ = false;
    if (punched_once_) {
        std::uint64_t gap = now_ - last_punch_;
        if (2 * gap > 3 * punch_period_us_) ++late_punches_;
        longest_punch_gap_us_ = std::max(longest_punch_gap_us_, gap);
    }
    punched_.push_back(row);
    last_punch_ = now_;
    punched_once_ = true;
}

std::uint16_t SimHardware::status_lines() {
    std::uint16_t bits = forced_status;
    if (backwards_ ? position_ == 0 : position_ >= reader_tape().size()) bits |= tapefw::status::tape_out;
    return bits;
}

}  // namespace tapesim
