// tape archive as a user runs it: bags of real reads checked by coreutils and by an independent reader,
// faults named by verify, a run killed at a random point, later reads added, an index.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "bagit_reader.hpp"
#include "process_util.hpp"
#include "test_util.hpp"

namespace {

namespace fs = std::filesystem;

// Two reads of a turning program as a clean reader gives them (the project's own sample): their restoration is
// complete, so a bag of them is made with exit 0.
struct TwoReads {
    TempDir dir;
    std::string r1 = dir.file("part.1"), r2 = dir.file("part.2");
    TwoReads() {
        fs::copy_file(sample_path("16k20f3s5-turning.iso.ptp"), r1);
        fs::copy_file(sample_path("16k20f3s5-turning.iso.ptp"), r2);
    }
};

int sh(const std::string& command) { return std::system(("sh -c '" + command + "' >/dev/null 2>&1").c_str()); }

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

TEST(ArchiveCli, CreateMakesABagCoreutilsAndAnIndependentReaderAccept) {
    TwoReads t;
    std::string bag = t.dir.file("PART");
    Outcome r = tape_run({"archive", "create", bag, "--read", t.r1, "--read", t.r2, "--label", "PART 1", "--meta",
                          "Source-Organization=Test shop", "--photo", sample_path("README.md")},
                         t.dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("complete"), std::string::npos) << r.err;
    for (const char* f :
         {"data/reads/part.1", "data/reads/part.2", "data/photos/README.md", "data/restored.ptp",
          "data/restored.ptp.restore.json", "data/restored.html", "data/contents/text.txt", "data/format.txt",
          "data/tape.svg", "manifest-sha256.txt", "manifest-sha512.txt", "tagmanifest-sha256.txt"})
        EXPECT_TRUE(fs::exists(bag + "/" + f)) << f;
    EXPECT_EQ(read_text(bag + "/data/reads/part.1"), read_text(t.r1));  // as it came
    EXPECT_EQ(read_text(bag + "/data/contents/text.txt"), read_text(sample_path("16k20f3s5-turning.txt")));
    EXPECT_EQ(sh("cd " + bag + " && sha256sum -c --strict manifest-sha256.txt"), 0);
    EXPECT_EQ(sh("cd " + bag + " && sha512sum -c --strict manifest-sha512.txt"), 0);
    EXPECT_EQ(sh("cd " + bag + " && sha256sum -c --strict tagmanifest-sha256.txt"), 0);
    bagit_reader::Bag b = bagit_reader::read(bag);
    EXPECT_TRUE(b.errors.empty()) << ::testing::PrintToString(b.errors);
    EXPECT_EQ(b.info["Source-Organization"], "Test shop");
    EXPECT_EQ(b.info["Tape-Label"], "PART 1");
    EXPECT_EQ(b.info["External-Identifier"], "PART");
    EXPECT_EQ(b.info["Bag-Software-Agent"].rfind("tape ", 0), 0u);
    EXPECT_NE(b.info["Tape-Command"].find("archive create " + bag + " --read " + t.r1), std::string::npos);
    EXPECT_NE(read_text(bag + "/data/format.txt").find("ISO"), std::string::npos);
    r = tape_run({"archive", "verify", bag}, t.dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("restoring the reads again gives the same image"), std::string::npos) << r.err;
    r = tape_run({"archive", "create", bag, "--read", t.r1}, t.dir);
    EXPECT_EQ(r.status, 2) << "an existing bag replaced without --force: " << r.err;
}

struct Fault {
    const char* name;
    void (*make)(const std::string& bag);
    std::vector<std::string> said;  // in verify's messages
};

TEST(ArchiveCli, VerifyNamesEachFault) {
    std::vector<Fault> faults = {
        {"flipped byte",
         [](const std::string& bag) {
             std::string s = read_text(bag + "/data/reads/part.2");
             s[200] ^= 0x10;
             write(bag + "/data/reads/part.2", s);
         },
         {"data/reads/part.2: checksum-mismatch"}},
        {"file added",
         [](const std::string& bag) { write(bag + "/data/reads/part.3", "x"); },
         {"data/reads/part.3: file-unlisted", "oxum-mismatch"}},
        {"file removed",
         [](const std::string& bag) { fs::remove(bag + "/data/format.txt"); },
         {"data/format.txt: file-missing", "oxum-mismatch"}},
        {"truncated manifest",
         [](const std::string& bag) {
             std::string m = read_text(bag + "/manifest-sha256.txt");
             write(bag + "/manifest-sha256.txt", m.substr(0, m.size() - 30));
         },
         {"manifest-sha256.txt: line", "bad-manifest-line", "file-unlisted",
          "manifest-sha256.txt: tag-checksum-mismatch"}},
        {"restored image not what the reads give",
         [](const std::string& bag) {
             // Both manifests made to agree with a changed image: only restoring again can tell.
             std::string s = read_text(bag + "/data/restored.ptp");
             s[300] ^= 0x01;
             write(bag + "/data/restored.ptp", s);
             std::system(("cd " + bag + " && sha256sum data/*.* data/*/* > manifest-sha256.txt && sha512sum data/*.* " +
                          "data/*/* > manifest-sha512.txt && rm tagmanifest-sha256.txt")
                             .c_str());
         },
         {"data/restored.ptp: restored-again"}},
    };
    TwoReads t;
    for (const auto& f : faults) {
        std::string bag = t.dir.file("bag");
        fs::remove_all(bag);
        ASSERT_EQ(tape_run({"archive", "create", bag, "--read", t.r1, "--read", t.r2}, t.dir).status, 0);
        f.make(bag);
        Outcome r = tape_run({"archive", "verify", bag}, t.dir);
        EXPECT_EQ(r.status, 1) << f.name << ": " << r.err;
        for (const auto& s : f.said)
            EXPECT_NE(r.err.find(s), std::string::npos) << f.name << ": " << s << " in\n" << r.err;
    }
}

TEST(ArchiveCli, CrLfTagFilesVerify) {
    TwoReads t;
    std::string bag = t.dir.file("bag");
    ASSERT_EQ(tape_run({"archive", "create", bag, "--read", t.r1, "--read", t.r2}, t.dir).status, 0);
    for (const char* name : {"bagit.txt", "bag-info.txt", "manifest-sha256.txt", "manifest-sha512.txt"}) {
        std::string s = read_text(bag + "/" + name), crlf;
        for (char c : s) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
        write(bag + "/" + name, crlf);
    }
    ASSERT_EQ(sh("cd " + bag +
                 " && sha256sum bagit.txt bag-info.txt manifest-sha256.txt manifest-sha512.txt > "
                 "tagmanifest-sha256.txt"),
              0);
    Outcome r = tape_run({"archive", "verify", bag}, t.dir);
    EXPECT_EQ(r.status, 0) << r.err;
}

// A run killed anywhere leaves no bag or a whole one: never a half bag under the name.
TEST(ArchiveCli, KilledRunLeavesNoBagOrACompleteOne) {
    TwoReads t;
    // A longer tape, so that the run lasts long enough to be killed inside.
    std::string one = read_text(t.r1), big;
    for (int i = 0; i < 40; ++i) big += one;
    write(t.r1, big);
    write(t.r2, big);
    auto start = std::chrono::steady_clock::now();
    ASSERT_EQ(tape_run({"archive", "create", t.dir.file("timed"), "--read", t.r1, "--read", t.r2}, t.dir).status, 0);
    auto took = std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start);
    std::mt19937 random(std::random_device{}());
    int whole = 0, none = 0;
    for (int i = 0; i < 6; ++i) {
        std::string bag = t.dir.file("bag" + std::to_string(i));
        auto at = std::chrono::microseconds(std::uniform_int_distribution<long>(0, took.count())(random));
        {
            Process p({"archive", "create", bag, "--read", t.r1, "--read", t.r2}, t.dir);
            std::this_thread::sleep_for(at);
            p.signal(SIGKILL);
            p.wait();
        }
        if (!fs::exists(bag)) {
            ++none;
            continue;
        }
        ++whole;
        EXPECT_TRUE(bagit_reader::read(bag).errors.empty()) << "killed after " << at.count() << " us";
        EXPECT_EQ(tape_run({"archive", "verify", bag, "--fast"}, t.dir).status, 0);
    }
    EXPECT_EQ(whole + none, 6);
}

