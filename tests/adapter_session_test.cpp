// The host's side of the adapter protocol against adapters that misbehave in ways the simulator does
// not: a pipe (the lowest level, below the session) answers as a script says.
#include "device/adapter_session.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <deque>
#include <functional>
#include <optional>
#include <thread>

#include "core/protocol.hpp"
#include "tape/dnc.hpp"
#include "tape/error.hpp"

using namespace std::chrono_literals;
using tapefw::Msg;
using tapefw::Packet;

namespace {

// An adapter that answers RESET and GET_INFO as a good one does, and everything else as the test says:
// answer(request) gives the packets that follow a request, in order; damaged() packets fail their CRC.
class ScriptedPipe : public tape::adapter::PacketPipe {
public:
    std::function<std::vector<Packet>(const Packet&)> answer = [](const Packet&) { return std::vector<Packet>{}; };
    bool damage_everything = false;  ///< after the info: every packet fails its CRC

    void send(const Packet& p) override {
        auto type = static_cast<Msg>(p.type);
        if (type == Msg::reset) return queue(ok(p));
        if (type == Msg::get_info) {
            tapefw::Info info;
            info.capabilities = tapefw::caps::reader | tapefw::caps::punch;
            info.tracks = 0x0F;
            info.read_buffer = 1024;
            info.punch_buffer = 256;
            Packet reply;
            info.encode(reply);
            reply.seq = p.seq;
            hello_done_ = true;
            return queue(reply);
        }
        for (auto& reply : answer(p)) queue(reply);
    }
    std::optional<Packet> receive(std::chrono::milliseconds timeout) override {
        if (damage_everything && hello_done_) {
            std::this_thread::sleep_for(std::min(timeout, 5ms));
            ++bad_;  // a packet came, and failed its CRC
            return std::nullopt;
        }
        if (out_.empty()) {
            std::this_thread::sleep_for(std::min(timeout, 5ms));
            return std::nullopt;
        }
        Packet p = out_.front();
        out_.pop_front();
        return p;
    }
    std::uint64_t bad_packets() const override { return bad_; }
    std::string name() const override { return "adapter:scripted"; }

    static Packet ok(const Packet& request) {
        Packet reply;
        tapefw::Ok{request.type}.encode(reply);
        reply.seq = request.seq;
        return reply;
    }

private:
    void queue(const Packet& p) { out_.push_back(p); }
    std::deque<Packet> out_;
    std::uint64_t bad_ = 0;
    bool hello_done_ = false;
};

Packet rows(std::uint32_t first, std::uint8_t count) {
    tapefw::Rows r;
    r.first = first;
    r.count = count;
    for (std::uint8_t i = 0; i < count; ++i) r.rows[i] = static_cast<std::uint8_t>(0x40 + i);
    Packet p;
    r.encode(p);
    return p;
}

Packet status(std::uint16_t bits, std::uint32_t frame) {
    Packet p;
    tapefw::Status{bits, frame}.encode(p);
    return p;
}

Packet credit(std::uint32_t next, std::uint32_t punched, std::uint16_t free) {
    Packet p;
    tapefw::Credit{next, punched, free}.encode(p);
    return p;
}

// Reads until the end; the error's message, or "" when it ended well.
std::string read_to_end(tape::adapter::Session& s) {
    std::uint8_t buffer[256];
    try {
        auto deadline = std::chrono::steady_clock::now() + 10s;
        while (std::chrono::steady_clock::now() < deadline)
            if (s.read(buffer, 50ms).end) return "";
        return "still reading after 10 s";
    } catch (const tape::Error& e) {
        return e.what();
    }
}

// An adapter that answers READ_START with its OK and then the packets given, and nothing else.
std::unique_ptr<ScriptedPipe> reading(std::vector<Packet> after) {
    auto pipe = std::make_unique<ScriptedPipe>();
    pipe->answer = [after](const Packet& p) {
        if (static_cast<Msg>(p.type) != Msg::read_start) return std::vector<Packet>{};
        std::vector<Packet> out{ScriptedPipe::ok(p)};
        out.insert(out.end(), after.begin(), after.end());
        return out;
    };
    return pipe;
}

// The message of the Error f throws, or "" when it throws none.
std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const tape::Error& e) {
        return e.what();
    }
    return "";
}

tape::adapter::SessionTiming quick() {
    tape::adapter::SessionTiming t;
    t.silent = 300ms;
    return t;
}

}  // namespace

TEST(AdapterSession, AnAdapterWhoseEveryPacketFailsItsCrcIsSaidToBeDamagedNotSilent) {
    auto pipe = std::make_unique<ScriptedPipe>();
    auto* script = pipe.get();
    script->answer = [](const Packet& p) { return std::vector<Packet>{ScriptedPipe::ok(p)}; };
    tape::adapter::Session s(std::move(pipe), quick());
    std::uint8_t buffer[16];
    s.read(buffer, 10ms);  // READ_START answered
    script->damage_everything = true;
    std::string error = read_to_end(s);
    EXPECT_NE(error.find("the link is damaging every packet"), std::string::npos) << error;
    EXPECT_EQ(error.find("stopped answering"), std::string::npos) << error;
}

TEST(AdapterSession, ARequestAnsweredOnlyWithDamagedPacketsSaysTheLinkDamagesThem) {
    auto pipe = std::make_unique<ScriptedPipe>();
    auto* script = pipe.get();
    tape::adapter::Session s(std::move(pipe), quick());
    script->damage_everything = true;
    std::string error = error_of([&] { s.configure(tapefw::Config{}); });
    EXPECT_NE(error.find("no answer to CONFIG after 3 tries: the link is damaging every packet"), std::string::npos)
        << error;
}

