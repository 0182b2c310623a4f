#include "cli/options.hpp"

#include "cli/messages.hpp"
#include "tape/code.hpp"
#include "tape/image.hpp"

namespace cli {

std::vector<std::string> code_choices(bool with_auto, CodeSet codes) {
    std::vector<std::string> names;
    if (with_auto) names.emplace_back("auto");
    for (tape::Code c : tape::all_codes())
        if (codes == CodeSet::all || !tape::is_telecode(c)) names.emplace_back(tape::code_name(c));
    return names;
}

std::string code_option_help(bool with_auto, CodeSet codes) {
    const std::string telegraph =
        "; 5-track telegraph tape: ita2 (ITA2 Baudot-Murray, letters/figures shifts) or mtk2 (МТК-2, with the "
        "Russian register)";
    if (codes == CodeSet::all)
        return (with_auto ? "Tape code: auto (judged from the whole tape: ISO, EIA or the Elliott 920 telecode), "
                            "iso, eia"
                          : "Tape code: iso (ISO 7-bit, even parity on track 8), eia (EIA RS-244)") +
               telegraph +
               ", never detected; elliott900 (Elliott 900 telecode: ISO-like, £ for #, read as ISO unless given) or "
               "elliott920 (Elliott 920 telecode, parity on track 5)";
    return (with_auto ? "Tape code: auto (ISO or EIA, judged from the whole tape), iso or eia"
                      : "Tape code: iso (ISO 7-bit, even parity on track 8) or eia (EIA RS-244)") +
           telegraph + "; these are never detected";
}

void add_code_options(CLI::App* sub, CodeChoice& choice, bool with_auto, CodeSet codes) {
    if (!with_auto) choice.code = "iso";
    sub->add_option("--code,-c", choice.code, code_option_help(with_auto, codes))
        ->check(CLI::IsMember(code_choices(with_auto, codes)))
        ->capture_default_str();
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

void add_dialect_option(CLI::App* sub, std::string& dialect) {
    sub->add_option("--dialect", dialect,
                    "How programs are read: gost (ГОСТ 20999-83 / ISO 6983 as written), fanuc (O numbers, Custom "
                    "Macro B, ';'), linuxcnc (no '%' needed, lowercase, o-words), auto (chosen from the text; -v "
                    "says which and why)")
        ->check(CLI::IsMember({"auto", "gost", "fanuc", "linuxcnc"}))
        ->capture_default_str();
}

tape::FormatSpec parse_spec_or_fail(const std::string& text) {
    try {
        return tape::parse_format_spec(text);
    } catch (const tape::Error& e) {
        fail("", e);
    }
}

}  // namespace cli
