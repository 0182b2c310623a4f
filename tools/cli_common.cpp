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
    if (code == tape::Errc::usage || code == tape::Errc::exists) return usage;
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

std::atomic<bool>& interrupted() {
    static std::atomic<bool> flag{false};
    return flag;
}

namespace {
extern "C" void on_interrupt(int) { interrupted().store(true); }
}  // namespace

void install_interrupt_handler() {
    struct sigaction sa {};
    sa.sa_handler = on_interrupt;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
    signal(SIGPIPE, SIG_IGN);
}

int parse_and_run(CLI::App& app, int argc, char** argv, const std::string& help) {
    const std::string& program = globals().program;
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {  // --help, --help-all, --version
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << program << ": " << e.what() << "\n"
                  << program << ": run " << (help.empty() ? "'" + program + " --help'" : help) << " for the options\n";
        return usage;
    } catch (const Exit& e) {
        return e.status;
    }
    return ok;
}

void say(const std::string& file, const std::string& message) {
    // Bytes from the input reach messages: a terminal must not act on them or hide them.
    std::cerr << globals().program << ": " << tape::visible(file.empty() ? "" : file + ": ") << tape::visible(message)
              << '\n';
}

std::string where_text(const tape::Position& where, bool raw_frames) {
    if (!where.frame) return where.describe();
    // A frame first (what a tape has), then what helps to find it: the byte of a raw file, the line of the text.
    std::string more;
    if (raw_frames) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "byte 0x%llX", static_cast<unsigned long long>(*where.frame - 1));
        more = buf;
    }
    if (where.line) more += (more.empty() ? "line " : ", line ") + std::to_string(*where.line);
    return "frame " + std::to_string(*where.frame) + (more.empty() ? "" : " (" + more + ")");
}

void say_note(const std::string& name, const tape::Diagnostic& d) {
    std::string where = d.where.describe();
    say(name, (where.empty() ? "" : where + ": ") + "note: " + with_hint(d.message, d.hint));
}

std::string hint_text(const tape::Hint& hint) {
    using A = tape::Hint::Action;
    switch (hint.action) {
        case A::none:
            return "";
        case A::replace_output:
            return "use --force to replace it";
        case A::use_charset:
            return "use --charset " + std::string(hint.value);
        case A::use_iso_parity:
            return "try --code iso --parity " + std::string(hint.value);
        case A::read_as_image:
            return "if this is a tape image, give --input image";
        case A::give_source_format:
            return "give --from SPEC for implied points";
        case A::use_code:
            return "try --code " + std::string(hint.value);
        case A::use_five_track_code:
            return "try `tape decode --code ita2` or `--code mtk2`";
        case A::encode_text:
            return "use `tape encode` to punch it";
    }
    return "";
}

std::string with_hint(std::string message, const tape::Hint& hint) {
    std::string h = hint_text(hint);
    return h.empty() ? message : message + " (" + h + ")";
}

void say_diagnostic(const std::string& name, const tape::Diagnostic& d, bool raw_frames) {
    std::string where = where_text(d.where, raw_frames);
    say(name, (where.empty() ? "" : where + ": ") + with_hint(d.message, d.hint));
}

