// tape archive as a user runs it: bags of real reads checked by coreutils and by an independent reader,
// faults named by verify, a run killed at a random point, later reads added, an index.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
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

// data/tape.png is a picture drawn by a real renderer (the picture module, as tape render draws a .png): a PNG
// whose header says its size, and whose pixels tape scan reads back as the restored tape's first strip.
TEST(ArchiveCli, TapePngIsAPictureTapeScanReadsBack) {
    TwoReads t;
    std::string bag = t.dir.file("bag");
    Outcome r = tape_run({"archive", "create", bag, "--read", t.r1, "--read", t.r2}, t.dir);
    if (r.err.find("built without OpenCV") != std::string::npos) GTEST_SKIP() << "built without OpenCV: " << r.err;
    ASSERT_EQ(r.status, 0) << r.err;
    std::string png = read_text(bag + "/data/tape.png");
    ASSERT_GE(png.size(), 24u);
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    EXPECT_EQ(png.substr(12, 4), "IHDR");
    auto be32 = [&png](std::size_t at) {
        std::uint32_t v = 0;
        for (std::size_t i = at; i < at + 4; ++i) v = v << 8 | static_cast<unsigned char>(png[i]);
        return v;
    };
    // Strips of 500 mm at 50 dpi, one under the other: about a thousand pixels wide; the 1.06 m of this tape
    // in three strips, each of 25.4 mm tape (50 pixels) and a margin.
    EXPECT_GT(be32(16), 900u);
    EXPECT_LT(be32(16), 1100u);
    EXPECT_GT(be32(20), 3 * 50u);
    EXPECT_LT(be32(20), be32(16));
    EXPECT_NE(read_text(bag + "/data/format.txt").find("tape.png pictures the tape as it looks"), std::string::npos);
    Outcome scan = tape_run({"scan", bag + "/data/tape.png", "-o", t.dir.file("scanned.ptp")}, t.dir);
    ASSERT_EQ(scan.status, 0) << scan.err;
    EXPECT_NE(scan.err.find("another strip"), std::string::npos) << scan.err;
    std::string scanned = read_text(t.dir.file("scanned.ptp")), restored = read_text(bag + "/data/restored.ptp");
    EXPECT_GT(scanned.size(), 150u) << "the first strip holds 500 mm of tape: 196 frames";
    EXPECT_EQ(scanned, restored.substr(0, scanned.size()));
    EXPECT_EQ(sh("cd " + bag + " && sha256sum -c --strict manifest-sha256.txt"), 0);
}

// The files of a bag's data/contents/ of a tape punched from text.
std::map<std::string, std::string> contents_of_tape(const TempDir& dir, const std::string& name,
                                                    const std::string& text) {
    write(dir.file(name + ".txt"), text);
    EXPECT_EQ(tape_run({"encode", dir.file(name + ".txt"), "-o", dir.file(name + ".ptp")}, dir).status, 0);
    std::string bag = dir.file(name);
    Outcome r = tape_run({"archive", "create", bag, "--read", dir.file(name + ".ptp")}, dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(bagit_reader::read(bag).errors.empty()) << name;
    EXPECT_EQ(sh("cd " + bag + " && sha512sum -c --strict manifest-sha512.txt"), 0) << name;
    std::map<std::string, std::string> files;
    for (const auto& e : fs::directory_iterator(bag + "/data/contents"))
        files[e.path().filename().string()] = read_text(e.path().string());
    return files;
}

// A tape of several programs: text.txt whole, and each program in a file of its own, from its start to the next
// one's, named by its number, or by its place where it has none; one program alone is text.txt only.
TEST(ArchiveCli, ContentsHoldAFilePerProgram) {
    TempDir dir;
    const std::string p1 = "%1\nN1 G00 X100\nN2 M02\n", p2 = "%\nN1 G01 X200 F100\nN2 M02\n",
                      p3 = "%3\nN1 G00 Z50\nN2 M02\n";
    auto gost = contents_of_tape(dir, "gost", p1 + p2 + p3);
    EXPECT_EQ(gost.size(), 4u);
    EXPECT_EQ(gost["1.txt"], p1);
    EXPECT_EQ(gost["program-2.txt"], p2);
    EXPECT_EQ(gost["3.txt"], p3);
    EXPECT_EQ(gost["text.txt"], p1 + p2 + p3);
    // Fanuc's programs start at their O numbers; the '%' around them go with the first and the last.
    const std::string o1 = "%\nO0001\nN1 G00 X100.\nN2 M30\n", o2 = "O0002\nN1 G01 X200. F100.\nN2 M30\n%\n";
    auto fanuc = contents_of_tape(dir, "fanuc", o1 + o2);
    EXPECT_EQ(fanuc.size(), 3u);
    EXPECT_EQ(fanuc["O0001.txt"], o1);
    EXPECT_EQ(fanuc["O0002.txt"], o2);
    EXPECT_NE(bagit_reader::read(dir.file("fanuc"))
                  .info["Tape-Contents"]
                  .find("its 2 programs each in a file of its own, named by its number or its place on the tape: "
                        "contents/O0001.txt, contents/O0002.txt"),
              std::string::npos);
    auto one = contents_of_tape(dir, "one", p1);
    EXPECT_EQ(one.size(), 1u);
    EXPECT_EQ(one["text.txt"], p1);
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

// A bag of a DEC loader tape holds its memory image and checksums, of the format its source names (a .rim
// file RIM, the other PDP-8 tapes BIN, the PDP-11 "-PB" tapes absolute loader: outside2/SOURCES.md); other
// tapes hold neither. True for a loader tape whose bag holds them.
bool loader_contents_fit(const std::string& bag, const std::string& read) {
    std::string name = fs::path(read).filename().string(), family = fs::path(read).parent_path().filename().string();
    std::string format = family == "pdp8" ? (name.ends_with(".rim") ? "PDP-8 RIM" : "PDP-8 BIN")
                         : family == "pdp11" && name.ends_with("-PB.ptap") ? "PDP-11 absolute loader"
                                                                           : "";
    bool memory = fs::exists(bag + "/data/contents/memory.txt");
    EXPECT_EQ(memory, !format.empty()) << name;
    if (!memory || format.empty()) return false;
    std::string checksums = read_text(bag + "/data/contents/checksums.txt");
    EXPECT_NE(checksums.find(format), std::string::npos) << name << ": " << checksums.substr(0, 200);
    std::string image = read_text(bag + "/data/contents/memory.txt");
    EXPECT_NE(image.find(":"), std::string::npos) << name;
    EXPECT_EQ(image.find_first_not_of("01234567:- \n"), std::string::npos) << name << ": octal only";
    EXPECT_NE(bagit_reader::read(bag).info["Tape-Contents"].find(
                  format + (format.ends_with("loader") ? "" : " loader") + " tape"),
              std::string::npos)
        << name;
    return true;
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
        loaders += loader_contents_fit(bag, set[0]);
        Outcome v = tape_run({"archive", "verify", bag}, dir);
        EXPECT_EQ(v.status, 0) << set[0] << ": " << v.err;
    }
    EXPECT_EQ(loaders, 6) << "the four PDP-8 and two PDP-11 loader tapes' memory images";
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
