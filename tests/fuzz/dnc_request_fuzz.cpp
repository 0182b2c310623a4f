// libFuzzer target: a punch-out's text as the DNC service reads a request from it. Whatever comes from
// the line, every name it lets through is one name_problem accepts: no path, no NUL, no over-long
// name, nothing but letters, digits, '_', '-' and '.'; and a restart's block is N and digits.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "tape/dnc_request.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    auto request = tape::dnc::parse_request(text);
    if (!request) return 0;
    for (const auto& name : request->names) {
        if (!tape::dnc::name_problem(name).empty()) __builtin_trap();
        if (name.size() > tape::dnc::max_name_length || name.find("..") != std::string::npos ||
            name.find('/') != std::string::npos || name.find('\0') != std::string::npos || name[0] == '.')
            __builtin_trap();
    }
    if (request->kind == tape::dnc::Request::Kind::restart && !request->names.empty()) {
        const std::string& b = request->block;
        if (b.size() < 2 || (b[0] != 'N' && b[0] != 'n' && b[0] != ':')) __builtin_trap();
        for (std::size_t i = 1; i < b.size(); ++i)
            if (b[i] < '0' || b[i] > '9') __builtin_trap();
    }
    if (request->comment.size() > 82) __builtin_trap();
    return 0;
}