void fail(const std::string& file, const tape::Error& e, bool raw_frames) {
    std::string where = where_text(e.where(), raw_frames);
    say(file, (where.empty() ? "" : where + ": ") + with_hint(e.what(), e.hint()));
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

tape::InputOptions input_options(const CodeChoice& choice, const std::string& format_id, const std::string& kind) {
    tape::InputOptions o;
    o.kind = kind == "text"    ? tape::InputKind::text
             : kind == "image" ? tape::InputKind::image
                               : tape::InputKind::automatic;
    o.format = format_id.empty() ? nullptr : tape::find_image_format(format_id);
    o.detect_code = choice.code == "auto";
    o.decode.code = tape::parse_code(choice.code).value_or(tape::Code::iso);
    o.decode.parity = *tape::parse_parity(choice.parity);
    o.decode.charset = *tape::parse_charset(choice.charset);
    o.decode.eia_table = globals().table();
    o.decode.max_diagnostics = globals().max_errors;
    return o;
}

std::unique_ptr<tape::Input> open_input(const std::string& path, const tape::InputOptions& options) {
    if (!options.detect_code && options.decode.code == tape::Code::eia && options.decode.parity != tape::Parity::even)
        fail(display_name(path), tape::Errc::usage, "--parity is for ISO tapes; EIA parity is always odd on track 5");
    std::unique_ptr<tape::Input> input;
    try {
        input = std::make_unique<tape::Input>(path.empty() ? "-" : path, options);
    } catch (const tape::Error& e) {
        fail(display_name(path), e);
    }
    for (const auto& note : input->notes()) say_note(display_name(path), note);
    return input;
}

const tape::DecodeOptions& decide_code(tape::Input& input, const std::string& name) {
    try {
        const tape::DecodeOptions& o = input.decode_options();
        if (globals().verbosity > 0 && input.detection()) say(name, "code " + input.detection()->reason);
        // A code or parity given by hand is taken as given; the verdict is still drawn (from the
        // read-ahead), so that a tape failing the given code can be said to read cleanly another way.
        if (!input.detection()) input.detect();
        return o;
    } catch (const tape::Error& e) {
        fail(name, e);
    }
}

TapeInput read_tape(const std::string& path, const std::string& format_id) {
    TapeInput in;
    in.name = path.empty() ? "-" : path;
    tape::InputOptions o = input_options(CodeChoice{}, format_id, "image");
    o.detect_code = false;
    auto input = open_input(in.name, o);
    in.format = input->format();
    try {
        for (auto frames = input->next_frames(); !frames.empty(); frames = input->next_frames())
            in.frames.insert(in.frames.end(), frames.begin(), frames.end());
    } catch (const tape::Error& e) {
        fail(display_name(in.name), e);
    }
    return in;
}

void add_code_options(CLI::App* sub, CodeChoice& choice, bool with_auto, bool five_track) {
    std::vector<std::string> codes = {"iso", "eia"};
    if (five_track) codes.insert(codes.end(), {"ita2", "mtk2"});
    if (with_auto)
        codes.insert(codes.begin(), "auto");
    else
        choice.code = "iso";
    std::string help = with_auto ? "Tape code: auto (ISO or EIA, judged from the whole tape), iso or eia"
                                 : "Tape code: iso (ISO 7-bit, even parity on track 8) or eia (EIA RS-244)";
    if (five_track)
        help +=
            "; 5-track telegraph tape: ita2 (ITA2 Baudot-Murray, letters/figures shifts) or mtk2 (МТК-2, "
            "with the Russian register); these are never detected";
    sub->add_option("--code,-c", choice.code, help)->check(CLI::IsMember(codes))->capture_default_str();
    sub->add_option("--parity,-p", choice.parity,
                    "Track 8 rule for ISO/ASCII tapes: even (NC tapes), odd, mark (DEC-era ASCII), space, none")
        ->check(CLI::IsMember({"even", "odd", "mark", "space", "none"}))
        ->capture_default_str();
    sub->add_option("--charset", choice.charset, "ascii, or koi7 for Russian text switched with SO/SI (КОИ-7 Н1)")
        ->check(CLI::IsMember({"ascii", "koi7"}))
        ->capture_default_str();
}

std::vector<std::string> format_ids(bool for_writing) {
    std::vector<std::string> ids;
    for (const auto& f : tape::image_formats())
        if (for_writing ? f.can_write() : f.can_read()) ids.emplace_back(f.id);
    return ids;
}

std::string format_choices(bool for_writing) {
    auto ids = format_ids(for_writing);
    std::string text;
    for (std::size_t i = 0; i < ids.size(); ++i) text += (i == 0 ? "" : i + 1 == ids.size() ? " or " : ", ") + ids[i];
    return text;
}

CLI::Validator format_check(bool for_writing) { return CLI::IsMember(format_ids(for_writing)); }

const tape::ImageFormat& output_format(const std::string& format_id, const std::string& path) {
    const tape::ImageFormat* format = format_id.empty() ? nullptr : tape::find_image_format(format_id);
    if (!format && path != "-") format = tape::image_format_for_path(path);
    if (!format) format = &tape::default_image_format();
    if (!format->can_write())
        fail(path, tape::Errc::usage,
             std::string(format->id) + " images can only be read; write " + format_choices(true));
    return *format;
}

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

void add_program_source_options(CLI::App* sub, ProgramSource& source, bool with_keep_going) {
    add_code_options(sub, source.choice, true, true);
    sub->add_option("--format,-f", source.format,
                    "Image format of IN: " + format_choices(false) + " (IN is then a tape image)")
        ->check(format_check(false));
    sub->add_option("--input", source.kind, "What IN is: auto (image or text by extension and content), text, image")
        ->check(CLI::IsMember({"auto", "text", "image"}))
        ->capture_default_str();
    add_dialect_option(sub, source.dialect);
    if (with_keep_going)
        sub->add_flag("--keep-going,-k", source.keep_going,
                      "Go on past bad frames (each reported; exit 1 at the end) instead of stopping at the first");
}

void add_dialect_option(CLI::App* sub, std::string& dialect) {
    sub->add_option("--dialect", dialect,
                    "How programs are read: gost (ГОСТ 20999-83 / ISO 6983 as written), fanuc (O numbers, Custom "
                    "Macro B, ';'), linuxcnc (no '%' needed, lowercase, o-words), auto (chosen from the text; -v "
                    "says which and why)")
        ->check(CLI::IsMember({"auto", "gost", "fanuc", "linuxcnc"}))
        ->capture_default_str();
}

tape::LoadOptions load_options(const ProgramSource& source) {
    return tape::LoadOptions{tape::parse_dialect(source.dialect).value_or(tape::Dialect::automatic)};
}

void say_dialect(const std::string& name, const tape::DialectChoice& choice) {
    if (globals().verbosity <= 0) return;
    say(name, "dialect " + std::string(tape::dialect_name(choice.dialect)) +
                  (choice.reason.empty() ? " (given with --dialect)" : " (" + choice.reason + ")"));
}

ProgramInput open_program(const std::string& path, const ProgramSource& source) {
    tape::InputOptions o = input_options(source.choice, source.format, source.kind);
    o.decode.positions = true;
    o.decode.keep_going = source.keep_going;
    ProgramInput in;
    in.name = display_name(path);
    in.load = load_options(source);
    in.keep_going = source.keep_going;
    in.input = open_input(path, o);
    in.from_tape = in.input->is_image();
    if (in.from_tape) decide_code(*in.input, in.name);
    return in;
}

namespace {
// Bad frames are printed as decode prints them (or left to the visitor), and the dialect said with -v.
class BadFramesFail : public tape::ProgramVisitor {
public:
    BadFramesFail(tape::ProgramVisitor& to, const std::string& name, bool raw, bool frames_to_visitor)
        : to_(to), name_(name), raw_(raw), frames_to_visitor_(frames_to_visitor) {}
    void label(std::string_view text) override { to_.label(text); }
    void program_start(const tape::Program& header) override { to_.program_start(header); }
    void block(const tape::Block& block) override { to_.block(block); }
    void after_end(std::string_view text, const tape::Location& where) override { to_.after_end(text, where); }
    void physical_start() override { to_.physical_start(); }
    void record_end(const tape::Location& where, bool closes_program) override {
        to_.record_end(where, closes_program);
    }
    void dialect(const tape::DialectChoice& choice) override {
        say_dialect(name_, choice);
        to_.dialect(choice);
    }
    void end(const tape::Location& where) override { to_.end(where); }
    void finding(const tape::Finding& f) override {
        if (tape::is_bad_frame(f.code)) {
            bad_ = true;
            if (!frames_to_visitor_) {
                say_diagnostic(name_, f, raw_);
                return;
            }
        }
        to_.finding(f);
    }
    bool bad() const { return bad_; }

private:
    tape::ProgramVisitor& to_;
    const std::string& name_;
    bool raw_;
    bool frames_to_visitor_;
    bool bad_ = false;
};

bool raw_frames(const ProgramInput& in) { return in.from_tape && in.input->format()->bytes_are_frames; }
}  // namespace

void load_program(ProgramInput& in, tape::ProgramVisitor& visitor, bool frames_to_visitor) {
    BadFramesFail guard(visitor, in.name, raw_frames(in), frames_to_visitor && in.keep_going);
    try {
        tape::load_each(*in.input, guard, in.load);
    } catch (const tape::Error& e) {
        fail(in.name, e);
    }
    if (guard.bad()) in.damaged = true;
    if (guard.bad() && !in.keep_going) end_program(in);
}

void end_program(const ProgramInput& in) {
    if (!in.damaged) return;
    if (const tape::Decoder* d = in.input->decoder()) say_unlisted_frames(in.name, d->unlisted());
    say_other_reading(*in.input, in.name);
    throw Exit{bad_data};
}

void say_other_reading(tape::Input& input, const std::string& name) {
    if (!input.is_image() || !input.detection()) return;
    const tape::DecodeOptions& o = input.decode_options();
    // The verdict weighs 8-track readings only: a 5-track code given by hand is not second-guessed.
    if (o.code == tape::Code::ita2 || o.code == tape::Code::mtk2) return;
    tape::Reading forced{o.code, o.code == tape::Code::eia ? tape::Parity::odd : o.parity};
    if (auto note = tape::other_reading(*input.detection(), forced)) say(name, with_hint(note->message, note->hint));
}

void load_program_whole(ProgramInput& in) {
    try {
        tape::load(*in.input, in.tape, in.load);
    } catch (const tape::Error& e) {
        fail(in.name, e);
    }
    say_dialect(in.name, tape::DialectChoice{in.tape.dialect, in.tape.dialect_reason});
    bool bad = false;
    for (const auto& f : in.tape.findings)
        if (tape::is_bad_frame(f.code)) {
            say_diagnostic(in.name, f, raw_frames(in));
            bad = true;
        }
    if (bad) {
        say_other_reading(*in.input, in.name);
        throw Exit{bad_data};
    }
}

tape::FormatSpec parse_spec_or_fail(const std::string& text) {
    try {
        return tape::parse_format_spec(text);
    } catch (const tape::Error& e) {
        fail("", e);
    }
}

std::string json_number(const std::optional<std::uint64_t>& n) { return n ? std::to_string(*n) : "null"; }

std::string finding_json(const tape::Diagnostic& f) {
    return "{\"rule\": " + json_string(std::string(f.id())) +
           ", \"severity\": " + json_string(std::string(tape::severity_name(f.severity))) +
           ", \"frame\": " + json_number(f.where.frame) + ", \"line\": " + json_number(f.where.line) +
           ", \"column\": " + json_number(f.where.column) + ", \"block\": " + json_number(f.where.block) +
           ", \"message\": " + json_string(f.message) + "}";
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

std::string position_text(const tape::Position& where, bool from_tape) {
    if (from_tape && where.frame) return "frame " + std::to_string(*where.frame);
    return "line " + std::to_string(where.line.value_or(0));
}

std::string position_text(const tape::Location& where, bool from_tape) {
    if (from_tape && where.frame) return "frame " + std::to_string(*where.frame);
    return "line " + std::to_string(where.line);
}

std::string label_text(const tape::LeaderLabel& label) {
    return label.text + " (frames " + std::to_string(label.first + 1) + "-" +
           std::to_string(label.first + label.frames) + ", " + (label.code == tape::Code::eia ? "EIA" : "ISO") +
           " letters)";
}

std::string label_json(const std::optional<tape::LeaderLabel>& label) {
    if (!label) return "null";
    return "{\"text\": " + json_string(label->text) + ", \"first_frame\": " + std::to_string(label->first + 1) +
           ", \"frames\": " + std::to_string(label->frames) +
           ", \"code\": " + json_string(std::string(tape::code_name(label->code))) + "}";
}

}  // namespace cli
