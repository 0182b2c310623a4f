#include "cli/completion.hpp"

#include <cctype>
#include <iostream>
#include <vector>

#include "cli/run.hpp"

namespace cli {
namespace {

// A command of the program by its path of subcommand names ("" for the program, "adapter info").
struct Command {
    std::string path;
    std::string subcommands, options, with_value;  ///< words separated by spaces
};

void add_word(std::string& words, const std::string& word) { words += (words.empty() ? "" : " ") + word; }

// Hidden options and subcommands (CLI11's empty group) are left out, as --help leaves them out.
void collect(const CLI::App& app, const std::string& path, std::vector<Command>& out) {
    Command c{path, "", "", ""};
    auto shown = [](const CLI::Option* o) { return o->nonpositional() && !o->get_group().empty(); };
    for (const CLI::Option* o : app.get_options(shown)) {
        std::vector<std::string> names;
        for (const auto& s : o->get_snames()) names.push_back("-" + s);
        for (const auto& l : o->get_lnames()) names.push_back("--" + l);
        for (const auto& name : names) {
            add_word(c.options, name);
            if (o->get_items_expected_max() > 0) add_word(c.with_value, name);
        }
    }
    auto subcommands = app.get_subcommands([](const CLI::App* s) { return !s->get_group().empty(); });
    for (const CLI::App* s : subcommands) add_word(c.subcommands, s->get_name());
    out.push_back(c);
    for (const CLI::App* s : subcommands) collect(*s, path.empty() ? s->get_name() : path + " " + s->get_name(), out);
}

std::string function_name(const std::string& program) {
    std::string name = "_" + program;
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return name;
}

}  // namespace

std::string bash_completion(const CLI::App& app, const std::string& program) {
    std::vector<Command> commands;
    collect(app, "", commands);
    const std::string f = function_name(program);
    std::string s = "# bash completion for " + program + ", made by `" + program + " --bash-completion`\n\n";
    // Sets the words of a command; the options that take a value add up along the path, as a
    // subcommand takes its parents' options too.
    s += f + "_command() {\n    case $1 in\n";
    for (const auto& c : commands)
        s += "        \"" + c.path + "\") subcommands=\"" + c.subcommands + "\" options=\"" + c.options +
             "\" with_value+=\" " + c.with_value + "\" ;;\n";
    s += "    esac\n}\n\n";
    s += f + R"(() {
    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD - 1]}
    local path="" subcommands="" options="" with_value="" i word
    )" + f +
         R"(_command ""
    for ((i = 1; i < COMP_CWORD; i++)); do
        word=${COMP_WORDS[i]}
        if [[ " $with_value " == *" $word "* ]]; then
            ((i++))
        elif [[ " $subcommands " == *" $word "* ]]; then
            path=${path:+$path }$word
            )" +
         f + R"(_command "$path"
        fi
    done
    COMPREPLY=()
    # An option's value, or a word that is no subcommand: a file name (complete -o default).
    [[ " $with_value " == *" $prev "* ]] && return
    if [[ $cur == -* ]]; then
        mapfile -t COMPREPLY < <(compgen -W "$options" -- "$cur")
    elif [[ -n $subcommands ]]; then
        mapfile -t COMPREPLY < <(compgen -W "$subcommands" -- "$cur")
    fi
}
complete -o default -F )" +
         f + " " + program + "\n";
    return s;
}

void add_bash_completion_flag(CLI::App& app, const std::string& program) {
    app.add_flag_callback(
           "--bash-completion",
           [&app, program] {
               std::cout << bash_completion(app, program);
               throw Exit{ok};
           },
           "Print a bash completion script and end")
        ->group("")
        ->trigger_on_parse();
}

}  // namespace cli
