#pragma once

// Screenshots of the X display, as xwd (Debian package x11-apps) writes them.

#include <string>

#include <opencv2/core.hpp>

namespace zrender::test {

// The image of an XWD file of a 24-bit TrueColor window (Xvfb's), as CV_8UC3 BGR; empty when
// the file is not one.
cv::Mat readXwd(const std::string& path);

}  // namespace zrender::test
