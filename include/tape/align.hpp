// Several reads of one physical tape aligned frame by frame. Tape frames carry no address, and a
// reader slips: it drops a frame, reads one twice, garbles a stain or a splice, starts late or stops
// early, and the leaders differ. So reads are aligned as sequences, not by offset: unique runs of
// frames they share anchor them to one reference read (the longest), the stretches between the
// anchors are aligned by dynamic programming, and every read's frames are placed in shared columns.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "tape/error.hpp"
#include "tape/frame.hpp"
#include "tape/limits.hpp"

namespace tape {

struct AlignOptions {
    std::size_t anchor_length = 12;  ///< frames in an anchor: a run that occurs once in each read
    /// A stretch between anchors larger than this many cells (frames x frames) is not aligned inside:
    /// its frames stand in columns of their own. Bounds time and memory on reads that disagree long.
    std::size_t max_cells = 4 << 20;
    /// Reads of which fewer than this fraction of the runs that occur once in each anchor in order
    /// are refused as reads of another tape.
    double min_shared = 0.5;
    /// Reads of another tape are left out (ReadAlignment::related is false for them, and they have no
    /// frame in any column) instead of refused.
    bool drop_unrelated = false;
};

/// Thrown by align_reads for a read that shares too little with the reference to be of the same tape.
class UnrelatedRead : public Error {
public:
    UnrelatedRead(std::size_t read, std::size_t reference, double anchored);
    std::size_t read() const { return read_; }            ///< from 0
    std::size_t reference() const { return reference_; }  ///< from 0
    /// The share of the runs that occur as often in each read that anchored them to each other.
    double anchored() const { return anchored_; }

private:
    std::size_t read_, reference_;
    double anchored_;
};

/// The reads in shared columns: column c holds, for every read, the index of its frame there, or
/// none where that read has no frame (it dropped one the others read, or read one twice).
class ReadAlignment {
public:
    static constexpr std::int32_t none = -1;

    ReadAlignment(std::size_t reads, std::size_t reference) : reads_(reads), reference_(reference) {}

    std::size_t reads() const { return reads_; }
    std::size_t columns() const { return reads_ ? cells_.size() / reads_ : 0; }
    /// The read the others were aligned to.
    std::size_t reference() const { return reference_; }
    /// The index of read's frame in column, or none.
    std::int32_t frame(std::size_t column, std::size_t read) const { return cells_[column * reads_ + read]; }
    /// The first and one past the last column where read has a frame: outside, it did not read the tape
    /// (it started late or stopped early); inside, a none is a frame it lost.
    std::size_t first_column(std::size_t read) const { return first_[read]; }
    std::size_t end_column(std::size_t read) const { return end_[read]; }
    /// True when read covers column (between its first and last frame).
    bool covers(std::size_t read, std::size_t column) const { return column >= first_[read] && column < end_[read]; }
    /// The fraction of each read's frames matched exactly with the reference's (1 for the reference).
    double shared(std::size_t read) const { return shared_[read]; }
    /// False for a read left out as a read of another tape (AlignOptions::drop_unrelated).
    bool related(std::size_t read) const { return related_[read]; }

    /// For align_reads: appends one column (reads() entries).
    void add_column(std::span<const std::int32_t> column);
    /// For align_reads: room for this many columns.
    void reserve(std::size_t columns) { cells_.reserve(columns * reads_); }
    void set_shared(std::size_t read, double fraction) { shared_.at(read) = fraction; }
    void set_related(std::size_t read, bool related) { related_.at(read) = related; }
    /// Shared and related, as another alignment of the same reads has them.
    void take_read_facts(const ReadAlignment& a) { shared_ = a.shared_, related_ = a.related_; }
    /// Computes first_column/end_column once the columns are in.
    void finish();

private:
    std::size_t reads_, reference_;
    std::vector<std::int32_t> cells_;
    std::vector<std::size_t> first_, end_;
    std::vector<double> shared_ = std::vector<double>(reads_, 1.0);
    std::vector<bool> related_ = std::vector<bool>(reads_, true);
};

/// The frame `read` has in column, or nullopt (reads: those the alignment was made of).
inline std::optional<Frame> frame_at(const ReadAlignment& a, std::span<const std::span<const Frame>> reads,
                                     std::size_t column, std::size_t read) {
    std::int32_t i = a.frame(column, read);
    if (i == ReadAlignment::none) return std::nullopt;
    return reads[read][static_cast<std::size_t>(i)];
}

/// True when every read that covers column has a frame there, and they are all the same.
bool unanimous(const ReadAlignment& a, std::span<const std::span<const Frame>> reads, std::size_t column);

/// Aligns reads (each a whole image's frames, at most max_tape_frames). Throws UnrelatedRead (an
/// Error(Errc::bad_image)) naming the read when one shares too little with the reference to be of the
/// same tape (unless options.drop_unrelated), Error(Errc::bad_image) when no read has frames, and
/// Error(Errc::usage) for a read longer than max_tape_frames. One read alone is its own alignment.
ReadAlignment align_reads(std::span<const std::span<const Frame>> reads, const AlignOptions& options = {});

}  // namespace tape
