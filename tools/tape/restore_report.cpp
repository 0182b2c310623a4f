// The restore report as text and as JSON (restore_report.hpp).
#include "restore_report.hpp"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "cli/globals.hpp"
#include "cli/inputs.hpp"
#include "cli/json.hpp"
#include "cli/messages.hpp"
#include "tape/restore_doubts.hpp"

namespace cli {
namespace {

std::string cm(std::uint64_t frame) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", tape::frame_distance_cm(frame));
    return buf;
}

double cm_value(std::uint64_t frame) { return std::round(tape::frame_distance_cm(frame) * 10) / 10; }

constexpr tape::FrameStatus all_statuses[] = {
    tape::FrameStatus::clean,      tape::FrameStatus::voted,     tape::FrameStatus::inferred,
    tape::FrameStatus::guessed,    tape::FrameStatus::contested, tape::FrameStatus::unstable,
    tape::FrameStatus::unresolved, tape::FrameStatus::missing,   tape::FrameStatus::extra};

std::string summary_text(const tape::RestoreResult& r) {
    std::string s = "frames:";
    for (auto st : all_statuses)
        s += std::string(st == tape::FrameStatus::clean ? " " : ", ") + std::string(tape::status_name(st)) + " " +
             std::to_string(r.count(st));
    s += "  (extra: read by a minority, not written; missing: ends of the tape no read covers)\n";
    if (r.run_length_votes)
        s += "voted on a run length: " + std::to_string(r.run_length_votes) +
             " run(s) of equal frames whose length the reads disagreed on, decided by the odds of a lost or doubled "
             "frame or by the program's rules\n";
    if (r.contested_unwritten)
        s += "in doubt and not written: " + std::to_string(r.contested_unwritten) + " frame(s) most reads lack\n";
    return s;
}

// Frames left out at one place for one reason, each read having the same there: the blank frames of a
// longer leader or trailer, said once for the stretch.
bool alike(const tape::RestoreProblem& a, const tape::RestoreProblem& b) {
    return !a.frame && !b.frame && a.after == b.after && a.status == b.status && a.reason == b.reason &&
           a.seen == b.seen && a.covered == b.covered && a.written == b.written && a.line == b.line;
}

// count: how many alike problems p stands for.
std::string problem_text(const RestoreReportInput& in, const tape::RestoreProblem& p, std::size_t count) {
    std::string s = "  " + problem_place(p) + (p.line ? " (line " + std::to_string(*p.line) + ")" : "") +
                    (p.frame ? ", " + cm(*p.frame) + " cm" : "") + ": " + std::string(tape::status_name(p.status)) +
                    (count > 1 ? ", " + std::to_string(count) + " frames alike" : "") + ": " + p.reason + "\n";
    for (std::size_t i = 0; i < p.seen.size(); ++i)
        s += "      read " + std::to_string(i + 1) + ": " +
             (p.seen[i]      ? frame_text(in.code, *p.seen[i])
              : p.covered[i] ? "no frame"
                             : "not read here") +
             "\n";
    if (p.status == tape::FrameStatus::missing) return s;
    s += std::string("      ") + (!p.frame ? "not written: " : "written: ") + frame_text(in.code, p.written) + "\n";
    if (!p.candidates.empty() && p.status != tape::FrameStatus::inferred) {
        s += p.status == tape::FrameStatus::guessed ? "      alternatives:" : "      candidates:";
        for (std::size_t i = p.status == tape::FrameStatus::guessed ? 1 : 0; i < p.candidates.size(); ++i)
            s += " " + frame_text(in.code, p.candidates[i]) + ";";
        s.back() = '\n';
    }
    return s;
}

std::string quoted_hex_or_null(bool has, tape::Frame f) { return has ? "\"" + tape::frame_hex(f) + "\"" : "null"; }

// One problem as JSON, written straight into s in nlohmann-json's compact layout: a long tape's report
// lists tens of thousands of voted frames, and a JSON value built for each cost more than the restoration.
void append_problem_json(std::string& s, const tape::RestoreProblem& p) {
    using nlohmann::ordered_json;
    auto number_or_null = [](auto n) { return n ? std::to_string(*n) : std::string("null"); };
    s += "{\"status\":\"" + std::string(tape::status_name(p.status)) + "\",\"in_doubt\":";
    s += tape::in_doubt(p.status) ? "true" : "false";
    s += ",\"frame\":" + number_or_null(p.frame) + ",\"after\":" + std::to_string(p.after);
    s += ",\"line\":" + number_or_null(p.line) + ",\"cm\":";
    s += p.frame ? ordered_json(cm_value(*p.frame)).dump() : "null";
    s += ",\"seen\":[";
    for (std::size_t i = 0; i < p.seen.size(); ++i) {
        s += (i ? ",{\"read\":" : "{\"read\":") + std::to_string(i + 1) + ",\"covered\":";
        s += p.covered[i] ? "true" : "false";
        s += ",\"frame\":" + quoted_hex_or_null(p.seen[i].has_value(), p.seen[i].value_or(0)) + "}";
    }
    bool written = p.frame && p.status != tape::FrameStatus::missing;
    s += "],\"written\":" + quoted_hex_or_null(written, p.written);
    s += ",\"left_out\":" + quoted_hex_or_null(!p.frame, p.written) + ",\"candidates\":[";
    for (std::size_t i = 0; i < p.candidates.size(); ++i)
        s += (i ? "," : "") + quoted_hex_or_null(true, p.candidates[i]);
    s += std::string("],\"run_length\":") + (p.run_length ? "true" : "false") + ",\"odds\":";
    // The odds of the length written over the next (null: the program's rules decided): with the doubts
    // file, decode -v and lint name each run decided against a read.
    s += p.run_length && p.odds > 0 ? ordered_json(std::round(p.odds)).dump() : "null";
    s += ",\"reason\":" + ordered_json(p.reason).dump() + "}";
}

}  // namespace

