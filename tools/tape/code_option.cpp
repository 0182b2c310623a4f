// The tape codes a command offers with --code, from the library's list.
#include "code_option.hpp"

#include "tape/code.hpp"

namespace cli {

std::string code_option_help(bool with_auto) {
    std::string help = with_auto ? "Tape code: auto (judged from the whole tape: ISO, EIA or the Elliott 920 "
                                   "telecode), iso, eia"
                                 : "Tape code: iso (ISO 7-bit, even parity on track 8), eia (EIA RS-244)";
    return help +
           "; 5-track telegraph tape: ita2 (ITA2 Baudot-Murray, letters/figures shifts) or mtk2 (МТК-2, with the "
           "Russian register), never detected; elliott900 (Elliott 900 telecode: ISO-like, £ for #, read as ISO "
           "unless given) or elliott920 (Elliott 920 telecode, parity on track 5)";
}

void widen_code_option(CLI::App* sub, bool with_auto) {
    std::vector<std::string> codes;
    if (with_auto) codes.emplace_back("auto");
    for (tape::Code c : tape::all_codes()) codes.emplace_back(tape::code_name(c));
    CLI::Option* opt = sub->get_option("--code");
    // The narrower check add_code_options() gave is switched off and said no more in --help.
    CLI::Validator* narrow = opt->get_validator();
    narrow->active(false);
    narrow->description("");
    opt->check(CLI::IsMember(codes))->description(code_option_help(with_auto));
}

}  // namespace cli
