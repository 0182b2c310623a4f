#include "cli/signals.hpp"

#include <signal.h>

#include "tape/file_io.hpp"

namespace cli {
namespace {

extern "C" void discard_output_and_die(int sig) {
    tape::discard_pending_output();
    ::signal(sig, SIG_DFL);
    ::raise(sig);
}

extern "C" void on_interrupt(int) { interrupted().store(true); }

}  // namespace

void install_output_cleanup() {
    struct sigaction sa {};
    sa.sa_handler = discard_output_and_die;
    sigemptyset(&sa.sa_mask);
    for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) ::sigaction(sig, &sa, nullptr);
}

std::atomic<bool>& interrupted() {
    static std::atomic<bool> flag{false};
    return flag;
}

void install_interrupt_handler() {
    struct sigaction sa {};
    sa.sa_handler = on_interrupt;
    sigemptyset(&sa.sa_mask);
    // A hang-up (the terminal closed, an ssh session dropped) stops a device run as Ctrl-C does:
    // every frame already read kept, the line left in a known state.
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(sig, &sa, nullptr);
    ::signal(SIGPIPE, SIG_IGN);
}

}  // namespace cli
