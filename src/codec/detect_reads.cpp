// The code of a tape read several times: each read judged on its own, the reading most of them fit
// chosen. Taking the longest read alone let one read of noise (a reader left running, a torn leader)
// turn the verdict to "no code" for reads that all fit ISO.
#include <algorithm>
#include <vector>

#include "tape/detect.hpp"

namespace tape {

namespace {

bool fits_a_code(const CodeDetection& d) {
    return d.code && d.reading && (d.kind == TapeKind::iso || d.kind == TapeKind::eia || d.kind == TapeKind::ascii);
}

struct Vote {
    Reading reading;
    std::size_t reads = 0;
    std::uint64_t frames = 0;
    std::size_t longest = 0;  // index of its longest read
};

}  // namespace

ReadsDetection detect_code_of_reads(std::span<const std::span<const Frame>> reads, const CodeTable* eia_table) {
    ReadsDetection out;
    if (reads.empty()) return out;
    std::vector<CodeDetection> verdicts;
    std::vector<Vote> votes;
    for (std::size_t i = 0; i < reads.size(); ++i) {
        verdicts.push_back(detect_code(reads[i], eia_table));
        if (reads[i].size() > reads[out.from].size()) out.from = i;
        if (!fits_a_code(verdicts[i])) continue;
        auto v =
            std::find_if(votes.begin(), votes.end(), [&](const Vote& x) { return x.reading == *verdicts[i].reading; });
        if (v == votes.end()) v = votes.insert(votes.end(), Vote{.reading = *verdicts[i].reading, .longest = i});
        ++v->reads;
        v->frames += reads[i].size();
        if (reads[i].size() > reads[v->longest].size()) v->longest = i;
    }
    auto best = std::max_element(votes.begin(), votes.end(), [](const Vote& a, const Vote& b) {
        return a.reads != b.reads ? a.reads < b.reads : a.frames < b.frames;
    });
    if (best != votes.end()) out.from = best->longest, out.agreeing = best->reads;
    out.detection = std::move(verdicts[out.from]);
    return out;
}

}  // namespace tape