TEST(ArchiveCli, AddKeepsTheFirstRestorationAndRecordsBoth) {
    TwoReads t;
    std::string bag = t.dir.file("bag");
    ASSERT_EQ(tape_run({"archive", "create", bag, "--read", t.r1}, t.dir).status, 0);
    std::string first = read_text(bag + "/data/restored.ptp");
    std::string r3 = t.dir.file("part.3");
    fs::copy_file(t.r1, r3);
    Outcome r = tape_run({"archive", "add", bag, "--read", r3}, t.dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(read_text(bag + "/data/restored.ptp"), first);
    EXPECT_TRUE(fs::exists(bag + "/data/restored-2.ptp"));
    EXPECT_NE(read_text(bag + "/data/restored-2.ptp.restore.json").find("reads/part.3"), std::string::npos);
    EXPECT_NE(read_text(bag + "/bag-info.txt").find("Tape-Restoration: restored-2.ptp from 2 read(s)"),
              std::string::npos);
    r = tape_run({"archive", "add", bag, "--read", r3}, t.dir);
    EXPECT_EQ(r.status, 2) << "a read of a name the bag has was not refused: " << r.err;
    r = tape_run({"archive", "verify", bag}, t.dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("the same images (2)"), std::string::npos) << r.err;
}

// --machine: the reads are restored with the profile, which the bag keeps, so that add and verify restore
// with the same one.
TEST(ArchiveCli, TheMachinesProfileIsKeptAndUsedAgain) {
    TwoReads t;
    std::string bag = t.dir.file("bag");
    Outcome r = tape_run({"archive", "create", bag, "--read", t.r1, "--machine", "16k20f3s5"}, t.dir);
    ASSERT_EQ(r.status, 0) << r.err;
    std::string kept = read_text(bag + "/data/machine.toml");
    EXPECT_NE(kept.find("Н22-1М"), std::string::npos) << "not the 16К20Ф3С5's profile: " << kept.substr(0, 200);
    EXPECT_NE(read_text(bag + "/bag-info.txt").find("Tape-Machine: 16k20f3s5 (data/machine.toml)"), std::string::npos);
    EXPECT_EQ(sh("cd " + bag + " && sha256sum -c --strict manifest-sha256.txt"), 0);
    ASSERT_EQ(tape_run({"archive", "add", bag, "--read", t.r2}, t.dir).status, 0);
    r = tape_run({"archive", "verify", bag}, t.dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("the same images (2)"), std::string::npos) << r.err;
    // A profile that does not read leaves no bag.
    r = tape_run({"archive", "create", t.dir.file("none"), "--read", t.r1, "--machine", "no-such-machine"}, t.dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_FALSE(fs::exists(t.dir.file("none")));
}

TEST(ArchiveCli, IndexListsEveryBag) {
    TwoReads t;
    fs::create_directory(t.dir.file("bags"));
    ASSERT_EQ(tape_run({"archive", "create", t.dir.file("bags/A-1"), "--read", t.r1, "--label", "FIRST"}, t.dir).status,
              0);
    ASSERT_EQ(
        tape_run({"archive", "create", t.dir.file("bags/B-2"), "--read", t.r2, "--label", "SECOND"}, t.dir).status, 0);
    Outcome r = tape_run({"archive", "index", t.dir.file("bags")}, t.dir);
    ASSERT_EQ(r.status, 0) << r.err;
    std::string page = read_text(t.dir.file("bags/index.html"));
    for (const char* s : {"FIRST", "SECOND", "href=\"A-1/data/restored.html\"", "<svg"})
        EXPECT_NE(page.find(s), std::string::npos) << s;
    EXPECT_EQ(page.find("src=\"http"), std::string::npos) << "the page fetches nothing";
    EXPECT_EQ(page.find("href=\"http"), std::string::npos) << "the page links nowhere outside";
    EXPECT_EQ(tape_run({"archive", "index", t.dir.file("bags")}, t.dir).status, 2);
}

// The report a person reads first: the places in doubt first, each whole and linked to the tape drawn, the
// restored ones after, folded; one legend.
TEST(ArchiveCli, ReportPutsThePlacesToCheckFirst) {
    TempDir dir;
    std::vector<std::string> args = {"archive", "create", dir.file("bag")};
    for (const char* seed : {"11", "12"}) {
        std::string read = dir.file(std::string("r") + seed + ".ptp");
        ASSERT_EQ(
            run(TAPE_DAMAGE_BINARY,
                {sample_path("gost-20999-format-example.iso.ptp"), "-o", read, "--seed", seed, "--damage", "0.02"}, dir)
                .status,
            0);
        args.insert(args.end(), {"--read", read});
    }
    Outcome r = tape_run(args, dir);
    ASSERT_EQ(r.status, 1) << "two damaged reads leave frames in doubt: " << r.err;
    std::string page = read_text(dir.file("bag/data/restored.html"));
    std::string json = read_text(dir.file("bag/data/restored.ptp.restore.json"));
    std::size_t in_doubt = 0;
    for (auto at = json.find("\"in_doubt\":true"); at != std::string::npos; at = json.find("\"in_doubt\":true", at + 1))
        ++in_doubt;
    ASSERT_GT(in_doubt, 0u);
    EXPECT_NE(page.find("Places to check: " + std::to_string(in_doubt) + "<"), std::string::npos);
    std::size_t first_place = page.find("<section class=\"place doubtful\""), folded = page.find("<details>");
    ASSERT_NE(first_place, std::string::npos);
    ASSERT_NE(folded, std::string::npos);
    EXPECT_LT(first_place, folded);
    std::string place = page.substr(first_place, page.find("</section>", first_place) - first_place);
    for (const char* s : {"Left open because", "In the program line", "<td>1</td>", "<td>2</td>", "written",
                          "href=\"tape.svg#f", "<svg"})
        EXPECT_NE(place.find(s), std::string::npos) << s << " in\n" << place;
    std::size_t legends = 0;
    for (auto at = page.find("class=\"legend\""); at != std::string::npos; at = page.find("class=\"legend\"", at + 1))
        ++legends;
    EXPECT_EQ(legends, 1u);
    // And back: the whole tape's doubtful frames link to their place in the page.
    EXPECT_NE(read_text(dir.file("bag/data/tape.svg")).find("href=\"restored.html#p"), std::string::npos);
}

// Only tape archive pays for nettle: no other command loads it.
TEST(ArchiveCli, OnlyArchiveLoadsNettle) {
    TwoReads t;
    ::setenv("LD_DEBUG", "files", 1);
    Outcome version = tape_run({"--version"}, t.dir);
    Outcome archive = tape_run({"archive", "create", t.dir.file("bag"), "--read", t.r1}, t.dir);
    ::unsetenv("LD_DEBUG");
    EXPECT_EQ(version.err.find("nettle"), std::string::npos);
    EXPECT_NE(archive.err.find("libnettle.so.8"), std::string::npos) << archive.err.substr(0, 2000);
}

// Real reads from other archives: the Elliott 900 two-read sets, PDP-8 and PDP-11 loader tapes.
TEST(ArchiveCli, RealReadsArchiveAndVerify) {
    SKIP_WITHOUT_SHARED_DATA("outside2/tapes");
    TempDir dir;
    std::string tapes = shared_data("outside2/tapes");
    std::vector<std::vector<std::string>> sets;
    for (const auto& e : fs::directory_iterator(tapes + "/elliott900")) {
        std::string p = e.path().string();
        if (p.ends_with(".1") && fs::exists(p.substr(0, p.size() - 2) + ".2"))
            sets.push_back({p, p.substr(0, p.size() - 2) + ".2"});
    }
    for (const char* family : {"pdp8", "pdp11"})
        for (const auto& e : fs::directory_iterator(tapes + "/" + family)) sets.push_back({e.path().string()});
    ASSERT_GE(sets.size(), 10u);
    int loaders = 0;
    for (const auto& set : sets) {
        std::string bag = dir.file(fs::path(set[0]).filename().string() + ".bag");
        std::vector<std::string> args = {"archive", "create", bag};
        for (const auto& r : set) args.insert(args.end(), {"--read", r});
        Outcome r = tape_run(args, dir);
        // Not every restoration is complete (a single read of a binary tape checks nothing): exit 1 then, and
        // the bag is written all the same.
        ASSERT_TRUE(r.status == 0 || r.status == 1) << set[0] << ": " << r.err;
        ASSERT_NE(r.err.find("bag written"), std::string::npos) << r.err;
        EXPECT_TRUE(bagit_reader::read(bag).errors.empty()) << set[0];
        loaders += fs::exists(bag + "/data/contents/memory.txt");
        Outcome v = tape_run({"archive", "verify", bag}, dir);
        EXPECT_EQ(v.status, 0) << set[0] << ": " << v.err;
    }
    EXPECT_GE(loaders, 4) << "the PDP-8 and PDP-11 loader tapes' memory images";
}

TEST(ArchiveCli, ScansAsPhotosAndAsAScanRead) {
    SKIP_WITHOUT_SHARED_DATA("scans/patinho_feio_fita_absoluta_scan03.png");
    TempDir dir;
    std::string scans = shared_data("scans");
    std::string bag = dir.file("bag");
    Outcome r =
        tape_run({"archive", "create", bag, "--scan", scans + "/patinho_feio_fita_absoluta_scan03.png", "--photo",
                  scans + "/gav_reader_topview_partial.jpg", "--photo", scans + "/djr_coiled_tape_unknown.png"},
                 dir);
    if (r.err.find("built without OpenCV") != std::string::npos) GTEST_SKIP() << "built without OpenCV: " << r.err;
    ASSERT_TRUE(r.status == 0 || r.status == 1) << r.err;
    EXPECT_TRUE(fs::exists(bag + "/data/scans/patinho_feio_fita_absoluta_scan03.png"));
    EXPECT_EQ(read_text(bag + "/data/photos/djr_coiled_tape_unknown.png"),
              read_text(scans + "/djr_coiled_tape_unknown.png"));
    EXPECT_TRUE(bagit_reader::read(bag).errors.empty());
    Outcome v = tape_run({"archive", "verify", bag}, dir);
    EXPECT_EQ(v.status, 0) << v.err;
}

}  // namespace
