// A machine's answers to requests: programs from the library, a restart after a tool break, and
// nothing (or a short comment program) for what cannot be sent. "Done" only once the line drained.
#include <cstdio>

#include "machine.hpp"
#include "tape/error.hpp"
#include "tape/feed.hpp"
#include "tape/file_io.hpp"
#include "tape/restart.hpp"

namespace tape::dnc {
namespace {

FeedOptions feed_options(const MachineSettings& s) {
    FeedOptions o;
    o.encode.code = s.code;
    o.encode.parity = s.parity;
    o.encode.leader = s.leader;
    o.encode.trailer = s.trailer;
    o.encode.crlf = s.crlf;
    o.percent = s.percent;
    o.dialect = s.dialect;
    return o;
}

InputOptions text_input() {
    InputOptions o;
    o.kind = InputKind::text;
    return o;
}

// A comment for the control's screen: capitals, digits and a few signs, nothing that ends it early.
std::string comment_text(const std::string& text) {
    std::string out;
    for (char c : text.substr(0, 60)) {
        char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        out += (std::isalnum(static_cast<unsigned char>(u)) || u == ' ' || u == '.' || u == '-' || u == ',') ? u : ' ';
    }
    return out;
}

}  // namespace

void Machine::answer(Transport& line, const Request& request) {
    log(Priority::notice, "request " + request.comment);
    for (const auto& why : request.refused) say_unknown(line, "request refused: " + why, "REFUSED " + why);
    if (request.kind == Request::Kind::restart) {
        answer_restart(line, request);
        return;
    }
    auto library = shared_->library();
    for (const auto& name : request.names) {
        if (stop_) return;
        Found found = find_program(library->programs, name);
        if (found.path.empty()) {
            say_unknown(line, "no program '" + name + "' sent: " + found.problem, name + " NOT SENT " + found.problem);
            continue;
        }
        std::string text;
        try {
            text = read_program(found.path);
        } catch (const Error& e) {
            say_unknown(line, "no program '" + name + "' sent: " + e.what(), name + " NOT SENT CANNOT BE READ");
            continue;
        }
        send_text(line, text, name, found.path);
    }
}

void Machine::answer_restart(Transport& line, const Request& request) {
    if (request.names.empty()) return;  // refused, and said so
    const std::string& name = request.names[0];
    Found found = find_program(shared_->library()->programs, name);
    if (found.path.empty()) {
        say_unknown(line, "no restart of '" + name + "' sent: " + found.problem, name + " NOT SENT " + found.problem);
        return;
    }
    RestartPlan plan;
    try {
        plan = plan_restart(read_program(found.path), request.block, s_.dialect, s_.lathe);
    } catch (const Error& e) {
        say_unknown(line, "no restart of " + name + " at " + request.block + " sent: " + e.what(),
                    "NO RESTART OF " + name + " AT " + request.block);
        return;
    }
    send_text(line, plan.text(), name + " from " + plan.block,
              found.path + ", " + std::to_string(plan.modal.size()) + " block(s) of modal state rebuilt, " +
                  std::to_string(plan.approach.size()) + " block(s) of approach");
}

void Machine::say_unknown(Transport& line, const std::string& message, const std::string& comment) {
    log(Priority::warning, message);
    if (s_.answer_unknown) send_text(line, "%\n(" + comment_text(comment) + ")\n%\n", "a comment", "answer_unknown");
}

void Machine::send_text(Transport& line, const std::string& text, const std::string& program,
                        const std::string& source) {
    Input input(
        std::make_unique<MemorySource>(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size())),
        program, text_input());
    send(line, input, program, source);
}

void Machine::send(Transport& line, Input& input, const std::string& program, const std::string& source) {
    std::vector<Frame> frames;
    try {
        frames = frames_to_send(input, feed_options(s_));
    } catch (const Error& e) {
        log(Priority::err, "cannot send " + program + " (" + source + "): " + e.what());
        return;
    }
    FrameCode code = FrameCode::make(s_.code, s_.parity);
    SendOptions o{.rate = s_.rate,
                  .flow = s_.flow,
                  .wait_xon = s_.wait_xon,
                  .xon_timeout = s_.xon_timeout,
                  .xon = s_.xon,
                  .xoff = s_.xoff,
                  .stop = &stop_};
    o.burst = s_.burst;
    o.block_delay = s_.block_delay;
    o.block_end = code.frame_for('\n').value_or(0x0A);
    o.progress = [this](const LineProgress& p) { set_frames(p.frames); };
    o.other_input = [this](std::span<const std::uint8_t> b) { keep_pending(b); };  // the control's next request
    set_state(LineState::sending, program, frames.size());
    auto start = shared_->clock->now();
    std::string what = "sent " + program + " (" + source + "): ";
    SendResult r;
    try {
        r = send_frames(line, frames, o, *shared_->clock);
    } catch (const Error& e) {
        std::string message = what + "failed: " + e.what();
        count(&MachineStatus::failed, message);
        if (e.code() == Errc::io) throw Error(Errc::io, message);  // the line is gone: said, and opened again
        log(Priority::err, message);
        return;
    }
    char figures[96];
    std::snprintf(figures, sizeof figures,
                  "%llu frames, %.2f s, %llu pause(s): ", static_cast<unsigned long long>(r.sent), since(start),
                  static_cast<unsigned long long>(r.pauses));
    std::string message = what + figures + (r.stopped ? "stopped before the end" : "done");
    log(r.stopped ? Priority::warning : Priority::info, message);
    count(r.stopped ? &MachineStatus::failed : &MachineStatus::sent, message);
    set_state(LineState::listening);
}

}  // namespace tape::dnc
