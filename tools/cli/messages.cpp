#include "cli/messages.hpp"

#include <cstdio>
#include <iostream>

#include "cli/globals.hpp"
#include "tape/utf8_text.hpp"

namespace cli {

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
    say(name, (where.empty() ? "" : where + ": ") + std::string(tape::severity_name(d.severity)) + ": " +
                  with_hint(d.message, d.hint));
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

std::string label_text(const tape::LeaderLabel& label) {
    return label.text + " (frames " + std::to_string(label.first + 1) + "-" +
           std::to_string(label.first + label.frames) + ", " + (label.code == tape::Code::eia ? "EIA" : "ISO") +
           " letters)";
}

std::string position_text(const tape::Position& where, bool from_tape) {
    if (from_tape && where.frame) return "frame " + std::to_string(*where.frame);
    return "line " + std::to_string(where.line.value_or(0));
}

std::string position_text(const tape::Location& where, bool from_tape) {
    if (from_tape && where.frame) return "frame " + std::to_string(*where.frame);
    return "line " + std::to_string(where.line);
}

}  // namespace cli