TEST(AdapterSession, TapeOutNamingAFrameBeforeTheRowsAlreadySentIsAProtocolError) {
    tape::adapter::Session s(reading({rows(0, 20), status(tapefw::status::tape_out, 5)}), quick());
    std::string error = read_to_end(s);
    EXPECT_NE(
        error.find("protocol error: the adapter's STATUS (tape out) names frame 6, before the 20 frames it has sent"),
        std::string::npos)
        << error;
}

TEST(AdapterSession, CreditForMoreRowsThanTheQueueHoldsIsAProtocolError) {
    auto pipe = std::make_unique<ScriptedPipe>();
    pipe->answer = [](const Packet& p) {
        if (static_cast<Msg>(p.type) != Msg::punch) return std::vector<Packet>{};
        tapefw::Punch punch;
        punch.decode(p);
        return std::vector<Packet>{credit(punch.first + punch.count, 0, 9999)};
    };
    tape::adapter::Session s(std::move(pipe), quick());
    std::string error = error_of([&] {
        std::vector<std::uint8_t> row(10, 0x41);
        s.punch(row);
        s.drain();
    });
    EXPECT_NE(error.find("protocol error: the adapter gives credit for 9999 rows, more than its queue of 256"),
              std::string::npos)
        << error;
}

namespace {

Packet out_of_order(std::uint32_t expected) {
    Packet p;
    tapefw::ErrorReply{tapefw::ErrorCode::out_of_order, static_cast<std::uint8_t>(Msg::punch), expected}.encode(p);
    return p;
}

// An adapter that takes every PUNCH at once and punches it, then sends what after(punch) says.
std::unique_ptr<ScriptedPipe> punching(std::function<std::vector<Packet>(const tapefw::Punch&)> after) {
    auto pipe = std::make_unique<ScriptedPipe>();
    pipe->answer = [after](const Packet& p) {
        if (static_cast<Msg>(p.type) != Msg::punch) return std::vector<Packet>{};
        tapefw::Punch punch;
        punch.decode(p);
        return after(punch);
    };
    return pipe;
}

std::string punch_rows(tape::adapter::Session& s, std::size_t count) {
    return error_of([&] {
        std::vector<std::uint8_t> rows(count, 0x41);
        s.punch(rows);
        s.drain();
    });
}

}  // namespace

TEST(AdapterSession, AnOutOfOrderErrorForRowsTheAdapterHasSinceTakenIsStaleAndIgnored) {
    // The error about row 1 comes after the CREDIT that took rows 1-10: nothing is to be sent again.
    int punches = 0;
    tape::adapter::Session s(punching([&](const tapefw::Punch& punch) {
                                 ++punches;
                                 std::uint32_t end = punch.first + punch.count;
                                 return std::vector<Packet>{credit(end, end, 256), out_of_order(0)};
                             }),
                             quick());
    EXPECT_EQ(punch_rows(s, 10), "");
    EXPECT_EQ(s.rows_punched(), 10u);
    EXPECT_EQ(punches, 1) << "rows the adapter had taken were sent again";
}

TEST(AdapterSession, AnOutOfOrderErrorExpectingARowNeverSentIsAProtocolError) {
    tape::adapter::Session s(punching([](const tapefw::Punch& punch) {
                                 return std::vector<Packet>{out_of_order(punch.first + punch.count + 5)};
                             }),
                             quick());
    std::string error = punch_rows(s, 10);
    EXPECT_NE(error.find("protocol error: the adapter expects punch row 16, and only 10 were sent"), std::string::npos)
        << error;
}

TEST(AdapterSession, FramesNeverResentAreGivenUpAfterTheRequestsAndTheirTimeNotBefore) {
    tape::adapter::SessionTiming t = quick();
    t.silent = 10s;
    tape::adapter::Session s(reading({rows(10, 20)}), t);  // 0-9 never come, however often asked for
    auto start = std::chrono::steady_clock::now();
    std::string error = read_to_end(s);
    auto took = std::chrono::steady_clock::now() - start;
    EXPECT_NE(error.find("frames 1-10 lost: not received after 5 requests to resend in 0."), std::string::npos)
        << error;
    EXPECT_GE(took, t.lost_after);
    EXPECT_LT(took, t.lost_after + 1s);
}

namespace {

// A line whose write blocks until Ctrl-C comes, and then fails as an adapter's watchdog would make it.
class StoppedThenFaulty : public tape::Transport {
public:
    explicit StoppedThenFaulty(std::atomic<bool>& stop) : stop_(stop) {}
    tape::ReadResult read(std::span<std::uint8_t>, std::chrono::milliseconds) override { return {}; }
    void write(std::span<const std::uint8_t>) override {
        if (++writes_ < 10) return;
        stop_ = true;  // Ctrl-C while the write waits for the punch
        throw tape::Error(tape::Errc::io,
                          name() + ": frame 10: the adapter's watchdog stopped the reader and the punch");
    }
    void drain() override { throw tape::Error(tape::Errc::io, name() + ": drained after the stop"); }
    std::string name() const override { return "adapter:test"; }

private:
    std::atomic<bool>& stop_;
    int writes_ = 0;
};

}  // namespace

TEST(SendFrames, CtrlCWinsOverTheFaultTheDeviceReportsAfterIt) {
    std::atomic<bool> stop{false};
    StoppedThenFaulty line(stop);
    std::vector<tape::Frame> frames(100, 0x41);
    tape::SendResult r = tape::send_frames(line, frames, tape::SendOptions{.stop = &stop});
    EXPECT_TRUE(r.stopped);
    EXPECT_EQ(r.sent, 9u);
}
