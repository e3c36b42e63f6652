#pragma once

// The C interface of libzrender_window.so (src/view/window/HighguiWindow.cpp), resolved with
// dlsym. Images cross it as cv::Mat pointers: both sides link the same libopencv_core.

#include <cstddef>

#include <opencv2/core/mat.hpp>

extern "C" {
// Opens a window titled `title` on the X display of $DISPLAY; null with a message in `error`
// (at most `size` bytes) when there is no display or no GUI backend.
typedef void* (*ZrenderWindowOpenFn)(const char* title, char* error, size_t size);
typedef void (*ZrenderWindowShowFn)(void* window, const cv::Mat* image);
// Runs the window's events for up to `milliseconds`: the code of a key pressed (cv::waitKeyEx),
// -1 for none, -2 when the window was closed.
typedef int (*ZrenderWindowWaitKeyFn)(void* window, int milliseconds);
typedef void (*ZrenderWindowCloseFn)(void* window);
}
