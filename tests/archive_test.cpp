// The bag writer and verifier of tape/archive.hpp: RFC 8493's text rules, bags checked by an independent
// reader (bagit_reader.hpp) and by coreutils, and each fault a verifier must name.
#include "tape/archive.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "bagit_reader.hpp"
#include "tape/error.hpp"
#include "test_util.hpp"

namespace {

namespace fs = std::filesystem;

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

std::vector<std::string> ids(const tape::BagCheck& c) {
    std::vector<std::string> out;
    for (const auto& p : c.problems) out.push_back(p.id + " " + p.file);
    return out;
}

// A bag of three payload files, one of them with '%' and a line end in its name.
std::string small_bag(const TempDir& dir) {
    std::string bag = dir.file("bag");
    tape::BagWriter w(bag, false);
    w.add("reads/r1.ptp", std::string("\x80\x80\x25\x0a", 4));
    w.add("reads/100%\nsure.txt", "odd name");
    w.add("format.txt", "ISO with even parity\n");
    w.commit({{"External-Identifier", "T-1"}, {"Bagging-Date", "2026-11-29"}});
    return bag;
}

TEST(BagText, PercentEncodingOfNames) {
    EXPECT_EQ(tape::bag_encoded_path("a%b\r\nc d"), "a%25b%0D%0Ac d");
    EXPECT_EQ(tape::bag_decoded_path("a%25b%0D%0Ac d"), "a%b\r\nc d");
    EXPECT_EQ(tape::bag_decoded_path("%0a%0d"), "\n\r");  // hex digits in either case
    EXPECT_EQ(tape::bag_decoded_path("%41%2"), "%41%2");  // only the three the RFC names
}

TEST(BagText, LinesEndInLfCrLfOrCr) {
    auto l = tape::tag_file_lines("a\nb\r\nc\rd");
    ASSERT_EQ(l.size(), 4u);
    EXPECT_EQ(l[0], "a");
    EXPECT_EQ(l[1], "b");
    EXPECT_EQ(l[2], "c");
    EXPECT_EQ(l[3], "d");
}

TEST(BagText, BagInfoContinuationsAndBadLines) {
    std::vector<std::uint64_t> bad;
    auto info =
        tape::parse_bag_info("Source-Organization: Museum\r\n  of Computing\r\nno colon here\r\nX: 1\r\n", &bad);
    ASSERT_EQ(info.size(), 2u);
    EXPECT_EQ(info[0].value, "Museum of Computing");
    EXPECT_EQ(tape::bag_info_value(info, "source-organization"), "Museum of Computing");
    ASSERT_EQ(bad.size(), 1u);
    EXPECT_EQ(bad[0], 3u);
    EXPECT_EQ(tape::payload_oxum(279, 2), "279.2");
}

TEST(BagDigests, KnownAnswers) {
    std::string abc = "abc";
    auto d = tape::digest_bytes({reinterpret_cast<const std::uint8_t*>(abc.data()), abc.size()});
    EXPECT_EQ(d.sha256, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    EXPECT_EQ(d.sha512.substr(0, 32), "ddaf35a193617abacc417349ae204131");
    EXPECT_EQ(d.bytes, 3u);
}

TEST(BagWriter, WritesABagAnIndependentReaderAccepts) {
    TempDir dir;
    std::string bag = small_bag(dir);
    bagit_reader::Bag b = bagit_reader::read(bag);
    EXPECT_TRUE(b.errors.empty()) << ::testing::PrintToString(b.errors);
    EXPECT_EQ(b.info["External-Identifier"], "T-1");
    EXPECT_EQ(b.info["Payload-Oxum"], "33.3");
    EXPECT_EQ(b.manifests["sha256"].count("data/reads/100%\nsure.txt"), 1u);
    EXPECT_NE(read_text(bag + "/manifest-sha256.txt").find("data/reads/100%25%0Asure.txt"), std::string::npos);
    tape::BagCheck c = tape::verify_bag(bag);
    EXPECT_TRUE(c.valid()) << ::testing::PrintToString(ids(c));
    EXPECT_EQ(c.files, 3u);
    // No staging folder is left beside the bag.
    int entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path)) ++entries;
    EXPECT_EQ(entries, 1);
}

TEST(BagWriter, NeverReplacesWithoutLeaveAndLeavesNothingUncommitted) {
    TempDir dir;
    std::string bag = small_bag(dir);
    try {
        tape::BagWriter w(bag, false);
        FAIL() << "an existing bag was not refused";
    } catch (const tape::Error& e) {
        EXPECT_EQ(e.code(), tape::Errc::exists);
    }
    {
        tape::BagWriter w(dir.file("other"), false);
        w.add("a.txt", "a");
        EXPECT_TRUE(fs::exists(w.staging()));
    }  // never committed: nothing stays
    EXPECT_FALSE(fs::exists(dir.file("other")));
    int entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path)) ++entries;
    EXPECT_EQ(entries, 1);
    tape::BagWriter w(bag, true);  // replace: the new bag takes the old one's place
    w.add("only.txt", "x");
    w.commit({});
    EXPECT_FALSE(fs::exists(bag + "/data/format.txt"));
    EXPECT_TRUE(tape::verify_bag(bag).valid());
}

