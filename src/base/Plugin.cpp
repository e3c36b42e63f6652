#include "zrender/base/Plugin.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>
#include <vector>

namespace zrender {

namespace fs = std::filesystem;

namespace {

// The interface tag of a plugin's build (src/base/plugin/PluginAbi.cpp), or "none" for a
// plugin without one.
std::string abiOf(void* handle) {
  using Tag = const char* (*)();
  const auto tag = reinterpret_cast<Tag>(dlsym(handle, "zrenderPluginAbi"));
  return tag ? tag() : "none";
}

// The plugin's dlopen handle, or null with the reason in `error`. A plugin of another build is
// closed and the next place tried: its classes may not be this build's.
void* openPlugin(const std::string& fileName, std::string& error) {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) {
    error = "cannot find the executable's folder: " + ec.message();
    return nullptr;
  }
  const fs::path folder = exe.parent_path();
  // Installed (P/bin/zrender, P/lib/zrender/), then the build tree (build/zrender, and
  // build/tests/zrender_tests or build-fuzz/fuzz/fuzz_render one folder down).
  const std::vector<fs::path> candidates = {folder.parent_path() / "lib" / "zrender" / fileName,
                                            folder / fileName, folder.parent_path() / fileName};
  error = "not found in " + candidates[0].parent_path().string() + " nor beside " + exe.string();
  bool foreign = false;
  for (const fs::path& c : candidates) {
    if (!fs::exists(c, ec)) continue;
    void* handle = dlopen(c.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      if (!foreign) error = dlerror();
      continue;
    }
    const std::string abi = abiOf(handle);
    if (abi == ZRENDER_PLUGIN_ABI) return handle;
    dlclose(handle);
    if (!foreign) {
      error = c.string() + " is from another build of zrender (interface " + abi +
              ", this zrender's " + ZRENDER_PLUGIN_ABI + "); install zrender again";
      foreign = true;
    }
  }
  return nullptr;
}

}  // namespace

void* pluginObject(const std::string& fileName, const char* factory) {
  std::string reason;
  void* handle = openPlugin(fileName, reason);
  if (!handle) throw std::runtime_error("cannot load " + fileName + ": " + reason);
  using Factory = void* (*)();
  const auto make = reinterpret_cast<Factory>(dlsym(handle, factory));
  if (!make) throw std::runtime_error(fileName + " has no " + factory);
  return make();
}

}  // namespace zrender
