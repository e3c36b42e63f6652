// What a run loads at its start: none of OpenCV's libraries, which only the plugins that read,
// write, draw or show images bring in (docs/design.md, Plugins).

#include <gtest/gtest.h>

#include <string>

#include "support/TestSupport.hpp"

namespace zrender {
namespace {

// LD_TRACE_LOADED_OBJECTS makes the dynamic loader list the libraries the program would load
// and stop there, as ldd does.
TEST(ProgramStart, LoadsNoOpenCvLibrary) {
  const test::RunResult r =
      test::runZrender({"--version"}, "", test::RunLimits(), {{"LD_TRACE_LOADED_OBJECTS", "1"}});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("libtbb"), std::string::npos) << "no list of libraries:\n" << r.out;
  EXPECT_EQ(r.out.find("libopencv"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace zrender