TEST(BagWriter, UpdateKeepsEveryFileAndAddsOne) {
    TempDir dir;
    std::string bag = small_bag(dir);
    std::string before = read_text(bag + "/data/reads/r1.ptp");
    tape::BagWriter w = tape::BagWriter::update(bag);
    EXPECT_EQ(tape::bag_info_value(w.previous_info(), "External-Identifier"), "T-1");
    EXPECT_THROW(w.add("format.txt", "other"), tape::Error);  // never overwritten
    w.add("reads/r2.ptp", "second");
    w.commit(w.previous_info());
    EXPECT_EQ(read_text(bag + "/data/reads/r1.ptp"), before);
    tape::BagCheck c = tape::verify_bag(bag);
    EXPECT_TRUE(c.valid()) << ::testing::PrintToString(ids(c));
    EXPECT_EQ(c.files, 4u);
    EXPECT_TRUE(bagit_reader::read(bag).errors.empty());
}

TEST(BagVerify, FlippedByteIsNamedInEveryManifest) {
    TempDir dir;
    std::string bag = small_bag(dir);
    write(bag + "/data/format.txt", "ISO with even parity\r");
    auto c = tape::verify_bag(bag);
    EXPECT_FALSE(c.valid());
    EXPECT_EQ(ids(c),
              (std::vector<std::string>{"checksum-mismatch data/format.txt", "checksum-mismatch data/format.txt"}));
}

TEST(BagVerify, AddedFileIsUnlisted) {
    TempDir dir;
    std::string bag = small_bag(dir);
    write(bag + "/data/extra.txt", "x");
    auto c = tape::verify_bag(bag);
    EXPECT_EQ(ids(c), (std::vector<std::string>{"oxum-mismatch bag-info.txt", "file-unlisted data/extra.txt",
                                                "file-unlisted data/extra.txt"}));
}

TEST(BagVerify, RemovedFileIsMissing) {
    TempDir dir;
    std::string bag = small_bag(dir);
    fs::remove(bag + "/data/format.txt");
    auto c = tape::verify_bag(bag);
    EXPECT_EQ(ids(c), (std::vector<std::string>{"oxum-mismatch bag-info.txt", "file-missing data/format.txt",
                                                "file-missing data/format.txt"}));
}

TEST(BagVerify, TruncatedManifestIsNamed) {
    TempDir dir;
    std::string bag = small_bag(dir);
    std::string m = read_text(bag + "/manifest-sha512.txt");
    write(bag + "/manifest-sha512.txt", m.substr(0, m.size() / 2));  // cut inside the second line
    auto c = tape::verify_bag(bag);
    EXPECT_FALSE(c.valid());
    std::vector<std::string> got = ids(c);
    EXPECT_NE(std::find(got.begin(), got.end(), "bad-manifest-line manifest-sha512.txt"), got.end())
        << ::testing::PrintToString(got);
    EXPECT_NE(std::find(got.begin(), got.end(), "tag-checksum-mismatch manifest-sha512.txt"), got.end());
    EXPECT_EQ(std::count_if(got.begin(), got.end(), [](const auto& s) { return s.starts_with("file-unlisted"); }), 2);
}

TEST(BagVerify, CrLfTagFilesAreValid) {
    TempDir dir;
    std::string bag = small_bag(dir);
    for (const char* name : {"bagit.txt", "bag-info.txt", "manifest-sha256.txt", "manifest-sha512.txt"}) {
        std::string t = read_text(bag + "/" + name), crlf;
        for (char ch : t) crlf += ch == '\n' ? std::string("\r\n") : std::string(1, ch);
        write(bag + "/" + name, crlf);
    }
    fs::remove(bag + "/tagmanifest-sha256.txt");  // its checksums were of the LF files
    auto c = tape::verify_bag(bag);
    EXPECT_TRUE(c.valid()) << ::testing::PrintToString(ids(c));
    EXPECT_TRUE(bagit_reader::read(bag).errors.empty());
}

TEST(BagVerify, NoBagitTxtAndWrongOxum) {
    TempDir dir;
    std::string bag = small_bag(dir);
    std::string info = read_text(bag + "/bag-info.txt");
    write(bag + "/bag-info.txt", info.replace(info.find("33.3"), 4, "34.3"));
    fs::remove(bag + "/bagit.txt");
    auto got = ids(tape::verify_bag(bag));
    EXPECT_NE(std::find(got.begin(), got.end(), "no-bagit-txt bagit.txt"), got.end());
    EXPECT_NE(std::find(got.begin(), got.end(), "oxum-mismatch bag-info.txt"), got.end());
    EXPECT_NE(std::find(got.begin(), got.end(), "tag-file-missing bagit.txt"), got.end());
}

TEST(BagVerify, OtherAlgorithmsAreSaidNotChecked) {
    TempDir dir;
    std::string bag = small_bag(dir);
    write(bag + "/manifest-md5.txt", "");
    auto c = tape::verify_bag(bag);
    EXPECT_TRUE(c.valid());
    ASSERT_EQ(c.problems.size(), 1u);
    EXPECT_EQ(c.problems[0].id, "unchecked-algorithm");
    EXPECT_TRUE(c.problems[0].note);
}

}  // namespace
