#include "restore_report.hpp"

#include <cstdio>

#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/json.hpp"
#include "cli/messages.hpp"

namespace cli {
namespace {

std::string cm(std::uint64_t frame) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", tape::frame_distance_cm(frame));
    return buf;
}

bool needs_reread(tape::FrameStatus s) {
    using S = tape::FrameStatus;
    return s == S::contested || s == S::unstable || s == S::unresolved || s == S::missing;
}

constexpr tape::FrameStatus all_statuses[] = {tape::FrameStatus::clean,    tape::FrameStatus::voted,
                                              tape::FrameStatus::inferred, tape::FrameStatus::contested,
                                              tape::FrameStatus::unstable, tape::FrameStatus::unresolved,
                                              tape::FrameStatus::missing,  tape::FrameStatus::extra};

}  // namespace

std::optional<tape::FrameCode> code_for_reads(const std::string& code, const std::string& parity,
                                              const std::vector<TapeInput>& reads, std::string& name) {
    name = code;
    if (code == "none") return std::nullopt;
    if (code != "auto") {
        auto c = *tape::parse_code(code);
        return tape::FrameCode::make(c, c == tape::Code::eia ? tape::Parity::odd : *tape::parse_parity(parity),
                                     globals().table());
    }
    const TapeInput* longest = &reads.front();
    for (const auto& r : reads)
        if (r.frames.size() > longest->frames.size()) longest = &r;
    tape::CodeDetection d = tape::detect_code(longest->frames, globals().table());
    if (globals().verbosity > 0) say(display_name(longest->name), d.reason);
    if (!d.code || !d.reading ||
        (d.kind != tape::TapeKind::iso && d.kind != tape::TapeKind::eia && d.kind != tape::TapeKind::ascii)) {
        name = "none";
        return std::nullopt;
    }
    name = tape::reading_name(*d.reading);
    return tape::FrameCode::make(d.reading->code, d.reading->parity, globals().table());
}

std::string frame_text(const std::optional<tape::FrameCode>& code, tape::Frame f) {
    std::string s = tape::holes_picture(f);
    if (!code) return s;
    switch (code->kind(f)) {
        case tape::FrameKind::character:
            return s + " '" + tape::char_label(code->character(f)) + "'";
        case tape::FrameKind::blank:
            return s + " blank";
        case tape::FrameKind::rubout:
            return s + " DEL";
        case tape::FrameKind::parity_error:
            return s + " parity error";
        case tape::FrameKind::not_in_code:
            return s + " not in the code";
    }
    return s;
}

std::vector<RereadRange> reread_list(const tape::RestoreResult& r) {
    constexpr std::uint64_t margin = 5, join = 20;
    std::vector<RereadRange> out;
    for (const auto& p : r.problems) {
        if (!needs_reread(p.status) || !p.frame) continue;
        std::uint64_t from = *p.frame > margin ? *p.frame - margin : 1;
        std::uint64_t to = std::min<std::uint64_t>(*p.frame + margin, r.frames.size());
        if (!out.empty() && from <= out.back().to + join)
            out.back().to = std::max(out.back().to, to);
        else
            out.push_back({from, to});
    }
    return out;
}

