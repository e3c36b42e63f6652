#pragma once

// The C interface of libzrender_drawing.so (src/io/drawing/OpenCvDrawing.cpp), resolved with
// dlsym. The arguments are the C++ objects of io/Drawing.hpp, by pointer: plugin and program
// are built together, with the same compiler and standard library.

#include <cstddef>
#include <string>
#include <vector>

namespace zrender {
class Image;
struct ChartGroup;
struct PixelBox;
}  // namespace zrender

extern "C" {
// Each returns 0 on success, or writes a message into `error` (at most `size` bytes).
typedef int (*ZrenderDrawBarChartFn)(const std::string* title,
                                     const std::vector<zrender::ChartGroup>* groups,
                                     zrender::Image* out, char* error, size_t size);
typedef int (*ZrenderOverlayBoxFn)(int width, int height, const std::vector<std::string>* lines,
                                   zrender::PixelBox* out, char* error, size_t size);
typedef int (*ZrenderWithOverlayFn)(const zrender::Image* frame,
                                    const std::vector<std::string>* lines, zrender::Image* out,
                                    char* error, size_t size);
typedef int (*ZrenderContactSheetFn)(const std::vector<zrender::Image>* frames, zrender::Image* out,
                                     char* error, size_t size);
}
