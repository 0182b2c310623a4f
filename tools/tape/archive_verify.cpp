// tape archive verify: a bag checked against its manifests (tape/archive.hpp), then its reads restored
// again and each restored image compared with the one the bag holds.
#include "archive_bag.hpp"
#include "cli/messages.hpp"
#include "cli/outputs.hpp"
#include "cli/run.hpp"
#include "restore_run.hpp"
#include "tape/file_io.hpp"

namespace cli {
namespace {

void say_problem(const std::string& bag, const tape::BagProblem& p) {
    std::string where = bag + (p.file.empty() ? "" : "/" + p.file);
    say(where, (p.line ? "line " + std::to_string(p.line) + ": " : std::string()) + (p.note ? "note: " : "") + p.id +
                   ": " + p.message);
}

// The first frame where two images differ, in words; "" when they are the same.
std::string difference(const std::string& a, const std::string& b) {
    if (a == b) return "";
    std::size_t n = 0;
    while (n < a.size() && n < b.size() && a[n] == b[n]) ++n;
    return "they differ from byte " + std::to_string(n) + " on (" + std::to_string(a.size()) + " bytes held, " +
           std::to_string(b.size()) + " restored again)";
}

// Restores the reads again as when the bag was made; false when the image is not the one held.
bool same_restoration(const std::string& bag, const BagRestoration& r, const tape::MachineProfile* machine) {
    std::vector<std::string> paths;
    for (const auto& n : r.reads) paths.push_back(bag + "/data/" + n);
    ReadsAndDoubts in = read_tapes_or_pictures(paths);
    RestoreReportInput report;
    report.code = code_for_reads("auto", "", in.reads, report.code_text);
    RestoreChoices choices;
    choices.machine = machine;  // the profile the bag keeps, as when it was made
    tape::RestoreResult result = run_restore(choices, in, report);
    tape::ImageWriteOptions wo;
    if (report.code) wo.annotate = &*report.code;
    std::string again = image_text(output_format("", r.image), result.frames, wo, r.image);
    auto held = tape::read_file(bag + "/data/" + r.image);
    std::string why = difference(std::string(held.begin(), held.end()), again);
    if (!why.empty())
        say(bag + "/data/" + r.image, "restored-again: restoring its " + std::to_string(r.reads.size()) +
                                          " read(s) again gives another image: " + why);
    return why.empty();
}

}  // namespace

void archive_verify(const std::string& bag, bool fast) {
    tape::BagCheck c;
    try {
        c = tape::verify_bag(bag);
    } catch (const tape::Error& e) {
        fail(bag, e);
    }
    for (const auto& p : c.problems) say_problem(bag, p);
    std::string algorithms;
    for (const auto& a : c.algorithms) algorithms += (algorithms.empty() ? "" : " and ") + a;
    if (!c.valid()) {
        say(bag, "not valid: " + std::to_string(c.problems.size()) + " problem(s) above");
        throw Exit{bad_data};
    }
    std::string done = "valid: " + std::to_string(c.files) + " payload files, " + std::to_string(c.octets) +
                       " bytes, every " + algorithms + " checksum right";
    if (fast) return say(bag, done + " (--fast: the restorations were not made again)");
    std::vector<BagRestoration> rs = bag_restorations(bag);
    std::optional<tape::MachineProfile> machine = bag_machine(bag);
    bool same = true;
    for (const auto& r : rs) same = same_restoration(bag, r, machine ? &*machine : nullptr) && same;
    if (!same) {
        say(bag, "checksums right, but a restoration is not what its reads give (see above)");
        throw Exit{bad_data};
    }
    say(bag, done + "; restoring the reads again gives " +
                 (rs.empty() ? std::string("nothing: the bag holds no restoration")
                             : "the same image" + std::string(rs.size() > 1 ? "s" : "") + " (" +
                                   std::to_string(rs.size()) + ")"));
}

}  // namespace cli
