// What a run loads at its start: OpenCV's core and imgproc (the frame buffer is a cv::Mat), and
// none of imgcodecs, videoio, highgui or what they pull in (GDAL, FFmpeg, Qt), which only the
// plugins that read, write or show images bring (docs/design.md, Plugins).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/TestSupport.hpp"

namespace zrender {
namespace {

// LD_TRACE_LOADED_OBJECTS makes the dynamic loader list the libraries the program would load
// and stop there, as ldd does.
TEST(ProgramStart, LoadsOpenCvCoreButNotItsCodecsVideoOrWindows) {
  const test::RunResult r =
      test::runZrender({"--version"}, "", test::RunLimits(), {{"LD_TRACE_LOADED_OBJECTS", "1"}});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("libtbb"), std::string::npos) << "no list of libraries:\n" << r.out;
  EXPECT_NE(r.out.find("libopencv_core"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("libopencv_imgproc"), std::string::npos) << r.out;
  for (const char* heavy : {"libopencv_imgcodecs", "libopencv_videoio", "libopencv_highgui",
                            "libgdal", "libavcodec", "libQt"})
    EXPECT_EQ(r.out.find(heavy), std::string::npos) << heavy << " in:\n" << r.out;
}

// A zrender copied beside a codecs plugin of another build (an old install's, say) refuses it by
// name and writes nothing, where calling it would crash.
TEST(ProgramStart, ACodecsPluginOfAnotherBuildIsRefusedByName) {
  namespace fs = std::filesystem;
  const test::TempDir dir;
  const std::string zrender = dir.file("zrender");
  fs::copy_file(ZRENDER_BINARY, zrender);
  const fs::path tests = fs::read_symlink("/proc/self/exe").parent_path();
  fs::copy_file(tests / "libzrender_foreign.so", dir.file("libzrender_codecs.so"));
  const test::RunResult r = test::runProgram({zrender, "bunny", "-o", dir.file("out.jpg")});
  EXPECT_EQ(r.status, 1) << r.err;
  const std::string start = "zrender: internal error: cannot load libzrender_codecs.so: " +
                            dir.file("libzrender_codecs.so") +
                            " is from another build of zrender (interface 0000000000000000";
  EXPECT_EQ(r.err.rfind(start, 0), 0u) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("out.jpg")));
}

}  // namespace
}  // namespace zrender
