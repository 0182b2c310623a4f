// tape info: what is on a tape — code, parity found, frame counts, program starts.
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

namespace cli {
namespace {

struct InfoArgs {
    std::string input = "-", format, code = "auto", parity;
    bool json = false;
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

std::string evidence_json(const tape::TapeEvidence& e) {
    std::ostringstream o;
    o << "{\"frames\": " << e.frames << ", \"punched\": " << e.punched << ", \"even\": " << e.parity.even
      << ", \"odd\": " << e.parity.odd << ", \"track8\": " << e.parity.mark << ", \"five_track\": " << e.five_track
      << ", \"iso_lf\": " << e.iso_lf << ", \"eia_eob\": " << e.eia_eob
      << ", \"longest_track8_run\": " << e.longest_0x80_run << ", \"text\": " << (e.text ? "true" : "false")
      << ", \"readings\": [";
    for (std::size_t i = 0; i < e.fits.size(); ++i) {
        const auto& f = e.fits[i];
        o << (i ? ", " : "") << "{\"reading\": " << json_string(tape::reading_name(f.reading))
          << ", \"bad_frames\": " << f.bad_frames << ", \"controls\": " << f.controls
          << ", \"end_of_blocks\": " << f.end_of_blocks << "}";
    }
    o << "]}";
    return o.str();
}

void run(const InfoArgs& a) {
    std::string name = display_name(a.input);
    tape::InputOptions io = input_options(CodeChoice{}, a.format, "image");
    io.detect_code = false;
    auto in = open_input(a.input, io);
    // The verdict is drawn from the whole tape: every frame goes through the detector, which decodes
    // it each way at once, and (for a rule it does not try) through one surveyor more.
    tape::Detector detector(globals().table(), in->format()->bytes_are_frames);
    std::optional<tape::Parity> given_rule;
    if (!a.parity.empty()) given_rule = *tape::parse_parity(a.parity);
    const bool given_code = a.code != "auto";
    const tape::Code code_given = a.code == "eia" ? tape::Code::eia : tape::Code::iso;
    std::optional<tape::Surveyor> extra;
    if (given_rule) extra.emplace(tape::FrameCode::make(code_given, *given_rule, globals().table()));
    // A leader label is holes, but no data: counted as the blank leader it is punched into.
    std::optional<tape::LeaderLabel> label;
    try {
        label = in->label();
        std::uint64_t at = 0;
        std::vector<tape::Frame> scratch;
        for (auto frames = in->next_frames(); !frames.empty(); frames = in->next_frames()) {
            auto counted = tape::without_label(frames, at, label, scratch);
            at += frames.size();
            detector.feed(counted);
            if (extra) extra->feed(counted);
        }
    } catch (const tape::Error& e) {
        fail(name, e);
    }
    tape::CodeDetection d = detector.result();
    std::optional<tape::Code> code = given_code ? std::optional(code_given) : d.code;
    std::string reason = given_code ? "given with --code" : d.reason;
    // Errors are counted against the rule given, else the one of the code, else the one the tape fits.
    tape::Parity rule = given_rule  ? *given_rule
                        : code      ? tape::Parity::even
                        : d.reading ? d.reading->parity
                                    : d.evidence.parity.dominant().value_or(tape::Parity::even);
    tape::Reading reading{code.value_or(tape::Code::iso), code == tape::Code::eia ? tape::Parity::odd : rule};
    tape::TapeSurvey s = extra ? extra->result() : detector.survey(reading);
    auto counts = d.evidence.parity;
    std::string code_text = code ? std::string(tape::code_name(*code)) : "unknown";
    std::optional<tape::Diagnostic> other;
    if (given_code || given_rule) other = tape::other_reading(d, reading);
    std::string advice = hint_text(d.hint);
    std::ostringstream out;
    if (a.json) {
        out << "{\"file\": " << json_string(name) << ", \"format\": " << json_string(std::string(in->format()->id))
            << ", \"code\": " << (code ? json_string(code_text) : "null")
            << ", \"code_reason\": " << json_string(reason)
            << ", \"kind\": " << json_string(std::string(tape::tape_kind_name(d.kind)))
            << ", \"verdict\": " << json_string(d.reason) << ", \"leader_label\": " << label_json(label)
            << ", \"advice\": " << (advice.empty() ? "null" : json_string(advice))
            << ", \"other_reading\": " << (other ? json_string(with_hint(other->message, other->hint)) : "null")
            << ", \"evidence\": " << evidence_json(d.evidence) << ", \"parity\": " << json_string(parity_found(counts))
            << ", \"parity_rule\": " << json_string(std::string(tape::parity_name(rule)))
            << ", \"frames\": {\"total\": " << s.frames << ", \"leader\": " << s.leader << ", \"data\": " << s.data
            << ", \"del\": " << s.rubouts << ", \"blank_inside\": " << s.blank_inside << ", \"trailer\": " << s.trailer
            << ", \"parity_errors\": " << s.parity_errors << ", \"not_in_code\": " << s.not_in_code
            << "}, \"program_starts\": " << s.program_starts << ", \"end_of_blocks\": " << s.end_of_blocks << "}\n";
    } else {
        const auto& e = d.evidence;
        auto misfit = counts.dominant() ? counts.misfits(*counts.dominant()) : 0;
        out << "file:           " << name << "\n"
            << "format:         " << in->format()->id << "\n"
            << "code:           " << code_text << (given_code ? " (given with --code)" : "") << "\n"
            << "tape:           " << d.reason << "\n";
        if (label) out << "leader label:   " << label_text(*label) << "\n";
        if (!advice.empty()) out << "advice:         " << advice << "\n";
        if (other) out << "note:           " << with_hint(other->message, other->hint) << "\n";
        out << "evidence:       " << e.punched << " punched of " << e.frames << " frames, " << e.five_track
            << " with tracks 6-8 clear, " << e.iso_lf << " LF (ISO end of block), " << e.eia_eob
            << " track 8 alone (EIA end of block), longest run of those " << e.longest_0x80_run << "\n";
        for (const auto& f : e.fits) {
            std::string label = "  as " + tape::reading_name(f.reading) + ":";
            out << label << std::string(label.size() < 30 ? 30 - label.size() : 1, ' ') << fit_text(f) << "\n";
        }
        out << "parity found:   " << parity_found(counts) << " (" << counts.frames << " punched frames, " << counts.even
            << " even, " << counts.odd << " odd, " << counts.mark << " with track 8"
            << (misfit ? ", " + std::to_string(misfit) + " do not fit" : "") << ")\n"
            << "frames:         " << s.frames << "\n"
            << "  leader:       " << s.leader << "\n"
            << "  data:         " << s.data << "\n"
            << "  DEL:          " << s.rubouts << "\n"
            << "  blank inside: " << s.blank_inside << "\n"
            << "  trailer:      " << s.trailer << "\n"
            << "  parity errors:" << ' ' << s.parity_errors << " (" << tape::parity_name(rule) << " rule)\n";
        if (s.not_in_code) out << "  not in code:  " << s.not_in_code << "\n";
        out << "program starts: " << s.program_starts << "\n"
            << "end of blocks:  " << s.end_of_blocks << "\n";
    }
    write_output("-", out.str(), false, false);
}

}  // namespace

void add_info(CLI::App& app) {
    auto a = std::make_shared<InfoArgs>();
    auto* sub = app.add_subcommand("info", "Tell what is on a tape: code, parity found, frame counts, program starts");
    sub->add_option("input", a->input, "Tape image; - or nothing for stdin");
    sub->add_option("--code,-c", a->code, "auto, iso or eia")
        ->check(CLI::IsMember({"auto", "iso", "eia"}))
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
