// tape archive: a tape kept as a BagIt bag (RFC 8493) an archivist can hand on — every read as it came,
// scans and photos, the restored image with its report, what it holds, checksums — and verified years
// later. The steps are in archive_*.cpp; this file holds the options.
#include "archive_bag.hpp"
#include "cli/machines.hpp"
#include "cli/numbers.hpp"
#include "commands.hpp"
#include "device_options.hpp"

namespace cli {

namespace {

void add_archive_create(CLI::App* archive) {
    auto a = std::make_shared<ArchiveCreateArgs>();
    auto* sub = archive->add_subcommand(
        "create",
        "Pack reads of one tape, its scans and photos as a bag, with the restored image, its report, what it "
        "holds and checksums");
    sub->add_option("bag", a->bag, "The bag's folder, made whole or not at all")->required();
    sub->add_option("--read,-r", a->reads, "A read of the tape (a tape image), kept as it came in data/reads/");
    sub->add_option("--scan", a->scans,
                    "A picture of the tape read as tape scan does, kept in data/scans/ and restored with the reads");
    sub->add_option("--from", a->from,
                    "An adapter to read the tape from (adapter:PATH or usb:...): --times reads, forwards and "
                    "backwards in turn, each kept as it came in data/reads/read-N.ptp");
    sub->add_option("--times", a->times, "How many times --from reads the tape")
        ->check(whole_number(1, 99))
        ->capture_default_str();
    sub->add_option("--timeout", a->timeout, "A read from --from ends after SECONDS without a frame (0: never)")
        ->check(real_number(0, max_timeout_s))
        ->capture_default_str();
    sub->add_option("--photo", a->photos, "A photo of the tape, its box or its label, kept in data/photos/");
    sub->add_option("--label", a->label, "The tape's label as written on it (bag-info.txt Tape-Label)");
    sub->add_option("--meta", a->meta,
                    "KEY=VALUE for bag-info.txt (Source-Organization=..., External-Identifier=..., Contact-Name=...)");
    add_machine_option(sub, a->machine,
                       "the reads are restored with its word formats and code tables; the profile is kept in "
                       "the bag (data/machine.toml), so that add and verify restore as create did");
    sub->add_flag("--force", a->force, "Replace an existing bag (the new one takes its place whole)");
    sub->callback([a] { archive_create(*a); });
}

void add_archive_add(CLI::App* archive) {
    struct Args {
        std::string bag;
        std::vector<std::string> reads, scans;
    };
    auto a = std::make_shared<Args>();
    auto* sub = archive->add_subcommand(
        "add", "Add a later read to a bag and restore again: the new restoration is kept beside the ones before");
    sub->add_option("bag", a->bag, "The bag")->required();
    sub->add_option("--read,-r", a->reads, "A later read of the tape (a tape image)");
    sub->add_option("--scan", a->scans, "A later picture of the tape");
    sub->callback([a] { archive_add(a->bag, a->reads, a->scans); });
}

void add_archive_verify(CLI::App* archive) {
    struct Args {
        std::string bag;
        bool fast = false;
    };
    auto a = std::make_shared<Args>();
    auto* sub = archive->add_subcommand(
        "verify",
        "Check a bag: every file against every manifest, Payload-Oxum, no file unlisted or missing, and "
        "restoring the reads again gives the image held (exit 1 with each difference named)");
    sub->add_option("bag", a->bag, "The bag")->required();
    sub->add_flag("--fast", a->fast, "The checksums only: do not restore the reads again");
    sub->callback([a] { archive_verify(a->bag, a->fast); });
}

void add_archive_index(CLI::App* archive) {
    struct Args {
        std::string dir, output;
        bool force = false;
    };
    auto a = std::make_shared<Args>();
    auto* sub = archive->add_subcommand(
        "index", "One HTML page of a folder of bags: label, identifier, contents, restorations, the tape's start");
    sub->add_option("dir", a->dir, "The folder holding the bags")->required();
    sub->add_option("-o,--output", a->output, "The page (default: DIR/index.html)");
    sub->add_flag("--force", a->force, "Replace an existing page");
    sub->callback([a] { archive_index(a->dir, a->output, a->force); });
}

}  // namespace

void add_archive(CLI::App& app) {
    auto* archive = app.add_subcommand(
        "archive",
        "Keep a tape as a BagIt bag (RFC 8493): reads, scans, photos, the restored image and its report, "
        "contents, checksums; verify it, add later reads, index a folder of bags");
    archive->require_subcommand(1);
    add_archive_create(archive);
    add_archive_add(archive);
    add_archive_verify(archive);
    add_archive_index(archive);
}

}  // namespace cli
