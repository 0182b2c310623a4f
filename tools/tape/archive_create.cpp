// tape archive create and add: a bag made from reads, scans and photos, and a later read added to one.
#include <filesystem>
#include <optional>
#include <set>

#include "archive_bag.hpp"
#include "cli/machines.hpp"
#include "cli/messages.hpp"
#include "cli/run.hpp"

namespace cli {
namespace {

// Labels the writer sets itself: given with --meta they would be wrong.
bool computed_label(const std::string& label) {
    for (const char* l : {"Payload-Oxum", "Bag-Size", "Bag-Software-Agent", "Tape-Command", "Tape-Restoration"})
        if (label == l) return true;
    return false;
}

std::vector<tape::BagInfoEntry> meta_entries(const std::vector<std::string>& meta) {
    std::vector<tape::BagInfoEntry> out;
    for (const auto& m : meta) {
        std::size_t eq = m.find('=');
        std::string key = m.substr(0, eq);
        bool ok = eq != std::string::npos && eq > 0 && key.find_first_of(":\r\n\t ") == std::string::npos &&
                  m.find_first_of("\r\n") == std::string::npos;
        if (!ok)
            fail("", tape::Errc::usage, "--meta " + m + ": give KEY=VALUE, a KEY of no spaces or ':', on one line");
        if (computed_label(key)) fail("", tape::Errc::usage, "--meta " + key + ": tape archive writes it itself");
        out.push_back({key, m.substr(eq + 1)});
    }
    return out;
}

// Where each input goes in the bag: folder/NAME, NAME the file's own; two of one name are refused.
std::vector<std::string> bag_names(const std::vector<std::string>& paths, const std::string& folder,
                                   std::set<std::string>& taken) {
    std::vector<std::string> out;
    for (const auto& p : paths) {
        std::string name = folder + "/" + std::filesystem::path(p).filename().string();
        if (std::filesystem::path(p).filename().empty() || !taken.insert(name).second)
            fail(p, tape::Errc::usage, "data/" + name + " is already in the bag: give the files distinct names");
        out.push_back(name);
    }
    return out;
}

void copy_in(tape::BagWriter& bag, const std::vector<std::string>& paths, const std::vector<std::string>& names) {
    for (std::size_t i = 0; i < paths.size(); ++i) {
        try {
            bag.add_copy(names[i], paths[i]);
        } catch (const tape::Error& e) {
            fail(paths[i], e);
        }
    }
}

void commit_bag(tape::BagWriter& bag, const std::string& path, const std::vector<tape::BagInfoEntry>& info) {
    try {
        bag.commit(info);
    } catch (const tape::Error& e) {
        fail(path, e);
    }
}

}  // namespace

void archive_create(const ArchiveCreateArgs& a) {
    if (a.reads.empty() && a.scans.empty() && a.from.empty())
        fail(a.bag, tape::Errc::usage, "give at least one --read, --scan or --from");
    std::vector<tape::BagInfoEntry> meta = meta_entries(a.meta);
    std::vector<std::string> device_names = a.from.empty() ? std::vector<std::string>{} : device_read_names(a.times);
    std::set<std::string> taken(device_names.begin(), device_names.end());
    std::vector<std::string> read_names = bag_names(a.reads, "reads", taken);
    std::vector<std::string> scan_names = bag_names(a.scans, "scans", taken);
    std::vector<std::string> photo_names = bag_names(a.photos, "photos", taken);
    std::optional<tape::BagWriter> bag;
    try {
        bag.emplace(a.bag, a.force);
    } catch (const tape::Error& e) {
        fail(a.bag, e);
    }
    std::optional<tape::MachineProfile> machine = machine_or_fail(a.machine);
    if (!a.from.empty()) read_from_device(*bag, a.from, device_names, a.timeout);
    copy_in(*bag, a.reads, read_names);
    copy_in(*bag, a.scans, scan_names);
    copy_in(*bag, a.photos, photo_names);
    if (machine) bag->add(bag_machine_file, machine_profile_text(*machine));
    std::vector<std::string> paths, names = device_names;
    for (const auto& n : device_names) paths.push_back(bag->staging() + "/data/" + n);
    paths.insert(paths.end(), a.reads.begin(), a.reads.end());
    names.insert(names.end(), read_names.begin(), read_names.end());
    paths.insert(paths.end(), a.scans.begin(), a.scans.end());
    names.insert(names.end(), scan_names.begin(), scan_names.end());
    RestorationSummary r = add_restoration(*bag, "", paths, names, machine ? &*machine : nullptr);
    std::vector<tape::BagInfoEntry> info;
    if (!tape::bag_info_value(meta, "External-Identifier"))
        info.push_back({"External-Identifier", std::filesystem::path(a.bag).lexically_normal().filename().string()});
    if (!a.label.empty()) info.push_back({"Tape-Label", a.label});
    if (machine) info.push_back({"Tape-Machine", machine->name + " (data/" + bag_machine_file + ")"});
    info.insert(info.end(), meta.begin(), meta.end());
    info.push_back({"Bag-Software-Agent", std::string("tape ") + TAPE_VERSION});
    info.push_back({"Tape-Command", command_line()});
    info.push_back({"Tape-Restoration", r.words()});
    if (!r.contents.empty()) info.push_back({"Tape-Contents", r.contents});
    commit_bag(*bag, a.bag, info);
    say(a.bag, "bag written: " + r.words());
    if (!r.complete) throw Exit{bad_data};
}

void archive_add(const std::string& path, const std::vector<std::string>& reads,
                 const std::vector<std::string>& scans) {
    if (reads.empty() && scans.empty()) fail(path, tape::Errc::usage, "give at least one --read or --scan");
    std::vector<BagRestoration> before = bag_restorations(path);
    if (before.empty()) fail(path, tape::Errc::bad_image, "holds no restoration (data/restored.ptp.restore.json)");
    std::optional<tape::BagWriter> bag;
    try {
        bag.emplace(tape::BagWriter::update(path));
    } catch (const tape::Error& e) {
        fail(path, e);
    }
    std::set<std::string> taken;
    std::vector<std::string> read_names = bag_names(reads, "reads", taken);
    std::vector<std::string> scan_names = bag_names(scans, "scans", taken);
    std::vector<std::string> paths, names;
    for (const auto& n : before.back().reads) paths.push_back(path + "/data/" + n), names.push_back(n);
    for (const auto& [given, named] : {std::pair{&reads, &read_names}, std::pair{&scans, &scan_names}})
        for (std::size_t i = 0; i < given->size(); ++i) {
            if (bag->has((*named)[i]))
                fail((*given)[i], tape::Errc::usage,
                     "data/" + (*named)[i] + " is already in the bag: give it another name");
            paths.push_back((*given)[i]);
            names.push_back((*named)[i]);
        }
    copy_in(*bag, reads, read_names);
    copy_in(*bag, scans, scan_names);
    std::string suffix = "-" + std::to_string(before.size() + 1);
    std::optional<tape::MachineProfile> machine = bag_machine(path);  // as the bag was made
    RestorationSummary r = add_restoration(*bag, suffix, paths, names, machine ? &*machine : nullptr);
    std::vector<tape::BagInfoEntry> info = bag->previous_info();
    std::erase_if(info, [](const tape::BagInfoEntry& e) { return e.label == "Bagging-Date"; });
    info.push_back({"Tape-Command", command_line()});
    info.push_back({"Tape-Restoration", r.words()});
    commit_bag(*bag, path, info);
    say(path, "read(s) added: " + r.words() + "; the restorations before it are kept");
    if (!r.complete) throw Exit{bad_data};
}

}  // namespace cli
