#include "restart_frames.hpp"

#include <iostream>

#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/messages.hpp"
#include "tape/restart.hpp"

namespace cli {
namespace {

// IN's text: a text program as it is, an image decoded (a bad frame ends the program, as decode does).
std::string program_text(const std::string& path, const FeedProfile& p) {
    std::string name = display_name(path);
    auto input = open_input(path, input_options(p.choice, p.format, p.kind));
    if (input->is_image()) decide_code(*input, name);
    tape::DecodeResult all;
    try {
        while (input->next_text(all)) {
        }
    } catch (const tape::Error& e) {
        fail(name, e);
    }
    if (!all.diagnostics.empty()) {
        for (const auto& d : all.diagnostics) say_diagnostic(name, d, false);
        fail(name, tape::Errc::bad_program, "a restart needs the whole program: it has bad frames");
    }
    return all.text;
}

}  // namespace

std::vector<tape::Frame> restart_frames(const std::string& path, const FeedProfile& p, const std::string& block,
                                        bool show, bool lathe) {
    std::string name = display_name(path);
    tape::RestartPlan plan;
    try {
        plan = tape::plan_restart(program_text(path, p), block,
                                  tape::parse_dialect(p.dialect).value_or(tape::Dialect::automatic), lathe);
    } catch (const tape::Error& e) {
        fail(name, tape::Errc::usage, std::string("cannot restart at ") + block + ": " + e.what());
    }
    if (globals().verbosity >= 0)
        say(name, "restart at " + plan.block + " (line " + std::to_string(plan.line) + "), " +
                      std::to_string(plan.skipped_blocks) + " block(s) before it not sent, " +
                      std::to_string(plan.modal.size()) + " block(s) of modal state rebuilt, " +
                      std::to_string(plan.approach.size()) + " block(s) of approach");
    if (show) {
        std::cout << plan.header();
        return {};
    }
    std::string text = plan.text();
    tape::InputOptions io = feed_input_options(p);
    io.kind = tape::InputKind::text;
    io.format = nullptr;
    tape::Input input(std::make_unique<tape::MemorySource>(
                          std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size())),
                      name, io);
    return frames_to_send(input, name, p);
}

}  // namespace cli
