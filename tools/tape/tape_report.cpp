// What info and decode say about a tape beyond its characters: labels, binary formats.
#include "tape_report.hpp"

#include "cli/json.hpp"
#include "cli/messages.hpp"

namespace cli {
namespace {

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

Json leader_label_info(const std::optional<tape::LeaderLabel>& label) {
    if (!label) return nullptr;
    Json json = label_value(label);
    json["kind"] = label->font == tape::LabelFont::title ? "title" : "letters";
    return json;
}

std::string binary_block_line(const tape::BinaryBlock& b) {
    bool pdp11 = b.format == tape::BinaryFormat::pdp11_absolute;
    std::string s = std::string(pdp11 ? (b.end ? "end block" : "block") : tape::binary_format_name(b.format)) +
                    ": frames " + frames_range(b.first, b.frames);
    if (pdp11 && b.end)
        s += ", start address " + tape::octal_text(b.origin, 6);
    else if (pdp11)
        s += ", load " + tape::octal_text(b.origin, 6) + ", " + std::to_string(b.words) + " bytes";
    else
        s += ", " + std::to_string(b.origins) + " origin(s) from " + tape::octal_text(b.origin, 5) + ", " +
             std::to_string(b.words) + " words";
    if (b.checksum) {
        const auto& c = *b.checksum;
        s += ", checksum " + std::string(tape::checksum_state_name(c.state));
        if (c.state == tape::ChecksumSpan::State::fails)
            s += " (punched " + tape::octal_text(c.stored, pdp11 ? 3 : 4) + ", the frames give " +
                 tape::octal_text(c.computed, pdp11 ? 3 : 4) + ")";
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

Json binary_info(const tape::BinaryTape& t) {
    Json blocks = Json::array();
    for (const auto& b : t.blocks) {
        Json checksum = nullptr;
        if (b.checksum)
            checksum = {{"state", tape::checksum_state_name(b.checksum->state)},
                        {"stored", b.checksum->stored},
                        {"computed", b.checksum->computed}};
        blocks.push_back({{"format", tape::binary_format_id(b.format)},
                          {"first_frame", b.first + 1},
                          {"frames", b.frames},
                          {"origin", b.origin},
                          {"words", b.words},
                          {"end", b.end},
                          {"cut", b.cut},
                          {"checksum", checksum}});
    }
    Json json = {
        {"format", t.format ? Json(tape::binary_format_id(*t.format)) : Json(nullptr)},
        {"summary", t.summary()},
        {"block_count", t.block_count},
        {"checksums", {{"hold", t.checksums_held}, {"fail", t.checksums_failed}, {"missing", t.checksums_missing}}},
        {"start", t.start ? Json(*t.start) : Json(nullptr)},
        {"stray_frames", t.stray_frames},
        {"blocks", blocks}};
    return json;
}

}  // namespace cli
