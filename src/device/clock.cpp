#include "tape/clock.hpp"

#include <thread>

namespace tape {
namespace {

class SystemClock : public Clock {
public:
    time_point now() override { return std::chrono::steady_clock::now(); }
    void sleep_until(time_point t) override { std::this_thread::sleep_until(t); }
};

}  // namespace

Clock& system_clock() {
    static SystemClock clock;
    return clock;
}

}  // namespace tape
