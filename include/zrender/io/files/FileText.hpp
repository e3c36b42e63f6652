#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace zrender {

// The largest model file zrender reads, bytes (docs/design.md, Limits).
inline constexpr size_t kMaxModelBytes = size_t(2) << 30;

// The bytes of a file, read once for a parse. A regular file is mapped, not copied: its pages
// come straight from the kernel's cache (for the bunny's 2.4 MB, 0.3 ms mapped against 1.9 ms
// read into new memory). Anything else (a pipe) is read. If another program truncates a
// mapped file while it is read, the process gets SIGBUS; editors write a new file and rename
// it, which a mapping does not see (docs/design.md, Loading).
class FileText {
 public:
  // Throws InputError "PATH: cannot open file" (or "... (it is a folder)", "cannot read file",
  // "cannot read a device as a file", "file too large (over N MiB)" past `maxBytes`).
  explicit FileText(const std::string& path, size_t maxBytes = kMaxModelBytes);
  ~FileText();
  FileText(const FileText&) = delete;
  FileText& operator=(const FileText&) = delete;

  std::string_view text() const { return mapped_ ? std::string_view(mapped_, size_) : read_; }

 private:
  const char* mapped_ = nullptr;
  size_t size_ = 0;
  std::string read_;
};

}  // namespace zrender
