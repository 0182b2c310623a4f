// The corpus of restore_bench (restore_corpus.hpp).
#include "restore_corpus.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "tape/encode.hpp"
#include "tape/error.hpp"

namespace bench {
namespace {

std::string read_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Which frames of an ISO tape are its code: inside the data, outside ( ) comments and ';' comments
// (not for Fanuc, where ';' ends a block).
std::vector<bool> code_frames(const std::vector<tape::Frame>& t, bool semicolon_comments) {
    std::vector<bool> out(t.size(), false);
    auto data = tape::punched_part(t);
    std::size_t from = static_cast<std::size_t>(data.data() - t.data());
    bool paren = false, semi = false;
    for (std::size_t i = from; i < from + data.size(); ++i) {
        char c = static_cast<char>(t[i] & 0x7F);
        if (c == '\n') paren = semi = false;
        bool comment = paren || semi || c == '(' || (c == ';' && semicolon_comments);
        if (c == '(') paren = true;
        if (c == ')') paren = false;
        if (c == ';' && semicolon_comments) semi = true;
        out[i] = !comment;
    }
    return out;
}

CorpusTape encoded(const std::string& name, const std::string& text, bool semicolon_comments) {
    CorpusTape t;
    t.name = name;
    t.frames = tape::encode(text, tape::EncodeOptions{.leader = 40, .trailer = 40});
    t.code = code_frames(t.frames, semicolon_comments);
    return t;
}

}  // namespace

CorpusTape generated_tape(std::size_t chars, std::uint64_t seed, bool with_errors) {
    std::string t = "%\n";
    std::uint64_t x = seed * 0x9E3779B97F4A7C15ULL + 1;
    auto next = [&x](int m) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        return static_cast<int>(x % static_cast<std::uint64_t>(m));
    };
    char buf[128];
    for (long n = 1; t.size() < chars; ++n) {
        int len = std::snprintf(buf, sizeof buf, "N%ld G01 X%d.%03d Y%d.%02d F%d\n", n, next(1999) - 999, next(1000),
                                next(1999) - 999, next(100), 50 + next(900));
        if (with_errors && next(10) == 0)  // an arc with no centre, and a spindle speed after it
            len = std::snprintf(buf, sizeof buf, "N%ld G02 Y%d.%03d Z%+d S%d\n", n, next(1999) - 999, next(1000),
                                next(99999), next(999));
        t.append(buf, static_cast<std::size_t>(len));
    }
    t += "M02\n";
    return encoded("generated", t, false);
}

std::vector<CorpusTape> sample_tapes() {
    std::vector<CorpusTape> out;
    for (const char* name : {"16k20f3s5-turning.iso.ptp", "circle-examples.iso.ptp",
                             "gost-20999-format-example.iso.ptp", "koi7-comment.iso.ptp"}) {
        std::string bytes = read_file(std::string(TAPE_SAMPLE_TAPES) + "/" + name);
        if (bytes.empty()) std::fprintf(stderr, "restore_bench: cannot read %s\n", name);
        CorpusTape t;
        t.name = name;
        t.frames.assign(bytes.begin(), bytes.end());
        t.code = code_frames(t.frames, false);
        out.push_back(std::move(t));
    }
    return out;
}

std::vector<CorpusTape> real_tapes(std::string& note) {
    namespace fs = std::filesystem;
    std::vector<CorpusTape> out;
    const fs::path data = fs::path(TAPE_SAMPLE_TAPES) / ".." / ".." / "shared" / "data";
    if (!fs::is_directory(data)) {
        note = "no " + data.string() + ": the real programs and tapes are left out";
        return out;
    }
    std::vector<fs::path> files;
    for (const char* dir : {"outside/fanuc", "outside/lcnc", "outside2/fanuc", "outside2/haas", "outside2/lcnc",
                            "outside2/grbl", "outside2/okuma", "outside2/other", "outside2/sinumerik"})
        if (fs::is_directory(data / dir))
            for (const auto& e : fs::directory_iterator(data / dir)) files.push_back(e.path());
    files.push_back(data / "outside/receiveFile1.nc");
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
        try {
            bool lcnc = f.parent_path().filename() == "lcnc" || f.extension() == ".gcode";
            out.push_back(encoded(f.filename().string(), read_file(f), lcnc));
        } catch (const tape::Error& e) {
            note += f.filename().string() + " left out (" + e.what() + "); ";
        }
    }
    for (const char* dec : {"outside2/tapes/pdp11/DEC-11-O1PA-PA.ptap", "outside2/tapes/pdp11/DEC-11-YIPA-PA1.ptap"}) {
        std::string bytes = read_file(data / dec);
        if (bytes.empty()) continue;
        CorpusTape t;
        t.name = fs::path(dec).filename().string();
        t.frames.assign(bytes.begin(), bytes.end());
        t.code = code_frames(t.frames, true);
        t.nc = false;
        out.push_back(std::move(t));
    }
    return out;
}

}  // namespace bench
