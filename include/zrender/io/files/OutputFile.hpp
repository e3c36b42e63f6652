#pragma once

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "zrender/io/files/InterruptCleanup.hpp"

namespace zrender {

// One output file, written completely or not at all (docs/design.md, Outputs). It is written
// inside a private folder that this object makes beside the target (".zrender-" and 16 random
// letters, mode 0700, so no other user can plant or swap anything in it), then renamed over
// the target by commit(): what was at the target stays until then, a symbolic link there is
// replaced and never written through, and a failure or an interrupt (InterruptCleanup.hpp)
// leaves nothing behind. Failures throw InputError "TARGET: cannot write file: REASON".
class OutputFile {
 public:
  // Makes the missing parent folders of `target`, then the private folder.
  explicit OutputFile(const std::filesystem::path& target);
  ~OutputFile();  // removes the private folder and what it holds, unless committed
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  const std::filesystem::path& target() const { return target_; }

  // The file, created empty (O_EXCL, O_NOFOLLOW) on first use: its descriptor, or a stream
  // on it. Either is this object's to close.
  int descriptor();
  std::FILE* stream();
  // Writes all `size` bytes of `data` at the file's end, or throws.
  void write(const void* data, size_t size);
  // The file's name for a library that opens it by name (a video writer): through
  // /proc/self/fd, so it names the private folder this object holds open whatever becomes of
  // the folder's name; the file is created first, with the target's extension.
  std::filesystem::path pathForLibrary();

  // Closes the file (its last write's error is the reason, as for write()), then renames it
  // over the target and removes the private folder.
  void commit();
  // " (no space left on device)" when the file system of the private folder has less than
  // 1 MiB left, else "": the likely reason when a library's writer stopped without one.
  std::string diskFullNote() const;
  // Throws InputError "TARGET: REASON".
  [[noreturn]] void fail(const std::string& reason) const;

 private:
  void closeFile();
  void removeAll();

  std::filesystem::path target_;
  std::string fileName_;  // inside the folder: "out" and the target's extension
  InFlightFiles inFlight_;
  bool listed_ = false;
  int folderFd_ = -1;
  int fd_ = -1;
  std::FILE* stream_ = nullptr;
};

// Throws InputError unless `path` could be written later, so that a run that would fail at
// its end writes nothing: makes the missing parent folders (the write would), refuses a folder
// in the target's place, and makes and removes an OutputFile's private folder beside it.
void checkWritable(const std::filesystem::path& path);

// An output a command will write, and the option that names it ("-o").
struct NamedOutput {
  const char* option;
  std::filesystem::path path;
};

// Throws InputError "command line: A and B both name FILE" when two outputs are the same
// directory entry, however spelled: "x.png", "./x.png", "d/../x.png", or through a link to a
// folder. (A symbolic link at the target itself is replaced, not written through, so a link and
// the file it points to are two outputs.)
void checkDistinctOutputs(const std::vector<NamedOutput>& outputs);

// Writes `bytes` to `path` as an OutputFile.
void writeFileAtomically(const std::filesystem::path& path, const std::string& bytes);

// Adds `bytes` at the end of the regular file at `path` (a CI step summary), or makes it: the
// old bytes and the new are written as one new file that replaces it, so a full disk or an
// interrupt leaves the old file whole, and a symbolic link there is replaced, not followed.
void appendFileAtomically(const std::filesystem::path& path, const std::string& bytes);

}  // namespace zrender
