#include "tape/damage.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include "tape/error.hpp"

namespace tape {
namespace {

// splitmix64 (Steele, Lea, Flood 2014): fully specified in a few lines, so that a seed means the same
// damage on every platform, which std:: distributions do not promise.
class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1): the top 53 bits, which a double holds exactly.
    double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    /// Uniform in [0, n), n > 0; the modulo's bias (n / 2^64) is far below anything a test could see.
    std::uint64_t below(std::uint64_t n) { return next() % n; }

private:
    std::uint64_t state_;
};

// One frame of the tape on its way to the reader.
struct Piece {
    Frame frame;
    std::size_t original;  // index in the undamaged tape; 0 for blank frames added to the leader
    bool missing = false;  // torn out, removed from the leader, or never read
};

// An event of the steps before reading: its read index is known once the reader has passed its piece.
struct PendingEvent {
    DamageEvent event;
    std::size_t piece;
};

std::string number_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

void check_rate(const char* name, double rate) {
    if (!(rate >= 0 && rate <= 1))  // written so that NaN fails too
        throw Error(Errc::usage, std::string(name) + " must be a rate from 0 to 1, not " + number_text(rate));
}

std::size_t magnitude(long v) {
    // Through unsigned arithmetic, so that the most negative long has a magnitude too.
    return v < 0 ? static_cast<std::size_t>(0UL - static_cast<unsigned long>(v)) : static_cast<std::size_t>(v);
}

// Marks `count` consecutive pieces from `first` missing and returns the pending event.
PendingEvent mark_missing(std::vector<Piece>& pieces, DamageKind kind, std::size_t first, std::size_t count) {
    for (std::size_t i = first; i < first + count; ++i) pieces[i].missing = true;
    return PendingEvent{DamageEvent{kind, pieces[first].original, 0, count}, first};
}

// Step 1: a stretch of the data torn out, between the first and the last punched frame.
void tear(std::vector<Piece>& pieces, std::size_t first_original, std::span<const Frame> tape, std::size_t torn,
          Random& random, std::vector<PendingEvent>& pending) {
    if (torn == 0) return;
    auto punched = punched_part(tape);
    if (punched.empty()) throw Error(Errc::usage, "the tape has no punched frame: there is no data to tear");
    std::size_t data = punched.size();
    if (torn > data)
        throw Error(Errc::usage, "cannot tear " + std::to_string(torn) + " frames out of data only " +
                                     std::to_string(data) + " frames long");
    std::size_t start = static_cast<std::size_t>(punched.data() - tape.data()) + random.below(data - torn + 1);
    pending.push_back(mark_missing(pieces, DamageKind::torn, first_original + start, torn));
}

// Step 3: frames never read at the start and the end, counted among those still there.
void cut_ends(std::vector<Piece>& pieces, const DamageOptions& o, std::vector<PendingEvent>& pending) {
    std::size_t left = 0;
    for (const Piece& p : pieces) left += p.missing ? 0 : 1;
    auto cut = [&](DamageKind kind, std::size_t count, bool from_start) {
        if (count == 0) return;
        std::size_t lowest = 0;  // the event names the first cut frame in tape order
        for (std::size_t k = 0, done = 0; done < count; ++k) {
            std::size_t i = from_start ? k : pieces.size() - 1 - k;
            if (pieces[i].missing) continue;
            pieces[i].missing = true;
            if (!from_start || done == 0) lowest = i;
            ++done;
        }
        pending.push_back(PendingEvent{DamageEvent{kind, pieces[lowest].original, 0, count}, lowest});
    };
    std::size_t late = std::min(o.start_late, left);
    cut(DamageKind::start_late, late, true);
    cut(DamageKind::stop_early, std::min(o.stop_early, left - late), false);
}

// Step 4: the reader passes every piece; events drawn frame by frame. Pending events get their read
// index as the reader passes their piece.
class Reader {
public:
    Reader(const DamageOptions& o, Random& random, std::vector<PendingEvent>& pending, DamageLog* log)
        : o_(o), random_(random), pending_(pending), log_(log) {
        // Visited in piece order, so that one pass resolves them all; the log keeps the order applied.
        for (std::size_t i = 0; i < pending_.size(); ++i) by_piece_.push_back(i);
        std::sort(by_piece_.begin(), by_piece_.end(),
                  [this](std::size_t a, std::size_t b) { return pending_[a].piece < pending_[b].piece; });
    }

    std::vector<Frame> read(const std::vector<Piece>& pieces) {
        std::size_t left = 0;  // frames still to be read, so that a burst at the end is cut short
        for (const Piece& p : pieces) left += p.missing ? 0 : 1;
        out_.reserve(left + left / 8);
        for (std::size_t i = 0; i < pieces.size(); ++i) {
            resolve(i);
            if (pieces[i].missing) continue;
            frame(pieces[i], left);
            --left;
        }
        return std::move(out_);
    }

    std::vector<DamageEvent>& events() { return events_; }

private:
    void resolve(std::size_t piece) {
        for (; next_pending_ < by_piece_.size() && pending_[by_piece_[next_pending_]].piece == piece; ++next_pending_)
            pending_[by_piece_[next_pending_]].event.read = out_.size();
    }

