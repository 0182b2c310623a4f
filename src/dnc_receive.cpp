// Receiving frames from a line: everything kept as it arrives, the run ended by the program's end,
// a quiet line, a hang-up or the user.
#include "tape/dnc.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

using namespace std::chrono_literals;

bool is_flow_code(Frame f, const FrameCode& code) {
    if (code.kind(f) != FrameKind::character) return false;
    char c = code.character(f);
    return c >= 0x11 && c <= 0x14;
}

}  // namespace

ReceiveResult receive_frames(Transport& line, const ReceiveOptions& o, Clock& clock) {
    ReceiveResult r;
    FrameCode code = FrameCode::make(o.code, Parity::even, o.eia_table);
    ProgramEndWatch watch;
    auto last_frame = clock.now(), start = clock.now(), last_report = start;
    std::vector<Frame> kept;
    std::uint8_t buf[512];
    for (;;) {
        if (o.stop && o.stop->load()) {
            // Ask the other side to stop, and still take what it sends on in the next moments.
            std::uint8_t xoff = dc3;
            try {
                line.write({&xoff, 1});
            } catch (const Error&) {
            }
            auto grace_end = clock.now() + 300ms;
            while (clock.now() < grace_end) {
                ReadResult got = line.read(buf, 50ms);
                if (got.count) {
                    if (o.sink) o.sink(std::span<const Frame>(buf, got.count));
                    r.frames += got.count;
                }
                if (got.end) break;
            }
            r.end = ReceiveResult::End::stopped;
            return r;
        }
        ReadResult got = line.read(buf, 100ms);
        if (got.count) {
            last_frame = clock.now();
            kept.clear();
            bool done = false;
            for (std::size_t i = 0; i < got.count && !done; ++i) {
                Frame f = buf[i];
                if (o.drop_flow_codes && is_flow_code(f, code)) continue;
                kept.push_back(f);
                if (o.until_program_end && code.kind(f) == FrameKind::character &&
                    watch.feed(code.character(f)) == ProgramEndWatch::Event::next_percent)
                    done = true;
            }
            if (o.sink && !kept.empty()) o.sink(kept);
            r.frames += kept.size();
            if (o.progress && clock.now() - last_report > 250ms) {
                last_report = clock.now();
                double s = std::chrono::duration<double>(clock.now() - start).count();
                o.progress(LineProgress{r.frames, 0, 0, false, s > 0 ? static_cast<double>(r.frames) / s : 0});
            }
            if (done) {
                r.end = ReceiveResult::End::program_end;
                return r;
            }
        }
        if (got.end) {
            r.end = ReceiveResult::End::hangup;
            return r;
        }
        if (o.idle_timeout.count() > 0 && clock.now() - last_frame >= o.idle_timeout) {
            r.end = ReceiveResult::End::idle;
            return r;
        }
    }
}

}  // namespace tape
