#include "cli_common.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "tape/detect.hpp"
#include "tape/file_io.hpp"
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
            loaded_table = tape::CodeTable::parse(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
        } catch (const tape::Error& e) {
            fail(eia_table, e);
        }
    }
    return &*loaded_table;
}

std::string display_name(const std::string& path) { return path.empty() || path == "-" ? "stdin" : path; }

void say(const std::string& file, const std::string& message) {
    std::cerr << "tape: " << (file.empty() ? "" : file + ": ") << message << '\n';
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

std::vector<std::uint8_t> read_input(const std::string& path) {
    try {
        return tape::read_file(path.empty() ? "-" : path);
    } catch (const tape::Error& e) {
        fail(display_name(path), e);
    }
}

TapeInput tape_from_bytes(const std::string& path, const std::vector<std::uint8_t>& bytes, const std::string& format_id) {
    TapeInput in;
    in.name = path.empty() ? "-" : path;
    if (!format_id.empty()) in.format = tape::find_image_format(format_id);
    if (!in.format && in.name != "-") in.format = tape::image_format_for_path(in.name);
    // ".txt" may be a holes picture or not: the content decides, as for names without an extension.
    if (!in.format || in.format->id == "holes")
        in.format = &tape::detect_image_format(std::span(bytes).first(std::min<std::size_t>(bytes.size(), 4096)));
    try {
        in.frames = in.format->read(bytes);
    } catch (const tape::Error& e) {
        fail(display_name(in.name), e);
    }
    return in;
}

TapeInput read_tape(const std::string& path, const std::string& format_id) { return tape_from_bytes(path, read_input(path), format_id); }

bool is_image_input(const std::string& path, const std::vector<std::uint8_t>& bytes, const std::string& format_id, const std::string& kind) {
    if (kind != "auto") return kind == "image";
    if (!format_id.empty()) return true;
    const tape::ImageFormat* by_ext = path.empty() || path == "-" ? nullptr : tape::image_format_for_path(path);
    auto prefix = std::span<const std::uint8_t>(bytes).first(std::min<std::size_t>(bytes.size(), 4096));
    return (by_ext && by_ext->id == "raw") || tape::find_image_format("holes")->match(prefix) >= 60 || !tape::is_program_text(bytes);
}

void add_code_options(CLI::App* sub, CodeChoice& choice, bool with_auto) {
    std::vector<std::string> codes = {"iso", "eia"};
    if (with_auto) codes.insert(codes.begin(), "auto");
    else choice.code = "iso";
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

tape::DecodeOptions resolve_code(const CodeChoice& choice, const TapeInput& input) {
    tape::DecodeOptions o;
    o.parity = *tape::parse_parity(choice.parity);
    o.charset = *tape::parse_charset(choice.charset);
    o.eia_table = globals().table();
    if (choice.code != "auto") {
        o.code = *tape::parse_code(choice.code);
    } else if (o.parity != tape::Parity::even) {
        o.code = tape::Code::iso;  // only ISO/ASCII tapes have a choice of parity
    } else {
        auto d = tape::detect_code(input.frames);
        if (!d.code) fail(display_name(input.name), tape::Errc::unknown_code, d.reason);
        if (globals().verbosity > 0) say(display_name(input.name), "code " + d.reason);
        o.code = *d.code;
    }
    if (o.code == tape::Code::eia && o.parity != tape::Parity::even)
        fail(display_name(input.name), tape::Errc::usage, "--parity is for ISO tapes; EIA parity is always odd on track 5");
    return o;
}

void write_output(const std::string& path, const std::string& data, bool binary, bool force) {
    if (path.empty() || path == "-") {
        if (binary && ::isatty(STDOUT_FILENO) && !force)
            fail("", tape::Errc::usage, "refusing to write a binary tape image to a terminal (use -o FILE, --format holes, or --force)");
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
    sub->add_option("--format,-f", source.format, "Image format of IN: raw or holes (IN is then a tape image)")
        ->check(CLI::IsMember({"raw", "holes"}));
    sub->add_option("--input", source.kind, "What IN is: auto (image or text by extension and content), text, image")
        ->check(CLI::IsMember({"auto", "text", "image"}))
        ->capture_default_str();
}

ProgramInput load_program(const std::string& path, const ProgramSource& source) {
    ProgramInput in;
    in.name = display_name(path);
    std::vector<std::uint8_t> bytes = read_input(path);
    if (!is_image_input(path, bytes, source.format, source.kind)) {
        in.tape = tape::load(std::string(bytes.begin(), bytes.end()));
        return in;
    }
    TapeInput t = tape_from_bytes(path, bytes, source.format);
    tape::DecodeOptions o = resolve_code(source.choice, t);
    o.positions = true;
    tape::DecodeResult r = tape::decode(t.frames, o);
    for (const auto& d : r.diagnostics) say(in.name, where_text(d.where, t.raw()) + ": " + d.message);
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
