#pragma once

// The C interface of libzrender_codecs.so (src/io/codecs/OpenCvCodecs.cpp), resolved with dlsym.
// cv::Mat crosses it by pointer: plugin and program share the same libopencv_core.

#include <cstddef>

namespace cv {
class Mat;
}

extern "C" {
// 0 on success; otherwise a message is written into `error` (at most `size` bytes).
typedef int (*ZrenderImwriteFn)(const char* path, const cv::Mat* image, char* error, size_t size);
// Fills `out` with cv::imread(path, flags); 0 on success.
typedef int (*ZrenderImreadFn)(const char* path, int flags, cv::Mat* out, char* error, size_t size);
typedef void* (*ZrenderVideoOpenFn)(const char* path, int fourcc, double fps, int width,
                                    int height);
typedef int (*ZrenderVideoWriteFn)(void* writer, const cv::Mat* frame);
typedef void (*ZrenderVideoCloseFn)(void* writer);
}
