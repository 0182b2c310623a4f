// tape archive's steps (cmd_archive.cpp wires them): a bag made from reads (archive_create.cpp), a later
// read added, a bag verified (archive_verify.cpp), a folder of bags indexed (archive_index.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tape/archive.hpp"
#include "tape/machine.hpp"

namespace cli {

struct ArchiveCreateArgs {
    std::string bag, label, machine;
    std::vector<std::string> reads, scans, photos, meta;
    std::string from;    ///< an adapter the tape is read from, times times, before the reads given
    unsigned times = 2;  ///< --times
    double timeout = 5;  ///< --timeout: a read from the adapter ends after this many seconds without a frame
    bool force = false;
};
/// Writes the bag; ends the program (exit 1) when the restoration is not complete, after writing it.
void archive_create(const ArchiveCreateArgs& a);

/// Where --from's reads go under data/: reads/read-1.ptp ... reads/read-TIMES.ptp.
std::vector<std::string> device_read_names(unsigned times);
/// Reads the tape from device (an adapter) once for each of names, into the bag's staging folder as it
/// comes: forwards, then backwards to the tape's start (turned to the tape's order), and so on in turn, as
/// tape read reads. A device failure, a read backwards that does not reach the tape's start or Ctrl-C ends
/// the program, and no bag is made.
void read_from_device(tape::BagWriter& bag, const std::string& device, const std::vector<std::string>& names,
                      double timeout_s);

/// Adds later reads (tape images) and scans to a bag and restores all its reads again as restored-N.ptp
/// beside the restorations it has; the bag is replaced whole.
void archive_add(const std::string& bag, const std::vector<std::string>& reads, const std::vector<std::string>& scans);

/// Checks the bag; with fast, the checksums only, else also that restoring its reads again gives each
/// restored image it holds. Every difference is said; exit 1 when there is one.
void archive_verify(const std::string& bag, bool fast);

/// One offline HTML page (output; "": DIR/index.html) of the bags in dir.
void archive_index(const std::string& dir, const std::string& output, bool force);

/// What one restoration put in a bag, for bag-info.txt.
struct RestorationSummary {
    std::string image;     ///< "restored.ptp", "restored-2.ptp"
    std::string code;      ///< "ISO with even parity", "none"
    std::string contents;  ///< the contents in words (archive_contents.hpp)
    std::size_t reads = 0;
    std::uint64_t frames = 0, in_doubt = 0;
    bool complete = false;
    bool unchecked = false;    ///< one read of a tape in no code: nothing could be checked
    bool code_misfit = false;  ///< most frames fail the code the reads were restored in
    /// "restored.ptp from 2 reads: 1454 frames, complete" or "..., 79 in doubt".
    std::string words() const;
};

/// Restores the reads at paths (named in the bag by names, relative to data/) and adds the restoration's
/// files to the bag, each name with suffix ("" or "-2"): restoredS.ptp, its report restoredS.ptp.restore.json
/// and restoredS.html, contentsS/, formatS.txt, tapeS.svg.
/// machine: the profile the reads are restored with (--machine), or nullptr.
RestorationSummary add_restoration(tape::BagWriter& bag, const std::string& suffix,
                                   const std::vector<std::string>& paths, const std::vector<std::string>& names,
                                   const tape::MachineProfile* machine);

/// Where a bag keeps the machine profile its reads were restored with: a copy, so that restoring them
/// again years later does not depend on the profile tape then bundles.
inline constexpr const char* bag_machine_file = "machine.toml";
/// The profile of a bag (data/machine.toml), or nullopt when it was made without --machine.
std::optional<tape::MachineProfile> bag_machine(const std::string& bag);
/// The text of the profile --machine names (bundled, a user's own or a path), to keep in a bag.
std::string machine_profile_text(const tape::MachineProfile& profile);

/// The restorations a bag holds, from its payload: ("restored.ptp", reads named relative to data/), in order.
struct BagRestoration {
    std::string image;
    std::vector<std::string> reads;
};
std::vector<BagRestoration> bag_restorations(const std::string& bag);

/// This run's command line, quoted for a shell where needed: "tape archive create ...".
std::string command_line();

}  // namespace cli
