// Encodes a block with the installed library, decodes it back, and checks that the text survived.
// Exit 0 when it did; 1 with a message otherwise.
#include <cstdio>
#include <string>
#include <vector>

#include "tape/tape.hpp"

int main() {
    const std::string line = "N10 G01 X+12.5 Y-3 F120\n";
    try {
        std::vector<tape::Frame> frames = tape::encode(line, tape::EncodeOptions{.leader = 10, .trailer = 10});
        if (frames.size() != line.size() + 20) {
            std::fprintf(stderr, "consumer: %zu frames for %zu characters\n", frames.size(), line.size());
            return 1;
        }
        tape::DecodeResult r = tape::decode(frames, tape::DecodeOptions{});
        if (!r.ok() || r.text != line) {
            std::fprintf(stderr, "consumer: decoded '%s', expected '%s'\n", r.text.c_str(), line.c_str());
            return 1;
        }
    } catch (const tape::Error& e) {
        std::fprintf(stderr, "consumer: %s\n", e.what());
        return 1;
    }
    std::puts("consumer: encoded and decoded back");
    return 0;
}
