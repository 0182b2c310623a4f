// tape info: what is on a tape — code, parity found, frame counts, program starts; for a binary loader
// tape its format, blocks and checksums.
#include <algorithm>
#include <cstdio>
#include <sstream>

#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/json.hpp"
#include "cli/messages.hpp"
#include "cli/options.hpp"
#include "cli/outputs.hpp"
#include "commands.hpp"
#include "tape/detect.hpp"
#include "tape/label.hpp"
#include "tape/survey.hpp"
#include "tape_report.hpp"

namespace cli {
namespace {

struct InfoArgs {
    std::string input = "-", format, code = "auto", parity;
    bool json = false;
};

// What info says, gathered from one pass over the tape.
struct InfoFacts {
    std::string name, format;
    tape::CodeDetection d;
    std::optional<tape::LeaderLabel> label;
    std::optional<tape::Code> code;  // the code the counts are read with, when one is known
    bool given_code = false;
    bool declared = false;                   // the code is the one the image's header names
    std::string reason;                      // how the code was chosen
    tape::Parity rule = tape::Parity::even;  // the parity errors are counted against it
    tape::TapeSurvey s;
    std::optional<tape::Diagnostic> other;  // another reading that fits, when the code was given
    std::string advice;
};

std::string parity_found(const tape::ParityCounts& p) {
    auto d = p.dominant();
    if (!d) return p.frames == 0 ? "none" : "mixed";
    return std::string(tape::parity_name(*d));
}

// The evidence of the verdict, one reading a line: what decoding the tape that way gives.
std::string fit_text(const tape::ReadingFit& f) {
    return std::to_string(f.bad_frames) + " bad frames, " + std::to_string(f.controls) + " stray controls, " +
           std::to_string(f.end_of_blocks) + " end of blocks";
}

Json evidence_info(const tape::TapeEvidence& e) {
    Json readings = Json::array();
    for (const auto& f : e.fits)
        readings.push_back({{"reading", tape::reading_name(f.reading)},
                            {"bad_frames", f.bad_frames},
                            {"controls", f.controls},
                            {"end_of_blocks", f.end_of_blocks}});
    return {{"frames", e.frames},  {"punched", e.punched},    {"even", e.parity.even},
            {"odd", e.parity.odd}, {"track8", e.parity.mark}, {"five_track", e.five_track},
            {"iso_lf", e.iso_lf},  {"eia_eob", e.eia_eob},    {"longest_track8_run", e.longest_0x80_run},
            {"text", e.text},      {"readings", readings}};
}

// Every frame goes through the detector, which decodes it each way at once (and tries the binary loader
// formats), and, for a code or rule it does not try, through one surveyor more.
InfoFacts scan(const InfoArgs& a) {
    InfoFacts f;
    f.name = display_name(a.input);
    tape::InputOptions io = input_options(CodeChoice{}, a.format, "image");
    io.detect_code = false;
    auto in = open_input(a.input, io);
    f.format = std::string(in->format()->id);
    tape::Detector detector(globals().table(), in->format()->bytes_are_frames);
    std::optional<tape::Parity> given_rule;
    if (!a.parity.empty()) given_rule = *tape::parse_parity(a.parity);
    f.given_code = a.code != "auto";
    if (f.given_code) f.code = *tape::parse_code(a.code);
    std::optional<tape::Surveyor> extra;
    try {
        if (auto named = in->declared_code(); !f.given_code && named && *named != tape::Code::iso) {
            f.code = named;
            f.declared = true;
        }
        if (f.given_code || f.declared || given_rule)
            extra.emplace(tape::FrameCode::make(f.code.value_or(tape::Code::iso),
                                                given_rule.value_or(tape::Parity::even), globals().table()));
        // A leader label is holes, but no data: counted as the blank leader it is punched into.
        f.label = in->label();
        std::uint64_t at = 0;
        std::vector<tape::Frame> scratch;
        for (auto frames = in->next_frames(); !frames.empty(); frames = in->next_frames()) {
            auto counted = tape::without_label(frames, at, f.label, scratch);
            at += frames.size();
            detector.feed(counted);
            if (extra) extra->feed(counted);
        }
    } catch (const tape::Error& e) {
        fail(f.name, e);
    }
    detector.finish();
    f.d = detector.result();
    if (!f.given_code && !f.declared) f.code = f.d.code;
    f.reason = f.given_code ? "given with --code" : f.declared ? "named by the image's header" : f.d.reason;
    // Errors are counted against the rule given, else the one of the code, else the one the tape fits.
    f.rule = given_rule    ? *given_rule
             : f.code      ? tape::Parity::even
             : f.d.reading ? f.d.reading->parity
                           : f.d.evidence.parity.dominant().value_or(tape::Parity::even);
    tape::Reading reading{f.code.value_or(tape::Code::iso), f.code == tape::Code::eia ? tape::Parity::odd : f.rule};
    f.s = extra ? extra->result() : detector.survey(reading);
    if ((f.given_code || given_rule) && !tape::is_five_track(reading.code)) f.other = tape::other_reading(f.d, reading);
    f.advice = hint_text(f.d.hint);
    if (tape::looks_like_koi7(f.d.evidence) && f.code == tape::Code::iso)
        f.advice =
            "Russian text in КОИ-7: letters shifted by SO ... SI read as Latin letters; decode with "
            "--charset koi7";
    return f;
}

// A label-only tape is no blank tape: it holds a label and no data.
std::string verdict_text(const InfoFacts& f) {
    if (f.d.kind == tape::TapeKind::blank && f.label)
        return "a leader label and no data: none of the other " +
               std::to_string(f.d.evidence.frames - f.label->frames) + " frames is punched";
    return f.d.reason;
}

std::string json_report(const InfoFacts& f) {
    const auto& s = f.s;
    auto text_or_null = [](bool given, const std::string& text) { return given ? Json(text) : Json(nullptr); };
    Json frames = {{"total", s.frames},
                   {"leader", s.leader},
                   {"data", s.data},
                   {"del", s.rubouts},
                   {"blank_inside", s.blank_inside},
                   {"trailer", s.trailer},
                   {"parity_errors", s.parity_errors},
                   {"not_in_code", s.not_in_code}};
    Json report = {
        {"file", f.name},
        {"format", f.format},
        {"code", f.code ? Json(std::string(tape::code_name(*f.code))) : Json(nullptr)},
        {"code_reason", f.reason},
        {"kind", std::string(tape::tape_kind_name(f.d.kind))},
        {"verdict", verdict_text(f)},
        {"leader_label", leader_label_info(f.label)},
        {"advice", text_or_null(!f.advice.empty(), f.advice)},
        {"other_reading", text_or_null(f.other.has_value(), f.other ? with_hint(f.other->message, f.other->hint) : "")},
        {"binary", f.d.evidence.binary ? binary_info(*f.d.evidence.binary) : Json(nullptr)},
        {"evidence", evidence_info(f.d.evidence)},
        {"parity", parity_found(f.d.evidence.parity)},
        {"parity_rule", std::string(tape::parity_name(f.rule))},
        {"frames", frames},
        {"program_starts", s.program_starts},
        {"end_of_blocks", s.end_of_blocks}};
    return json_text(report) + "\n";
}

std::string evidence_lines(const InfoFacts& f) {
    const auto& e = f.d.evidence;
    std::ostringstream out;
    out << "evidence:       " << e.punched << " punched of " << e.frames << " frames, " << e.five_track
        << " with tracks 6-8 clear, " << e.iso_lf << " LF (ISO end of block), " << e.eia_eob
        << " track 8 alone (EIA end of block), longest run of those " << e.longest_0x80_run << "\n";
    for (const auto& fit : e.fits) {
        std::string label = "  as " + tape::reading_name(fit.reading) + ":";
        out << label << std::string(label.size() < 30 ? 30 - label.size() : 1, ' ') << fit_text(fit) << "\n";
    }
    return out.str();
}

std::string counts_lines(const InfoFacts& f) {
    const auto& s = f.s;
    const auto& counts = f.d.evidence.parity;
    auto misfit = counts.dominant() ? counts.misfits(*counts.dominant()) : 0;
    std::ostringstream out;
    out << "parity found:   " << parity_found(counts) << " (" << counts.frames << " punched frames, " << counts.even
        << " even, " << counts.odd << " odd, " << counts.mark << " with track 8"
        << (misfit ? ", " + std::to_string(misfit) + " do not fit" : "") << ")\n"
        << "frames:         " << s.frames << "\n"
        << "  leader:       " << s.leader << "\n"
        << "  data:         " << s.data << "\n"
        << "  DEL:          " << s.rubouts << "\n"
        << "  blank inside: " << s.blank_inside << "\n"
        << "  trailer:      " << s.trailer << "\n"
        << "  parity errors:" << ' ' << s.parity_errors << " (" << tape::parity_name(f.rule) << " rule)\n";
    if (s.not_in_code) out << "  not in code:  " << s.not_in_code << "\n";
    out << "program starts: " << s.program_starts << "\n"
        << "end of blocks:  " << s.end_of_blocks << "\n";
    return out.str();
}

std::string text_report(const InfoFacts& f) {
    std::ostringstream out;
    out << "file:           " << f.name << "\n"
        << "format:         " << f.format << "\n"
        << "code:           " << (f.code ? std::string(tape::code_name(*f.code)) : "unknown")
        << (f.given_code ? " (given with --code)"
            : f.declared ? " (named by the image's header)"
                         : "")
        << "\n"
        << "tape:           " << verdict_text(f) << "\n";
    if (f.label) out << "leader label:   " << leader_label_words(*f.label) << "\n";
    if (const auto& b = f.d.evidence.binary) {
        out << "binary:         " << b->summary() << "\n";
        out << binary_block_lines(*b, globals().verbosity > 0, "  ");
    }
    if (!f.advice.empty()) out << "advice:         " << f.advice << "\n";
    if (f.other) out << "note:           " << with_hint(f.other->message, f.other->hint) << "\n";
    return out.str() + evidence_lines(f) + counts_lines(f);
}

void run(const InfoArgs& a) {
    InfoFacts f = scan(a);
    write_output("-", a.json ? json_report(f) : text_report(f), false, false);
}

}  // namespace

std::string tape_info_text(const std::string& path, const std::string& shown) {
    InfoArgs a;
    a.input = path;
    InfoFacts f = scan(a);
    f.name = shown;
    return text_report(f);
}

void add_info(CLI::App& app) {
    auto a = std::make_shared<InfoArgs>();
    auto* sub = app.add_subcommand(
        "info",
        "Tell what is on a tape: code, parity found, frame counts, program starts; the format, blocks and checksums "
        "of a binary loader tape (PDP-8 RIM and BIN, PDP-11 absolute loader)");
    sub->add_option("input", a->input, "Tape image; - or nothing for stdin");
    sub->add_option("--code,-c", a->code,
                    code_option_help(true, CodeSet::all) + "; a code given counts the frames its way")
        ->check(CLI::IsMember(code_choices(true, CodeSet::all)))
        ->capture_default_str();
    sub->add_option("--parity,-p", a->parity,
                    "Count parity errors against this rule (default: even, or what the tape uses)")
        ->check(CLI::IsMember({"even", "odd", "mark", "space", "none"}));
    sub->add_option("--format,-f", a->format, "Image format of IN: " + format_choices(false))
        ->check(format_check(false));
    sub->add_flag("--json", a->json, "One JSON object for other programs");
    sub->callback([a] { run(*a); });
}

}  // namespace cli
