// Pictures only when drawn: the tape program links no picture library, a command that draws or reads
// no picture never loads the picture module, and scan and render to a picture file load it and work;
// where it is missing or broken they say so, with exit 3.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <cstdlib>
#include <fstream>

#include "process_util.hpp"
#include "test_util.hpp"

namespace {

// The environment of the processes this test starts, set for its life.
class Env {
public:
    Env(const char* name, const std::string& value) : name_(name) { ::setenv(name, value.c_str(), 1); }
    ~Env() { ::unsetenv(name_); }
    Env(const Env&) = delete;
    Env& operator=(const Env&) = delete;

private:
    const char* name_;
};

TEST(PictureModule, TheProgramLinksNoPictureLibrary) {
    TempDir dir;
    std::string needed = dir.file("needed");
    ASSERT_EQ(std::system(("readelf -d " + std::string(TAPE_BINARY) + " > " + needed).c_str()), 0);
    std::string dynamic = read_text(needed);
    EXPECT_NE(dynamic.find("NEEDED"), std::string::npos);
    for (const char* library : {"opencv", "gdal", "png", "jpeg", "tiff"})
        EXPECT_EQ(dynamic.find(library), std::string::npos) << library << " in\n" << dynamic;
}

TEST(PictureModule, DecodeLoadsNoPictureModule) {
    TempDir dir;
    Env files("LD_DEBUG", "files");  // the dynamic loader names every object it loads, dlopen's too
    Outcome r = tape_run({"decode", sample_path("16k20f3s5-turning.iso.ptp"), "-o", dir.file("out.txt")}, dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("libusb"), std::string::npos) << "LD_DEBUG said nothing: " << r.err;
    EXPECT_EQ(r.err.find("tape-pictures"), std::string::npos);
    EXPECT_EQ(r.err.find("opencv"), std::string::npos);
}

TEST(PictureModule, RenderAndScanLoadItAndReadBack) {
    TempDir dir;
    Outcome encode = tape_run({"encode", sample_path("circle-examples.txt"), "-o", dir.file("c.ptp")}, dir);
    ASSERT_EQ(encode.status, 0) << encode.err;
    {
        Env files("LD_DEBUG", "files");
        Outcome render = tape_run({"render", dir.file("c.ptp"), "-o", dir.file("c.png")}, dir);
        if (render.status == 3 && render.err.find("built without OpenCV") != std::string::npos)
            GTEST_SKIP() << "built without OpenCV: " << render.err;
        ASSERT_EQ(render.status, 0) << render.err;
        EXPECT_NE(render.err.find("tape-pictures"), std::string::npos);
    }
    Outcome scan = tape_run({"scan", dir.file("c.png"), "-o", dir.file("s.ptp")}, dir);
    ASSERT_EQ(scan.status, 0) << scan.err;
    EXPECT_EQ(read_text(dir.file("s.ptp")), read_text(dir.file("c.ptp")));
}

TEST(PictureModule, MissingOrBrokenModuleIsSaidWithExit3) {
    TempDir dir;
    Outcome encode = tape_run({"encode", sample_path("circle-examples.txt"), "-o", dir.file("c.ptp")}, dir);
    ASSERT_EQ(encode.status, 0) << encode.err;
    {
        Env module("TAPE_PICTURE_MODULE", dir.file("no-such-module.so"));
        Outcome render = tape_run({"render", dir.file("c.ptp"), "-o", dir.file("c.png")}, dir);
        EXPECT_EQ(render.status, 3);
        if (render.err.find("built without OpenCV") != std::string::npos) GTEST_SKIP() << render.err;
        EXPECT_NE(render.err.find("the picture module is not installed (looked for " + dir.file("no-such-module.so")),
                  std::string::npos)
            << render.err;
        EXPECT_FALSE(std::ifstream(dir.file("c.png")).good());
    }
    std::ofstream(dir.file("broken.so")) << "not a shared object\n";
    Env module("TAPE_PICTURE_MODULE", dir.file("broken.so"));
    Outcome scan = tape_run({"scan", dir.file("c.png"), "-o", dir.file("s.ptp")}, dir);
    EXPECT_EQ(scan.status, 3);
    EXPECT_NE(scan.err.find("cannot load the picture module"), std::string::npos) << scan.err;
}

}  // namespace
