// tape info: what is on a tape — code, parity found, frame counts, program starts.
#include <algorithm>
#include <cstdio>
#include <sstream>

#include "cli_common.hpp"
#include "commands.hpp"
#include "tape/detect.hpp"
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

void run(const InfoArgs& a) {
    std::string name = display_name(a.input);
    tape::InputOptions io = input_options(CodeChoice{}, a.format, "image");
    io.detect_code = false;
    auto in = open_input(a.input, io);
    std::optional<tape::Code> code;
    std::string reason;
    std::optional<tape::Parity> rule;  // the parity rule errors are counted against, once it is known
    try {
        if (a.code == "auto") {
            const auto& d = in->detect();
            code = d.code;
            reason = d.reason;
            reason = with_hint(reason, d.hint);
        } else {
            code = tape::parse_code(a.code);
            reason = "given with --code";
        }
    } catch (const tape::Error& e) {
        fail(name, e);
    }
    if (!a.parity.empty())
        rule = *tape::parse_parity(a.parity);
    else if (code)
        rule = tape::Parity::even;
    // Without a code, errors are counted against the rule the whole tape uses: one survey a rule, in
    // one pass, and the one of the rule found is shown.
    std::vector<tape::Parity> rules =
        rule ? std::vector{*rule}
             : std::vector{tape::Parity::even, tape::Parity::odd, tape::Parity::mark, tape::Parity::space};
    std::vector<tape::Surveyor> surveyors;
    for (auto r : rules)
        surveyors.emplace_back(tape::FrameCode::make(code.value_or(tape::Code::iso), r, globals().table()));
    try {
        for (auto frames = in->next_frames(); !frames.empty(); frames = in->next_frames())
            for (auto& s : surveyors) s.feed(frames);
    } catch (const tape::Error& e) {
        fail(name, e);
    }
    auto counts = surveyors.front().result().parity;
    if (!rule) rule = counts.dominant().value_or(tape::Parity::even);
    auto chosen = static_cast<std::size_t>(std::find(rules.begin(), rules.end(), *rule) - rules.begin());
    tape::FrameCode fc = tape::FrameCode::make(code.value_or(tape::Code::iso), *rule, globals().table());
    tape::TapeSurvey s = surveyors[chosen].result();
    std::string code_text = code ? std::string(tape::code_name(*code)) : "unknown";
    std::ostringstream out;
    if (a.json) {
        out << "{\"file\": " << json_string(name) << ", \"format\": " << json_string(std::string(in->format()->id))
            << ", \"code\": " << (code ? json_string(code_text) : "null")
            << ", \"code_reason\": " << json_string(reason) << ", \"parity\": " << json_string(parity_found(counts))
            << ", \"parity_rule\": " << json_string(std::string(tape::parity_name(fc.parity())))
            << ", \"frames\": {\"total\": " << s.frames << ", \"leader\": " << s.leader << ", \"data\": " << s.data
            << ", \"del\": " << s.rubouts << ", \"blank_inside\": " << s.blank_inside << ", \"trailer\": " << s.trailer
            << ", \"parity_errors\": " << s.parity_errors << ", \"not_in_code\": " << s.not_in_code
            << "}, \"program_starts\": " << s.program_starts << ", \"end_of_blocks\": " << s.end_of_blocks << "}\n";
    } else {
        auto misfit = counts.dominant() ? counts.misfits(*counts.dominant()) : 0;
        out << "file:           " << name << "\n"
            << "format:         " << in->format()->id << "\n"
            << "code:           " << code_text << " (" << reason << ")\n"
            << "parity found:   " << parity_found(counts) << " (" << counts.frames << " punched frames, " << counts.even
            << " even, " << counts.odd << " odd, " << counts.mark << " with track 8"
            << (misfit ? ", " + std::to_string(misfit) + " do not fit" : "") << ")\n"
            << "frames:         " << s.frames << "\n"
            << "  leader:       " << s.leader << "\n"
            << "  data:         " << s.data << "\n"
            << "  DEL:          " << s.rubouts << "\n"
            << "  blank inside: " << s.blank_inside << "\n"
            << "  trailer:      " << s.trailer << "\n"
            << "  parity errors:" << ' ' << s.parity_errors << " (" << tape::parity_name(fc.parity()) << " rule)\n";
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
