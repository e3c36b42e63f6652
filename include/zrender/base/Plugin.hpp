#pragma once

// Shared libraries that zrender loads only when a command needs them (dlopen), so that their
// dependencies cost nothing at the start of the runs that do not: OpenCV's codecs
// (io/ImageCodecs.hpp) and its window (view/ViewWindow.hpp).

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <string>

namespace zrender {

// Opens the plugin `fileName` (e.g. "libzrender_codecs.so"), found relative to the executable
// only: in ../lib/zrender/ (an installed zrender: P/bin/zrender, P/lib/zrender/), then beside
// it and in its parent folder (the build tree). Returns the dlopen handle, or null with the
// reason in `error`.
void* openPlugin(const std::string& fileName, std::string& error);

// The address of `symbol` in a plugin opened by openPlugin, or null.
void* pluginSymbol(void* plugin, const char* symbol);

// For the plugins' C interfaces: writes `text` on one line into `error`, at most `size` bytes.
inline void setPluginError(char* error, size_t size, std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::snprintf(error, size, "%s", text.c_str());
}

}  // namespace zrender
