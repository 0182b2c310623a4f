#include "cli_common.hpp"

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "tape/detect.hpp"
#include "tape/file_io.hpp"
#include "tape/image_input.hpp"
#include "tape/utf8_text.hpp"

namespace cli {

int status_for(tape::Errc code) {
    if (code == tape::Errc::io) return io_failure;
    if (code == tape::Errc::usage) return usage;
    return bad_data;
}

Globals& globals() {
    static Globals g;
    return g;
}

const tape::CodeTable* Globals::table() {
    if (eia_table.empty()) return nullptr;
    if (!loaded_table) {
        try {
            auto bytes = tape::read_file(eia_table);
            loaded_table =
                tape::CodeTable::parse(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
        } catch (const tape::Error& e) {
            fail(eia_table, e);
        }
    }
    return &*loaded_table;
}

std::string display_name(const std::string& path) { return path.empty() || path == "-" ? "stdin" : path; }

namespace {
extern "C" void discard_output_and_die(int sig) {
    tape::discard_pending_output();
    ::signal(sig, SIG_DFL);
    ::raise(sig);
}
}  // namespace

void install_output_cleanup() {
    struct sigaction sa {};
    sa.sa_handler = discard_output_and_die;
    sigemptyset(&sa.sa_mask);
    for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) ::sigaction(sig, &sa, nullptr);
}

void say(const std::string& file, const std::string& message) {
    // Bytes from the input reach messages: a terminal must not act on them or hide them.
    std::cerr << "tape: " << tape::visible(file.empty() ? "" : file + ": ") << tape::visible(message) << '\n';
}

std::string where_text(const tape::Position& where, bool raw_frames) {
    std::string s = where.describe();
    if (raw_frames && where.frame) {
        char buf[32];
        std::snprintf(buf, sizeof buf, " (byte 0x%llX)", static_cast<unsigned long long>(*where.frame - 1));
        s += buf;
    }
    return s;
}

void fail(const std::string& file, const tape::Error& e, bool raw_frames) {
    std::string where = where_text(e.where(), raw_frames);
    say(file, (where.empty() ? "" : where + ": ") + e.what());
    throw Exit{status_for(e.code())};
}

void fail(const std::string& file, tape::Errc code, const std::string& message) {
    fail(file, tape::Error(code, message));
}

void say_unlisted(const std::string& name, std::uint64_t count, const std::string& what) {
    say(name, std::to_string(count) + " more " + what + " not shown (--max-errors " +
                  std::to_string(globals().max_errors) + ")");
}

void say_unlisted_frames(const std::string& name, const std::map<tape::Errc, std::uint64_t>& unlisted) {
    for (const auto& [code, count] : unlisted)
        say_unlisted(name, count, code == tape::Errc::parity ? "parity error(s)" : "frame(s) that are no character");
}

void report_bad_frames(const std::string& name, const tape::DecodeResult& r, bool raw_frames) {
    for (const auto& d : r.diagnostics) say(name, where_text(d.where, raw_frames) + ": " + d.message);
    say_unlisted_frames(name, r.unlisted);
}

std::vector<std::uint8_t> read_input(const std::string& path) {
    try {
        return tape::read_file(path.empty() ? "-" : path);
    } catch (const tape::Error& e) {
        fail(display_name(path), e);
    }
}

TapeInput tape_from_bytes(const std::string& path, const std::vector<std::uint8_t>& bytes,
                          const std::string& format_id) {
    TapeInput in;
    in.name = path.empty() ? "-" : path;
    try {
        // The same format decision as every streamed input: --format, else the extension, else content.
        tape::ImageInput image(std::make_unique<tape::MemorySource>(bytes), in.name,
                               format_id.empty() ? nullptr : tape::find_image_format(format_id));
        in.format = &image.format();
        for (auto frames = image.next(); !frames.empty(); frames = image.next())
            in.frames.insert(in.frames.end(), frames.begin(), frames.end());
    } catch (const tape::Error& e) {
        fail(display_name(in.name), e);
    }
    return in;
}

TapeInput read_tape(const std::string& path, const std::string& format_id) {
    return tape_from_bytes(path, read_input(path), format_id);
}

bool is_image_input(const std::string& path, const std::vector<std::uint8_t>& bytes, const std::string& format_id,
                    const std::string& kind) {
    if (kind != "auto") return kind == "image";
    if (!format_id.empty()) return true;
    const tape::ImageFormat* by_ext = path.empty() || path == "-" ? nullptr : tape::image_format_for_path(path);
    auto prefix = std::span<const std::uint8_t>(bytes).first(std::min<std::size_t>(bytes.size(), 4096));
    if ((by_ext && !tape::extension_is_ambiguous(path)) || tape::find_image_format("holes")->match(prefix) >= 60)
        return true;
    if (tape::is_program_text(bytes)) return false;
    // A text program with a stray byte is reported where the byte is, not read as a strange tape.
    if (tape::looks_like_damaged_text(bytes)) require_program_text(path, bytes);
    return true;
}

void require_program_text(const std::string& path, std::span<const std::uint8_t> bytes) {
    auto fault = tape::find_text_fault(bytes);
    if (!fault) return;
    say(display_name(path), fault->where.describe() + ": " + fault->what +
                                ": a text program cannot hold it (if this is a tape image, give --input image)");
    throw Exit{bad_data};
}

void add_code_options(CLI::App* sub, CodeChoice& choice, bool with_auto) {
    std::vector<std::string> codes = {"iso", "eia"};
    if (with_auto)
        codes.insert(codes.begin(), "auto");
    else
        choice.code = "iso";
    sub->add_option("--code,-c", choice.code,
                    with_auto ? "Tape code: auto (detect ISO or EIA from the first block), iso or eia"
                              : "Tape code: iso (ISO 7-bit, even parity on track 8) or eia (EIA RS-244)")
        ->check(CLI::IsMember(codes))
        ->capture_default_str();
    sub->add_option("--parity,-p", choice.parity,
                    "Track 8 rule for ISO/ASCII tapes: even (NC tapes), odd, mark (DEC-era ASCII), space, none")
        ->check(CLI::IsMember({"even", "odd", "mark", "space", "none"}))
        ->capture_default_str();
    sub->add_option("--charset", choice.charset, "ascii, or koi7 for Russian text switched with SO/SI (КОИ-7 Н1)")
        ->check(CLI::IsMember({"ascii", "koi7"}))
        ->capture_default_str();
}

tape::DecodeOptions resolve_code(const CodeChoice& choice, const std::string& name,
                                 const std::function<tape::CodeDetection()>& detect) {
    tape::DecodeOptions o;
    o.parity = *tape::parse_parity(choice.parity);
    o.charset = *tape::parse_charset(choice.charset);
    o.eia_table = globals().table();
    o.max_diagnostics = globals().max_errors;
    if (choice.code != "auto") {
        o.code = *tape::parse_code(choice.code);
    } else if (o.parity != tape::Parity::even) {
        o.code = tape::Code::iso;  // only ISO/ASCII tapes have a choice of parity
    } else {
        auto d = detect();
        if (!d.code) fail(name, tape::Errc::unknown_code, d.reason);
        if (globals().verbosity > 0) say(name, "code " + d.reason);
        o.code = *d.code;
    }
    if (o.code == tape::Code::eia && o.parity != tape::Parity::even)
        fail(name, tape::Errc::usage, "--parity is for ISO tapes; EIA parity is always odd on track 5");
    return o;
}

tape::DecodeOptions resolve_code(const CodeChoice& choice, const TapeInput& input) {
    return resolve_code(choice, display_name(input.name), [&] { return tape::detect_code(input.frames); });
}

namespace {
std::vector<std::string> format_ids(bool for_writing) {
    std::vector<std::string> ids;
    for (const auto& f : tape::image_formats())
        if (for_writing ? f.write != nullptr : f.read != nullptr) ids.emplace_back(f.id);
    return ids;
}
}  // namespace

std::string format_choices(bool for_writing) {
    auto ids = format_ids(for_writing);
    std::string text;
    for (std::size_t i = 0; i < ids.size(); ++i) text += (i == 0 ? "" : i + 1 == ids.size() ? " or " : ", ") + ids[i];
    return text;
}

CLI::Validator format_check(bool for_writing) { return CLI::IsMember(format_ids(for_writing)); }

void refuse_binary_terminal(const std::string& path, bool binary, bool force) {
    if ((path.empty() || path == "-") && binary && ::isatty(STDOUT_FILENO) && !force)
        fail("", tape::Errc::usage,
             "refusing to write a binary tape image to a terminal (use -o FILE, --format holes, or --force)");
}

void write_output(const std::string& path, const std::string& data, bool binary, bool force) {
    if (path.empty() || path == "-") {
        refuse_binary_terminal(path, binary, force);
        std::cout.write(data.data(), static_cast<std::streamsize>(data.size()));
        std::cout.flush();
        if (!std::cout) fail("stdout", tape::Errc::io, "cannot write");
        return;
    }
    try {
        tape::write_file_atomic(path, data, force);
    } catch (const tape::Error& e) {
        fail(path, e);
    }
}

void add_program_source_options(CLI::App* sub, ProgramSource& source) {
    add_code_options(sub, source.choice, true);
    sub->add_option("--format,-f", source.format,
                    "Image format of IN: " + format_choices(false) + " (IN is then a tape image)")
        ->check(format_check(false));
    sub->add_option("--input", source.kind, "What IN is: auto (image or text by extension and content), text, image")
        ->check(CLI::IsMember({"auto", "text", "image"}))
        ->capture_default_str();
}

ProgramInput load_program(const std::string& path, const ProgramSource& source) {
    ProgramInput in;
    in.name = display_name(path);
    std::vector<std::uint8_t> bytes = read_input(path);
    if (!is_image_input(path, bytes, source.format, source.kind)) {
        require_program_text(path, bytes);
        in.tape = tape::load(std::string(bytes.begin(), bytes.end()));
        return in;
    }
    TapeInput t = tape_from_bytes(path, bytes, source.format);
    tape::DecodeOptions o = resolve_code(source.choice, t);
    o.positions = true;
    tape::DecodeResult r = tape::decode(t.frames, o);
    report_bad_frames(in.name, r, t.raw());
    if (!r.ok()) throw Exit{bad_data};
    in.from_tape = true;
    in.tape = tape::load(std::move(r.text), std::move(r.frame_of));
    return in;
}

std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (unsigned char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += static_cast<char>(c);
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
        } else {
            out += static_cast<char>(c);
        }
    }
    return out + "\"";
}

std::string position_text(const tape::Location& where, bool from_tape) {
    if (from_tape && where.frame) return "frame " + std::to_string(*where.frame);
    return "line " + std::to_string(where.line);
}

}  // namespace cli
