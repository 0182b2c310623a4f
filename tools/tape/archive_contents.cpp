// The decoded contents of a restored tape for its bag (archive_contents.hpp).
#include "archive_contents.hpp"

#include <cstdio>

#include "tape/binary_tape.hpp"
#include "tape/decode.hpp"
#include "tape/dialect.hpp"
#include "tape_report.hpp"

namespace cli {
namespace {

// "00200: 7300 1234 ----": eight locations a line, a line only where something was loaded.
std::string memory_dump(const tape::MemoryImage& m) {
    std::string s;
    const int digits = m.words() ? 4 : 3;
    for (std::uint32_t row = 0; row < m.size(); row += 8) {
        bool any = false;
        for (std::uint32_t a = row; a < row + 8; ++a) any = any || m.loaded(a);
        if (!any) continue;
        char buf[16];
        std::snprintf(buf, sizeof buf, "%06o:", row);
        s += buf;
        for (std::uint32_t a = row; a < row + 8; ++a) {
            std::snprintf(buf, sizeof buf, " %0*o", digits, static_cast<unsigned>(m.at(a)));
            s += m.loaded(a) ? std::string(buf) : " " + std::string(digits, '-');
        }
        s += "\n";
    }
    return s;
}

std::string checksums_text(const tape::BinaryTape& t) { return t.summary() + "\n" + binary_block_lines(t, true, ""); }

}  // namespace

std::vector<PayloadFile> tape_contents(std::span<const tape::Frame> frames, const std::optional<tape::FrameCode>& code,
                                       const std::string& folder, std::string& what) {
    tape::BinaryDetector detector(true);
    detector.feed(frames);
    detector.finish();
    const tape::BinaryTape* binary = detector.tape();
    if (binary && binary->recognised() && detector.image()) {
        what = std::string(tape::binary_format_name(*binary->format)) + " loader tape: " + folder +
               "/memory.txt is what the loader puts in memory (octal, '-' where nothing is loaded), " + folder +
               "/checksums.txt its blocks and checksums";
        return {{folder + "/memory.txt", memory_dump(*detector.image())},
                {folder + "/checksums.txt", checksums_text(*binary)}};
    }
    if (!code) {
        what = "";
        return {};
    }
    tape::DecodeOptions o;
    o.code = code->code();
    if (o.code == tape::Code::iso) o.parity = code->parity();
    o.keep_going = true;
    o.max_diagnostics = 1;
    tape::DecodeResult d = tape::decode(frames, o);
    std::uint64_t bad = 0;
    for (const auto& diag : d.diagnostics) bad += tape::is_bad_frame(diag.code);
    for (const auto& [kind, n] : d.unlisted) bad += tape::is_bad_frame(kind) ? n : 0;
    tape::DialectChoice dialect = tape::guess_dialect(d.text);
    what = folder + "/text.txt is the tape's text as decoded" +
           (bad ? " (" + std::to_string(bad) + " place(s) that cannot be read are marked \xEF\xBF\xBD)" : "") +
           "; read as dialect " + std::string(tape::dialect_name(dialect.dialect)) + ": " + dialect.reason;
    return {{folder + "/text.txt", d.text}};
}

}  // namespace cli
