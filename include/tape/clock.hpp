// Time for pacing and time-outs, injectable so the device logic can be tested without waiting.
#pragma once

#include <chrono>

namespace tape {

class Clock {
public:
    using time_point = std::chrono::steady_clock::time_point;
    virtual ~Clock() = default;
    virtual time_point now() = 0;
    /// Returns at t or later (at once when t has passed).
    virtual void sleep_until(time_point t) = 0;
};

/// The steady clock of the machine.
Clock& system_clock();

}  // namespace tape