std::string problem_place(const tape::RestoreProblem& p) {
    return p.frame ? "frame " + std::to_string(*p.frame) : "after frame " + std::to_string(p.after);
}

std::optional<tape::FrameCode> code_for_reads(const std::string& code, const std::string& parity,
                                              const std::vector<TapeInput>& reads, std::string& name) {
    name = code;
    if (code == "none") return std::nullopt;
    // A parity given alone names the code too: ISO with that parity, as decode takes it.
    if (code != "auto" || !parity.empty()) {
        auto c = code == "auto" ? tape::Code::iso : *tape::parse_code(code);
        auto p = c == tape::Code::eia ? tape::Parity::odd : *tape::parse_parity(parity.empty() ? "even" : parity);
        auto made = tape::FrameCode::make(c, p, globals().table());
        name = c == tape::Code::eia ? "EIA" : "ISO with " + std::string(tape::parity_name(made.parity())) + " parity";
        return made;
    }
    std::vector<std::span<const tape::Frame>> frames;
    for (const auto& r : reads) frames.emplace_back(r.frames);
    tape::ReadsDetection voted = tape::detect_code_of_reads(frames, globals().table());
    const tape::CodeDetection& d = voted.detection;
    if (globals().verbosity > 0) say(display_name(reads[voted.from].name), d.reason);
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
        if (!tape::in_doubt(p.status)) continue;
        std::uint64_t at = p.frame ? *p.frame : std::max<std::uint64_t>(p.after, 1);
        std::uint64_t from = at > margin ? at - margin : 1;
        std::uint64_t to = std::min<std::uint64_t>(at + margin, std::max<std::size_t>(r.frames.size(), 1));
        if (!out.empty() && from <= out.back().to + join)
            out.back().to = std::max(out.back().to, to);
        else
            out.push_back({from, to});
    }
    return out;
}

