#include "zrender/base/Plugin.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <vector>

namespace zrender {

namespace fs = std::filesystem;

void* openPlugin(const std::string& fileName, const std::string& builtPath, std::string& error) {
  std::vector<std::string> candidates;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    candidates.push_back((exe.parent_path() / fileName).string());
    candidates.push_back((exe.parent_path().parent_path() / fileName).string());
  }
  candidates.push_back(builtPath);
  error = "not found beside the executable nor at " + builtPath;
  for (const std::string& c : candidates) {
    if (!fs::exists(c, ec)) continue;
    if (void* handle = dlopen(c.c_str(), RTLD_NOW | RTLD_LOCAL)) return handle;
    error = dlerror();
  }
  return nullptr;
}

void* pluginSymbol(void* plugin, const char* symbol) {
  return dlsym(plugin, symbol);
}

}  // namespace zrender
