// libFuzzer target: what a peer sends the DNC service's control socket, and what tape dnc status reads
// back from it. A request is answered with the status, with nothing, or waited for (never more than
// 64 bytes of it); a reply read back and written again reads the same.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "tape/dnc_service.hpp"

namespace {

bool same(const std::vector<tape::dnc::MachineStatus>& a, const std::vector<tape::dnc::MachineStatus>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].name != b[i].name || a[i].device != b[i].device || a[i].state != b[i].state ||
            a[i].program != b[i].program || a[i].frames != b[i].frames || a[i].total != b[i].total ||
            a[i].sent != b[i].sent || a[i].filed != b[i].filed || a[i].failed != b[i].failed || a[i].last != b[i].last)
            return false;
    return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    const std::string status = "tape-dnc status 1\n";
    for (bool complete : {false, true}) {
        auto reply = tape::dnc::control_reply(text, complete, [&] { return status; });
        if (complete && !reply) __builtin_trap();  // a peer that said all it will is answered
        if (!reply && text.size() >= 64) __builtin_trap();
        if (reply && !reply->empty() && *reply != status) __builtin_trap();
    }
    auto once = tape::dnc::parse_status_lines(text);
    auto twice = tape::dnc::parse_status_lines(tape::dnc::status_lines(once));
    auto thrice = tape::dnc::parse_status_lines(tape::dnc::status_lines(twice));
    if (once.size() != twice.size() || !same(twice, thrice)) __builtin_trap();
    return 0;
}
