#pragma once

// Helpers shared by the fuzz targets: a scratch folder per process, failure reporting, and the
// checks every InputError message must pass (docs/design.md, Errors: one line that names the file
// first).

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace zrender::fuzz {

// Reports a broken contract and aborts, which libFuzzer records as a crash with its input.
[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "zrender fuzz: contract broken: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

// A private folder for files written beside the fuzzed text (an .mtl), made once per process
// under $TMPDIR and removed at exit.
inline const std::filesystem::path& scratchFolder() {
  static const std::filesystem::path folder = [] {
    const char* base = std::getenv("TMPDIR");
    std::string pattern = std::string(base && *base ? base : "/tmp") + "/zrender-fuzz-XXXXXX";
    if (!mkdtemp(pattern.data())) fail("cannot create a scratch folder from " + pattern);
    static const std::string keep = pattern;
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(keep, ec);
    });
    return std::filesystem::path(pattern);
  }();
  return folder;
}

// An error or warning text must be one line (control bytes escaped) starting with `prefix`.
inline void checkMessage(const std::string& message, const std::string& prefix, const char* kind) {
  if (message.compare(0, prefix.size(), prefix) != 0) {
    fail(std::string(kind) + " does not start with '" + prefix + "': " + message);
  }
  for (const char c : message) {
    if (c == '\n' || c == '\r' || c == '\0')
      fail(std::string(kind) + " is not one line: " + message);
  }
}

}  // namespace zrender::fuzz
