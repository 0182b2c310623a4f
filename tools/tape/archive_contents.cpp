// The decoded contents of a restored tape for its bag (archive_contents.hpp).
#include "archive_contents.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <set>

#include "tape/binary_tape.hpp"
#include "tape/decode.hpp"
#include "tape/dialect.hpp"
#include "tape/program.hpp"
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

// Where each program of a text starts and the number it gives itself, as the loader finds them: nothing
// else of the programs is kept, so that a long tape costs one pass of the loader.
class ProgramStarts : public tape::ProgramVisitor {
public:
    struct Start {
        std::uint64_t offset = 0;
        std::optional<std::string> number;
    };
    std::vector<Start> starts;
    void program_start(const tape::Program& header) override { starts.push_back({header.start.offset, header.number}); }
};

// A program's number as a file name when it can be one as it is ("O1234", "0025"), else "".
std::string number_file_name(const std::optional<std::string>& number) {
    if (!number || number->empty() || number->size() > 40 || number->front() == '.') return "";
    for (char c : *number)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') return "";
    return *number;
}

// A file per program of a tape with several: its text from its start to the next one's (the label before
// the first is in text.txt only), named by its number, or by its place on the tape ("program-2") where it
// has none, or one that is no file name, or one an earlier program has.
std::vector<PayloadFile> program_files(const std::string& text, tape::Dialect dialect, const std::string& folder) {
    ProgramStarts found;
    tape::LoadOptions o;
    o.dialect = dialect;
    tape::load_each(text, {}, found, o);
    std::vector<PayloadFile> out;
    if (found.starts.size() < 2) return out;
    std::set<std::string> taken = {"text"};
    for (std::size_t i = 0; i < found.starts.size(); ++i) {
        std::string name = number_file_name(found.starts[i].number);
        if (name.empty() || !taken.insert(name).second) name = "program-" + std::to_string(i + 1);
        taken.insert(name);
        std::uint64_t from = found.starts[i].offset;
        std::uint64_t to = i + 1 < found.starts.size() ? found.starts[i + 1].offset : text.size();
        out.push_back({folder + "/" + name + ".txt", text.substr(from, to - from)});
    }
    return out;
}

// "contents/O1.txt, contents/program-2.txt": the first few, for a line of bag-info.txt.
std::string program_names(const std::vector<PayloadFile>& files) {
    constexpr std::size_t named = 5;
    std::string s;
    for (std::size_t i = 0; i < std::min(files.size(), named); ++i) s += (i ? ", " : "") + files[i].path;
    return files.size() > named ? s + " and " + std::to_string(files.size() - named) + " more" : s;
}

// "PDP-8 BIN loader tape", "PDP-11 absolute loader tape".
std::string loader_tape_name(tape::BinaryFormat f) {
    std::string name(tape::binary_format_name(f));
    return name + (name.ends_with("loader") ? " tape" : " loader tape");
}

}  // namespace

std::vector<PayloadFile> tape_contents(std::span<const tape::Frame> frames, const std::optional<tape::FrameCode>& code,
                                       const std::string& folder, std::string& what) {
    tape::BinaryDetector detector(true);
    detector.feed(frames);
    detector.finish();
    const tape::BinaryTape* binary = detector.tape();
    if (binary && binary->recognised() && detector.image()) {
        what = loader_tape_name(*binary->format) + ": " + folder +
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
    std::vector<PayloadFile> files = program_files(d.text, dialect.dialect, folder);
    what = folder + "/text.txt is the tape's text as decoded" +
           (bad ? " (" + std::to_string(bad) + " place(s) that cannot be read are marked \xEF\xBF\xBD)" : "") +
           (files.empty() ? ""
                          : "; its " + std::to_string(files.size()) +
                                " programs each in a file of its own, named by "
                                "its number or its place on the tape: " +
                                program_names(files)) +
           "; read as dialect " + std::string(tape::dialect_name(dialect.dialect)) + ": " + dialect.reason;
    files.insert(files.begin(), {folder + "/text.txt", d.text});
    return files;
}

}  // namespace cli