std::string restore_report_text(const RestoreReportInput& in) {
    const tape::RestoreResult& r = *in.result;
    std::string s = "restored " + std::to_string(r.frames.size()) + " frames from " + std::to_string(in.names.size()) +
                    " read(s), aligned to read " + std::to_string(r.reference + 1) + " (" +
                    display_name(in.names[r.reference]) + "); code " + in.code_text + "\n";
    for (std::size_t i = 0; i < in.names.size(); ++i) {
        char share[16];
        std::snprintf(share, sizeof share, "%.1f", r.shared[i] * 100);
        s += "  read " + std::to_string(i + 1) + ": " + display_name(in.names[i]) + ", " + std::to_string(in.sizes[i]) +
             " frames, " + share + "% shared with the reference\n";
    }
    s += "frames:";
    for (auto st : all_statuses)
        s += std::string(st == tape::FrameStatus::clean ? " " : ", ") + std::string(tape::status_name(st)) + " " +
             std::to_string(r.count(st));
    s += "  (extra: read by a minority, not written; missing: ends of the tape no read covers)\n";
    if (!r.problems.empty()) s += "problems:\n";
    for (const auto& p : r.problems) {
        s += "  " + (p.frame ? "frame " + std::to_string(*p.frame) : "after frame " + std::to_string(p.after)) +
             (p.line ? " (line " + std::to_string(*p.line) + ")" : "") + (p.frame ? ", " + cm(*p.frame) + " cm" : "") +
             ": " + std::string(tape::status_name(p.status)) + ": " + p.reason + "\n";
        if (p.status == tape::FrameStatus::missing) continue;
        for (std::size_t i = 0; i < p.seen.size(); ++i)
            s += "      read " + std::to_string(i + 1) + ": " +
                 (p.seen[i]      ? frame_text(in.code, *p.seen[i])
                  : p.covered[i] ? "no frame"
                                 : "not read here") +
                 "\n";
        s += std::string("      ") + (!p.frame ? "not written: " : "written: ") + frame_text(in.code, p.written) + "\n";
        if (!p.candidates.empty() && p.status != tape::FrameStatus::inferred) {
            s += "      candidates:";
            for (auto c : p.candidates) s += " " + frame_text(in.code, c) + ";";
            s.back() = '\n';
        }
    }
    auto reread = reread_list(r);
    if (!reread.empty()) {
        s += "read again:\n";
        for (const auto& x : reread)
            s += "  frames " + std::to_string(x.from) + "-" + std::to_string(x.to) + ", " + cm(x.from) + "-" +
                 cm(x.to) + " cm from the first feed hole\n";
    }
    s += r.complete() ? "every frame is clean, voted or inferred\n"
                      : "not every frame could be restored: the image holds them as read, listed above\n";
    return s;
}

std::string restore_report_json(const RestoreReportInput& in) {
    const tape::RestoreResult& r = *in.result;
    std::string s =
        "{\"schema\": \"tape-restore/1\", \"code\": " + (in.code ? json_string(in.code_text) : std::string("null")) +
        ", \"reads\": [";
    for (std::size_t i = 0; i < in.names.size(); ++i)
        s += std::string(i ? ", " : "") + "{\"file\": " + json_string(display_name(in.names[i])) +
             ", \"frames\": " + std::to_string(in.sizes[i]) + ", \"shared\": " + std::to_string(r.shared[i]) + "}";
    s += "], \"reference\": " + std::to_string(r.reference + 1) + ", \"frames\": " + std::to_string(r.frames.size()) +
         ", \"complete\": " + (r.complete() ? "true" : "false") + ", \"summary\": {";
    for (auto st : all_statuses)
        s += std::string(st == tape::FrameStatus::clean ? "" : ", ") + json_string(std::string(tape::status_name(st))) +
             ": " + std::to_string(r.count(st));
    s += "}, \"problems\": [";
    bool first = true;
    for (const auto& p : r.problems) {
        s += std::string(first ? "" : ", ") + "{\"status\": " + json_string(std::string(tape::status_name(p.status))) +
             ", \"frame\": " + json_number(p.frame) + ", \"after\": " + std::to_string(p.after) +
             ", \"line\": " + json_number(p.line) + ", \"cm\": " + (p.frame ? cm(*p.frame) : "null") + ", \"seen\": [";
        first = false;
        for (std::size_t i = 0; i < p.seen.size(); ++i)
            s += std::string(i ? ", " : "") + "{\"read\": " + std::to_string(i + 1) +
                 ", \"covered\": " + (p.covered[i] ? "true" : "false") +
                 ", \"frame\": " + (p.seen[i] ? json_string(tape::frame_hex(*p.seen[i])) : "null") + "}";
        s += "], \"written\": " +
             (p.status == tape::FrameStatus::missing ? std::string("null") : json_string(tape::frame_hex(p.written))) +
             ", \"candidates\": [";
        for (std::size_t i = 0; i < p.candidates.size(); ++i)
            s += std::string(i ? ", " : "") + json_string(tape::frame_hex(p.candidates[i]));
        s += "], \"reason\": " + json_string(p.reason) + "}";
    }
    s += "], \"reread\": [";
    auto reread = reread_list(r);
    for (std::size_t i = 0; i < reread.size(); ++i)
        s += std::string(i ? ", " : "") + "{\"from\": " + std::to_string(reread[i].from) +
             ", \"to\": " + std::to_string(reread[i].to) + ", \"from_cm\": " + cm(reread[i].from) +
             ", \"to_cm\": " + cm(reread[i].to) + "}";
    s += "]}\n";
    return s;
}

}  // namespace cli
