// The damage model: a damaged read of a tape, made from a seed, for testing and benchmarking restoration.
// The same tape, options and seed give the same read, frame for frame, with any compiler on any platform:
// the random numbers come from our own generator (splitmix64), never from std:: distributions.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "tape/frame.hpp"

namespace tape {

/// What damage to do. Rates are chances per frame, from 0 to 1. They are applied in this order:
///
///  1. torn: a stretch of `torn` consecutive frames is cut out at a random place inside the data (the
///     stretch lies between the first and the last punched frame, both included).
///  2. leader: `leader` > 0 adds that many blank frames at the start; < 0 removes that many blank frames
///     from the start, but never more than the leader the tape has (never a punched frame).
///  3. start_late, stop_early: that many frames at the start (end) are never read — the reader started
///     late or stopped early; any frames, blank or punched, and no more than there are.
///  4. Then frame by frame through what remains, in order, each frame meets at most one of these, drawn
///     with one random number against the rates in this order (so their sum must not exceed 1):
///     bursts (a stain or splice starts here: this frame and the next burst_length - 1, or fewer at the
///     end, read as random bytes, each different from what was punched; no other event starts inside a
///     burst), drops (the frame is not read), flips (one of its `tracks` holes, 8 unless told, chosen at random, reads
///     the other way: a punched frame may read blank and a blank one punched), doubles (the frame is read
///     twice).
struct DamageOptions {
    std::uint64_t seed = 0;
    double flips = 0;
    double drops = 0;
    double doubles = 0;
    double bursts = 0;             ///< chance that a burst starts at a frame
    std::size_t burst_length = 4;  ///< frames a burst garbles; at least 1
    std::size_t torn = 0;          ///< frames torn out inside the data; no more than the data spans
    long leader = 0;               ///< blank frames added (+) or removed (-) at the start
    std::size_t start_late = 0;    ///< frames not read at the start
    std::size_t stop_early = 0;    ///< frames not read at the end
    /// Tracks the tape has, 1 to 8: flips and the bytes of bursts touch tracks 1..tracks only, so that
    /// a damaged 5-track tape (give 5) still holds 5-track frames.
    int tracks = 8;
};

/// Options with one mixed rate spread evenly over flips, drops, doubles and bursts, so that about that
/// fraction of frames is damaged: each of the four kinds gets a quarter, and since a burst damages
/// burst_length frames, its chance of starting is that quarter divided by burst_length.
DamageOptions mixed_damage(double rate, std::uint64_t seed, std::size_t burst_length = 4);

enum class DamageKind : std::uint8_t {
    torn,
    leader_added,
    leader_removed,
    start_late,
    stop_early,
    burst,
    drop,
    flip,
    double_read,
};
inline constexpr std::size_t damage_kind_count = 9;

/// Stable short name: "torn", "leader-added", "leader-removed", "start-late", "stop-early", "burst",
/// "drop", "flip", "double".
std::string_view damage_kind_name(DamageKind kind);

/// One event. Indices count from 0. `original` is the index in the undamaged tape of the first frame
/// concerned (for blank frames added to the leader: of the frame they were added before, 0). `read` is
/// the index in the damaged read of the first frame concerned; for frames missing from the read (torn,
/// leader-removed, start-late, stop-early, drop) it is the index the first of them would have had, i.e.
/// the number of frames read before the gap.
struct DamageEvent {
    DamageKind kind;
    std::size_t original;
    std::size_t read;
    std::size_t frames;  ///< frames concerned: 1 for flip, drop and double (the copy is at read + 1)
    int track = 0;       ///< flip: the track (1..8) whose hole reads the other way; otherwise 0
};

/// Every event in the order applied (see DamageOptions): torn, leader, start-late, stop-early, then
/// the frame-by-frame events in tape order. An amount of 0 logs nothing.
struct DamageLog {
    std::vector<DamageEvent> events;
    std::array<std::size_t, damage_kind_count> counts{};  ///< events of each kind, by DamageKind

    std::size_t count(DamageKind kind) const { return counts[static_cast<std::size_t>(kind)]; }
    void add(const DamageEvent& event);
};

/// Throws Error(Errc::usage) for options no tape can be damaged with: a rate outside 0..1 (or not a
/// number), rates per frame adding up to more than 1, a burst_length of 0 with bursts, tracks outside 1..8.
void check_damage_options(const DamageOptions& options);

/// The tape as a damaged reader reads it; the log, when given, is replaced by what was done. Throws Error(Errc::usage)
/// as check_damage_options does, and for torn frames that do not fit inside the data.
std::vector<Frame> damage(std::span<const Frame> tape, const DamageOptions& options, DamageLog* log = nullptr);

}  // namespace tape
