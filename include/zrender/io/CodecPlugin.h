#pragma once

// The C interface of libzrender_codecs.so (src/io/codecs/OpenCvCodecs.cpp), resolved with dlsym.
// Images cross it as cv::Mat pointers: both sides link the same libopencv_core.

#include <cstddef>

#include <opencv2/core/mat.hpp>

extern "C" {
// Encodes `image` in the format of `extension` (".jpg") into `out`, a
// std::vector<unsigned char>; 0 on success, otherwise a message is written into `error` (at
// most `size` bytes).
typedef int (*ZrenderImencodeFn)(const char* extension, const cv::Mat* image, void* out,
                                 char* error, size_t size);
// Fills `out` with cv::imread(path, IMREAD_COLOR), 8-bit BGR; 0 on success.
typedef int (*ZrenderImreadFn)(const char* path, cv::Mat* out, char* error, size_t size);
typedef void* (*ZrenderVideoOpenFn)(const char* path, int fourcc, double fps, int width,
                                    int height);
typedef int (*ZrenderVideoWriteFn)(void* writer, const cv::Mat* frame);
typedef void (*ZrenderVideoCloseFn)(void* writer);
}
