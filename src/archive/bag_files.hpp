// What the bag writer and the verifier share: the payload files of a bag folder, and the tag files'
// names.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace tape::bag {

/// Every regular file under folder/data, as "data/..." ('/'-separated), sorted. A symbolic link or anything
/// else that is no regular file or folder is listed in others (it cannot be a payload file).
std::vector<std::string> payload_files(const std::filesystem::path& folder, std::vector<std::string>* others = nullptr);

/// The algorithm of a manifest's name: "sha256" for "manifest-sha256.txt" with prefix "manifest-"; empty for
/// another name.
std::string manifest_algorithm(std::string_view name, std::string_view prefix);

/// The tag files the writer makes anew each time (bagit.txt, bag-info.txt, every manifest and tag manifest).
bool written_tag_file(std::string_view name);

/// Writes data to path and flushes it to disk; throws Error(Errc::io).
void write_synced(const std::filesystem::path& path, std::string_view data);

}  // namespace tape::bag
