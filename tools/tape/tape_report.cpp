// What info and decode say about a tape beyond its characters: labels, binary formats.
#include "tape_report.hpp"

#include <cstdio>

#include "cli/json.hpp"
#include "cli/messages.hpp"

namespace cli {
namespace {

std::string octal(std::uint32_t v, int digits) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%0*o", digits, v);
    return buf;
}

std::string frames_range(std::uint64_t first, std::uint64_t count) {
    return std::to_string(first + 1) + "-" + std::to_string(first + count);
}

constexpr std::size_t few_blocks = 20;

}  // namespace

std::string leader_label_words(const tape::LeaderLabel& label) {
    if (label.font == tape::LabelFont::title)
        return "a title punched as letters of holes in another font, not read (frames " +
               frames_range(label.first, label.frames) + "; `tape show` draws it)";
    return label_text(label);
}

std::string leader_label_json(const std::optional<tape::LeaderLabel>& label) {
    if (!label) return "null";
    std::string json = label_json(label);
    json.pop_back();
    return json + ", \"kind\": " + (label->font == tape::LabelFont::title ? "\"title\"" : "\"letters\"") + "}";
}

std::string binary_block_line(const tape::BinaryBlock& b) {
    bool pdp11 = b.format == tape::BinaryFormat::pdp11_absolute;
    std::string s = std::string(pdp11 ? (b.end ? "end block" : "block") : tape::binary_format_name(b.format)) +
                    ": frames " + frames_range(b.first, b.frames);
    if (pdp11 && b.end)
        s += ", start address " + octal(b.origin, 6);
    else if (pdp11)
        s += ", load " + octal(b.origin, 6) + ", " + std::to_string(b.words) + " bytes";
    else
        s += ", " + std::to_string(b.origins) + " origin(s) from " + octal(b.origin, 5) + ", " +
             std::to_string(b.words) + " words";
    if (b.checksum) {
        const auto& c = *b.checksum;
        s += ", checksum " + std::string(tape::checksum_state_name(c.state));
        if (c.state == tape::ChecksumSpan::State::fails)
            s += " (punched " + octal(c.stored, pdp11 ? 3 : 4) + ", the frames give " +
                 octal(c.computed, pdp11 ? 3 : 4) + ")";
        if (c.state == tape::ChecksumSpan::State::missing) s += ": the tape ends before it";
    }
    if (b.cut && (!b.checksum || b.checksum->state != tape::ChecksumSpan::State::missing))
        s += "; the tape ends inside it";
    return s;
}

std::string binary_block_lines(const tape::BinaryTape& t, bool every, const std::string& indent) {
    std::string out;
    bool all = every || t.block_count <= few_blocks;
    std::size_t number = 0;
    for (const auto& b : t.blocks) {
        ++number;
        bool holds = !b.checksum || b.checksum->state == tape::ChecksumSpan::State::holds;
        if (all || !holds) out += indent + std::to_string(number) + ". " + binary_block_line(b) + "\n";
    }
    if (!all) out += indent + "(" + std::to_string(t.block_count) + " blocks; -v lists every one)\n";
    if (t.blocks.size() < t.block_count)
        out += indent + "(" + std::to_string(t.block_count - t.blocks.size()) + " more not listed)\n";
    return out;
}

std::string binary_json(const tape::BinaryTape& t) {
    std::string s =
        "{\"format\": " +
        (t.format ? json_string(std::string(tape::binary_format_id(*t.format))) : std::string("null")) +
        ", \"summary\": " + json_string(t.summary()) + ", \"block_count\": " + std::to_string(t.block_count) +
        ", \"checksums\": {\"hold\": " + std::to_string(t.checksums_held) +
        ", \"fail\": " + std::to_string(t.checksums_failed) + ", \"missing\": " + std::to_string(t.checksums_missing) +
        "}, \"start\": " + json_number(t.start ? std::optional<std::uint64_t>(*t.start) : std::nullopt) +
        ", \"stray_frames\": " + std::to_string(t.stray_frames) + ", \"blocks\": [";
    for (std::size_t i = 0; i < t.blocks.size(); ++i) {
        const auto& b = t.blocks[i];
        s += std::string(i ? ", " : "") + "{\"format\": " + json_string(std::string(tape::binary_format_id(b.format))) +
             ", \"first_frame\": " + std::to_string(b.first + 1) + ", \"frames\": " + std::to_string(b.frames) +
             ", \"origin\": " + std::to_string(b.origin) + ", \"words\": " + std::to_string(b.words) +
             ", \"end\": " + (b.end ? "true" : "false") + ", \"cut\": " + (b.cut ? "true" : "false") +
             ", \"checksum\": " +
             (b.checksum ? "{\"state\": " + json_string(std::string(tape::checksum_state_name(b.checksum->state))) +
                               ", \"stored\": " + std::to_string(b.checksum->stored) +
                               ", \"computed\": " + std::to_string(b.checksum->computed) + "}"
                         : std::string("null")) +
             "}";
    }
    return s + "]}";
}

}  // namespace cli
