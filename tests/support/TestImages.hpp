#pragma once

// Reading and writing image and video files in the tests, through OpenCV's imgcodecs and videoio
// in a module of their own (support/codecs/TestCodecs.cpp, libzrender_test_codecs.so) that is
// loaded at the first call. Linking them into zrender_tests loaded some 220 libraries (GDAL,
// FFmpeg, GTK) at the start of every test process: 0.1 s each, 0.2 s under AddressSanitizer,
// paid by the hundreds of tests that read no image.

#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>
#include <opencv2/imgcodecs.hpp>

namespace zrender::test {

// cv::imread: an empty matrix when the file cannot be read. `flags` are cv::IMREAD_*.
cv::Mat imread(const std::string& path, int flags = cv::IMREAD_COLOR);

// cv::imwrite: false when the file was not written.
bool imwrite(const std::string& path, const cv::Mat& image);

// cv::imencode into `bytes`: the file of extension `ext` (".png") that `image` would be.
bool imencode(const std::string& ext, const cv::Mat& image, std::vector<unsigned char>& bytes);

// The frame count of a video file as cv::VideoCapture reports it, or -1 when it cannot be opened.
int videoFrameCount(const std::string& path);

}  // namespace zrender::test
