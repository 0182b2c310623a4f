// A tape archived as a BagIt bag (RFC 8493, BagIt 1.0): a folder with bagit.txt, the payload under data/,
// bag-info.txt, a payload manifest per checksum algorithm (manifest-sha256.txt, manifest-sha512.txt) and a
// tag manifest (tagmanifest-sha256.txt). A bag is made in a folder beside its target and renamed into place
// only when complete, so that an interrupted run leaves either no bag or a whole one; a bag is verified
// against every manifest it has, file by file.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tape {

/// The SHA-256 and SHA-512 of some bytes, in lower-case hex, and how many bytes they were.
struct Digests {
    std::string sha256, sha512;
    std::uint64_t bytes = 0;
};
/// Digests of bytes in memory. The checksums are nettle's (libnettle.so.8), loaded on first use so that
/// no other command pays for it; throws Error(Errc::io) when it cannot be loaded.
Digests digest_bytes(std::span<const std::uint8_t> bytes);
/// Digests of a file, read once a megabyte at a time. Throws Error(Errc::io) naming path.
Digests digest_file(const std::string& path);

/// A file path as a manifest writes it (RFC 8493 §2.1.3): '%' as %25, CR as %0D, LF as %0A, else as is.
std::string bag_encoded_path(std::string_view path);
/// The path a manifest line names: %25, %0D and %0A decoded (in either case), anything else kept as is.
std::string bag_decoded_path(std::string_view encoded);
/// The lines of a tag file, each ended by LF, CR or CR LF (all three are valid); the last may be unended.
std::vector<std::string_view> tag_file_lines(std::string_view text);

/// A line of bag-info.txt: "Label: value" (a value continued over lines is joined with a space).
struct BagInfoEntry {
    std::string label, value;
};
/// The entries of bag-info.txt's text in order; a line that is no "Label: value" and no continuation is
/// named in bad_lines (1-based) when given.
std::vector<BagInfoEntry> parse_bag_info(std::string_view text, std::vector<std::uint64_t>* bad_lines = nullptr);
/// The value of the first entry with label (compared ignoring case), or nullopt.
std::optional<std::string> bag_info_value(const std::vector<BagInfoEntry>& info, std::string_view label);
/// "OCTETS.COUNT": the Payload-Oxum of payload files.
std::string payload_oxum(std::uint64_t octets, std::uint64_t files);

/// Makes a bag. The payload is written into a staging folder beside target (".NAME.partial-XXXXXX", on the
/// same file system), and commit() writes the tag files and renames it into place. A writer destroyed
/// without commit() (an error, an exception) removes its staging folder; a killed process leaves it, never
/// a bag under target.
class BagWriter {
public:
    /// A new bag at target. Throws Error(Errc::exists) when target exists and replace is false,
    /// Error(Errc::io) when the staging folder cannot be made.
    BagWriter(std::string target, bool replace);
    /// The bag at target again, with more payload: its payload and tag files (other than bagit.txt, bag-info.txt and
    /// the manifests, which commit() writes anew) are linked (or copied) into the staging folder, never changed.
    /// Throws Error(Errc::io) when target is no bag (no bagit.txt) or cannot be read.
    static BagWriter update(const std::string& target);
    ~BagWriter();
    BagWriter(BagWriter&&) noexcept;
    BagWriter& operator=(BagWriter&&) = delete;

    /// Adds a payload file at data/path (path relative, '/'-separated, no "." or ".." parts) with bytes.
    /// Throws Error(Errc::usage) for such a path or one that is already in the bag, Error(Errc::io) on failure.
    void add(std::string_view path, std::string_view bytes);
    /// Adds a payload file at data/path with the bytes of the file source, copied as they are.
    void add_copy(std::string_view path, const std::string& source);
    /// True when data/path is already in the bag.
    bool has(std::string_view path) const;
    /// The bag-info.txt of the bag update() opened (empty for a new bag).
    const std::vector<BagInfoEntry>& previous_info() const;
    /// Writes bagit.txt, the manifests (every payload file's SHA-256 and SHA-512), bag-info.txt (info in order,
    /// then Payload-Oxum and Bag-Size, replacing any given) and tagmanifest-sha256.txt; flushes everything to disk
    /// and puts the bag in place: renamed to target, or exchanged with the bag there (replace, update) and the old
    /// one removed. Throws Error(Errc::exists) when target appeared meanwhile and replace is false.
    void commit(const std::vector<BagInfoEntry>& info);
    /// The staging folder (for tests).
    const std::string& staging() const;

private:
    struct State;
    explicit BagWriter(std::unique_ptr<State> state);
    std::unique_ptr<State> state_;
};

/// One way a bag fails to be valid and complete (RFC 8493 §3), or a note about it.
struct BagProblem {
    /// Stable ids: "no-bagit-txt", "bad-bagit-txt", "no-manifest", "bad-manifest-line", "checksum-mismatch",
    /// "file-missing", "file-unlisted", "bad-path", "oxum-mismatch", "bad-oxum", "bad-bag-info-line",
    /// "tag-checksum-mismatch", "tag-file-missing", and (a note, not a failure) "unchecked-algorithm".
    std::string id;
    std::string file;        ///< the file it concerns, relative to the bag ("data/reads/r1.ptp", "manifest-sha256.txt")
    std::uint64_t line = 0;  ///< in that file, 1-based; 0 when not about a line
    std::string message;
    bool note = false;  ///< true: said, but the bag is valid
};

/// What verify_bag found.
struct BagCheck {
    std::vector<BagProblem> problems;     ///< in the order found: tag files, then each manifest, then data/
    std::vector<BagInfoEntry> info;       ///< bag-info.txt
    std::vector<std::string> algorithms;  ///< of the payload manifests checked ("sha256", "sha512")
    std::uint64_t files = 0, octets = 0;  ///< payload files found under data/ and their bytes
    /// True when nothing but notes was found.
    bool valid() const;
};
/// Checks the bag at path: bagit.txt; every payload manifest (sha256 and sha512; others are noted as not
/// checked), each line's file present and its checksum right; every file under data/ listed in every payload
/// manifest; Payload-Oxum against the payload; every tag manifest's files. Never throws for a bad bag (every
/// fault is a problem); throws Error(Errc::io) only when path is no folder.
BagCheck verify_bag(const std::string& path);

}  // namespace tape