std::string left_out_text(const RestoreReportInput& in, std::size_t i) {
    // A blank read shares nothing with the others, but it is no read of another tape.
    if (i < in.blank.size() && in.blank[i]) return "left out: no punched frame (blank tape only)";
    return "left out: a read of another tape, or too damaged to align";
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
             " frames, " + (r.related[i] ? std::string(share) + "% shared with the reference" : left_out_text(in, i)) +
             "\n";
    }
    s += summary_text(r);
    if (!r.problems.empty()) s += "problems:\n";
    for (std::size_t i = 0, n = 1; i < r.problems.size(); i += n) {
        for (n = 1; i + n < r.problems.size() && alike(r.problems[i], r.problems[i + n]);) ++n;
        s += problem_text(in, r.problems[i], n);
    }
    auto reread = reread_list(r);
    if (!reread.empty()) {
        s += "read again:\n";
        for (const auto& x : reread)
            s += "  frames " + std::to_string(x.from) + "-" + std::to_string(x.to) + ", " + cm(x.from) + "-" +
                 cm(x.to) + " cm from the first feed hole\n";
    }
    if (r.code_misfit)
        s += "most frames fail the code " + in.code_text +
             ": the reads were voted as frames of no code, nothing "
             "repaired\n";
    else if (r.unchecked)
        s += "one read of a tape in no code: nothing could be checked, so nothing is known to be right\n";
    else
        s += r.complete() ? "every frame is clean, voted or inferred\n"
                          : "not every frame could be restored: the image holds them as read, listed above\n";
    return s;
}

// The report is one JSON object, its members made by nlohmann-json one by one, so that the problems of a
// long tape are never all held as JSON values at once.
std::string restore_report_json(const RestoreReportInput& in) {
    using nlohmann::ordered_json;
    const tape::RestoreResult& r = *in.result;
    std::string s = "{";
    auto member = [&s](const char* key, const ordered_json& value) {
        s += (s.size() > 1 ? "," : "") + ordered_json(key).dump() + ":" + value.dump();
    };
    member("schema", "tape-restore/2");
    member("code", in.code ? ordered_json(in.code_text) : ordered_json(nullptr));
    ordered_json reads = ordered_json::array();
    for (std::size_t i = 0; i < in.names.size(); ++i)
        reads.push_back({{"file", display_name(in.names[i])},
                         {"frames", in.sizes[i]},
                         {"shared", std::round(r.shared[i] * 1000) / 1000},
                         {"related", static_cast<bool>(r.related[i])}});
    member("reads", reads);
    member("reference", r.reference + 1);
    member("frames", r.frames.size());
    member("complete", r.complete());
    member("checked", !r.unchecked);
    ordered_json summary;
    for (auto st : all_statuses) summary[std::string(tape::status_name(st))] = r.count(st);
    summary["run_length_votes"] = r.run_length_votes;
    summary["in_doubt_not_written"] = r.contested_unwritten;
    member("summary", summary);
    s += ",\"problems\":[";
    for (std::size_t i = 0; i < r.problems.size(); ++i) {
        if (i) s += ",";
        append_problem_json(s, r.problems[i]);
    }
    s += "]";
    ordered_json reread = ordered_json::array();
    for (const auto& x : reread_list(r))
        reread.push_back({{"from", x.from}, {"to", x.to}, {"from_cm", cm_value(x.from)}, {"to_cm", cm_value(x.to)}});
    member("reread", reread);
    if (!in.image_name.empty() && in.image_name != "-") {
        auto bytes = std::span(reinterpret_cast<const std::uint8_t*>(in.image_bytes.data()), in.image_bytes.size());
        member(
            "image",
            {{"file", in.image_name}, {"bytes", in.image_bytes.size()}, {"fnv1a64", tape::image_fingerprint(bytes)}});
    }
    return s + "}\n";
}

}  // namespace cli