    void frame(const Piece& p, std::size_t left) {
        if (burst_left_ > 0) {
            --burst_left_;
            out_.push_back(garbled(p.frame));
            return;
        }
        // One draw against the rates in the documented order.
        double u = random_.unit();
        double burst = o_.bursts, drop = burst + o_.drops, flip = drop + o_.flips, twice = flip + o_.doubles;
        if (u < burst) {
            std::size_t length = std::min(o_.burst_length, left);
            note(DamageKind::burst, p, length);
            burst_left_ = length - 1;
            out_.push_back(garbled(p.frame));
        } else if (u < drop) {
            note(DamageKind::drop, p, 1);
        } else if (u < flip) {
            int track = 1 + static_cast<int>(random_.below(static_cast<std::uint64_t>(o_.tracks)));
            note(DamageKind::flip, p, 1, track);
            out_.push_back(static_cast<Frame>(p.frame ^ (1U << (track - 1))));
        } else if (u < twice) {
            note(DamageKind::double_read, p, 1);
            out_.push_back(p.frame);
            out_.push_back(p.frame);
        } else {
            out_.push_back(p.frame);
        }
    }

    // A stained frame reads as any frame of the tracks but the one punched: every frame a burst logs is
    // damaged.
    Frame garbled(Frame f) {
        std::uint64_t others = (std::uint64_t{1} << o_.tracks) - 1;
        return static_cast<Frame>(f ^ (1 + random_.below(others)));
    }

    void note(DamageKind kind, const Piece& p, std::size_t frames, int track = 0) {
        if (log_) events_.push_back(DamageEvent{kind, p.original, out_.size(), frames, track});
    }

    const DamageOptions& o_;
    Random& random_;
    std::vector<PendingEvent>& pending_;
    std::vector<std::size_t> by_piece_;
    std::size_t next_pending_ = 0;
    DamageLog* log_;
    std::vector<Frame> out_;
    std::vector<DamageEvent> events_;
    std::size_t burst_left_ = 0;
};

}  // namespace

void check_damage_options(const DamageOptions& o) {
    check_rate("flips", o.flips);
    check_rate("drops", o.drops);
    check_rate("doubles", o.doubles);
    check_rate("bursts", o.bursts);
    // Each frame meets at most one event, drawn with one number: the chances must fit in 1 (with room for
    // rounding, so that rates written to add up to 1 are taken).
    double sum = o.bursts + o.drops + o.flips + o.doubles;
    if (sum > 1 + 1e-9)
        throw Error(Errc::usage, "flips, drops, doubles and bursts add up to " + number_text(sum) +
                                     " per frame; they may add up to 1 at most");
    if (o.bursts > 0 && o.burst_length == 0) throw Error(Errc::usage, "a burst must be at least 1 frame long");
    if (o.tracks < 1 || o.tracks > 8)
        throw Error(Errc::usage, "a tape has 1 to 8 tracks, not " + std::to_string(o.tracks));
}

DamageOptions mixed_damage(double rate, std::uint64_t seed, std::size_t burst_length) {
    DamageOptions o;
    o.seed = seed;
    o.flips = o.drops = o.doubles = rate / 4;
    o.burst_length = burst_length;
    o.bursts = rate / 4 / static_cast<double>(std::max<std::size_t>(burst_length, 1));
    return o;
}

std::string_view damage_kind_name(DamageKind kind) {
    switch (kind) {
        case DamageKind::torn:
            return "torn";
        case DamageKind::leader_added:
            return "leader-added";
        case DamageKind::leader_removed:
            return "leader-removed";
        case DamageKind::start_late:
            return "start-late";
        case DamageKind::stop_early:
            return "stop-early";
        case DamageKind::burst:
            return "burst";
        case DamageKind::drop:
            return "drop";
        case DamageKind::flip:
            return "flip";
        case DamageKind::double_read:
            return "double";
    }
    return "";
}

void DamageLog::add(const DamageEvent& event) {
    events.push_back(event);
    ++counts[static_cast<std::size_t>(event.kind)];
}

std::vector<Frame> damage(std::span<const Frame> tape, const DamageOptions& o, DamageLog* log) {
    check_damage_options(o);
    if (log) *log = DamageLog{};
    Random random(o.seed);
    // The leader's blank frames added go in front; the original frames follow at offset `added`.
    std::size_t added = o.leader > 0 ? magnitude(o.leader) : 0;
    std::vector<Piece> pieces;
    pieces.reserve(added + tape.size());
    pieces.insert(pieces.end(), added, Piece{blank_frame, 0});
    for (std::size_t i = 0; i < tape.size(); ++i) pieces.push_back(Piece{tape[i], i});

    std::vector<PendingEvent> pending;
    tear(pieces, added, tape, o.torn, random, pending);
    if (added > 0) pending.push_back(PendingEvent{DamageEvent{DamageKind::leader_added, 0, 0, added}, 0});
    if (o.leader < 0) {
        auto punched = punched_part(tape);
        auto leader = punched.empty() ? tape.size() : static_cast<std::size_t>(punched.data() - tape.data());
        std::size_t removed = std::min(magnitude(o.leader), leader);
        if (removed > 0) pending.push_back(mark_missing(pieces, DamageKind::leader_removed, 0, removed));
    }
    cut_ends(pieces, o, pending);

    // The log lists the steps before reading in the order applied, then what the reader met.
    Reader reader(o, random, pending, log);
    std::vector<Frame> out = reader.read(pieces);
    if (log) {
        for (const PendingEvent& p : pending) log->add(p.event);
        for (const DamageEvent& e : reader.events()) log->add(e);
    }
    return out;
}

}  // namespace tape
