#pragma once

// Shared libraries that zrender loads only when a command needs them (dlopen), so that their
// dependencies cost nothing at the start of the runs that do not: OpenCV's imgcodecs and
// videoio (io/CodecPlugin.hpp) and highgui (view/WindowPlugin.hpp) (docs/design.md, Plugins).
// A plugin gives one object through an `extern "C"` factory, an implementation of an abstract
// class that both sides compile from the same header.

#include <string>

namespace zrender {

// The object that the factory `factory` of the plugin `fileName` (e.g. "libzrender_codecs.so")
// returns, the plugin found relative to the executable only: in ../lib/zrender/ (an installed
// zrender: P/bin/zrender, P/lib/zrender/), then beside it and in its parent folder (the build
// tree). A plugin whose interface tag (src/base/plugin/PluginAbi.cpp: a hash of the headers,
// version and compiler it was built with) is not this build's is passed over: its classes may
// not be the ones this build calls. The object lives as long as the process. Throws
// std::runtime_error naming the file and why.
void* pluginObject(const std::string& fileName, const char* factory);

template <typename Interface>
Interface& loadPlugin(const std::string& fileName, const char* factory) {
  return *static_cast<Interface*>(pluginObject(fileName, factory));
}

}  // namespace zrender
