// What a run loads at its start: OpenCV's core and imgproc (the frame buffer is a cv::Mat), and
// none of imgcodecs, videoio, highgui or what they pull in (GDAL, FFmpeg, Qt), which only the
// plugins that read, write or show images bring (docs/design.md, Plugins).

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace zrender
