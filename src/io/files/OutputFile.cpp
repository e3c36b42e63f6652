#include "zrender/io/files/OutputFile.hpp"

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <map>
#include <system_error>

#include "zrender/base/Error.hpp"
#include "zrender/io/files/FileText.hpp"

namespace zrender {

namespace fs = std::filesystem;

namespace {

// 16 random lowercase letters (75 bits): a name no other user can guess ahead.
std::string randomLetters() {
  unsigned char bytes[16];
  size_t got = 0;
  while (got < sizeof bytes) {
    const ssize_t n = ::getrandom(bytes + got, sizeof bytes - got, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::system_error(errno, std::generic_category(), "getrandom");
    got += size_t(n);
  }
  std::string letters;
  for (unsigned char b : bytes) letters += char('a' + b % 26);
  return letters;
}

bool isRegularFile(const fs::path& path) {
  struct stat status {};
  return ::lstat(path.c_str(), &status) == 0 && S_ISREG(status.st_mode);
}

}  // namespace

OutputFile::OutputFile(const fs::path& target) : target_(target) {
  std::error_code ec;
  if (!target.parent_path().empty()) fs::create_directories(target.parent_path(), ec);
  if (ec) throw InputError(target.string() + ": cannot create folder: " + ec.message());
  const std::string extension = target.extension().string();
  fileName_ = "out" + (extension.size() <= 16 ? extension : std::string());
  const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  const int parentFd = ::open(parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (parentFd < 0) fail(std::string("cannot write file: ") + std::strerror(errno));
  try {
    std::string name;
    for (int attempt = 0;; ++attempt) {
      name = ".zrender-" + randomLetters();
      // Listed before it exists, so that an interrupt from here on finds it.
      inFlight_.folder = (parent / name).string();
      inFlight_.file = inFlight_.folder + "/" + fileName_;
      if (!listInFlight(&inFlight_)) fail("cannot write file: too many outputs at once");
      listed_ = true;
      int error = 0;
      {
        const MakingInFlight making;
        if (::mkdirat(parentFd, name.c_str(), 0700) == 0) {
          inFlight_.folderMade.store(true);
        } else {
          error = errno;
        }
      }
      if (!error) break;
      unlistInFlight(&inFlight_);
      listed_ = false;
      if (error != EEXIST || attempt == 8)
        fail(std::string("cannot write file: ") + std::strerror(error));
    }
    folderFd_ = ::openat(parentFd, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (folderFd_ < 0) fail(std::string("cannot write file: ") + std::strerror(errno));
  } catch (...) {
    ::close(parentFd);
    removeAll();
    throw;
  }
  ::close(parentFd);
}

OutputFile::~OutputFile() {
  removeAll();
}

int OutputFile::descriptor() {
  if (fd_ >= 0) return fd_;
  {
    const MakingInFlight making;
    fd_ = ::openat(folderFd_, fileName_.c_str(),
                   O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ >= 0) inFlight_.fileMade.store(true);
  }
  if (fd_ < 0) fail(std::string("cannot write file: ") + std::strerror(errno));
  return fd_;
}

std::FILE* OutputFile::stream() {
  if (stream_) return stream_;
  stream_ = ::fdopen(descriptor(), "wb");
  if (!stream_) fail(std::string("cannot write file: ") + std::strerror(errno));
  return stream_;
}

void OutputFile::write(const void* data, size_t size) {
  const int fd = descriptor();
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, bytes, size);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(std::string("cannot write file: ") + std::strerror(errno));
    bytes += n, size -= size_t(n);
  }
}

fs::path OutputFile::pathForLibrary() {
  descriptor();
  return fs::path("/proc/self/fd") / std::to_string(folderFd_) / fileName_;
}

void OutputFile::closeFile() {
  int error = 0;
  if (stream_) {
    errno = 0;
    if (std::fflush(stream_) != 0 || std::ferror(stream_)) error = errno ? errno : EIO;
    if (std::fclose(stream_) != 0 && !error) error = errno;
    stream_ = nullptr;
    fd_ = -1;
  } else if (fd_ >= 0) {
    if (::close(fd_) != 0) error = errno;
    fd_ = -1;
  }
  if (error) fail(std::string("cannot write file: ") + std::strerror(error));
}

void OutputFile::commit() {
  descriptor();  // an output with no bytes is still a file
  closeFile();
  const char* name = fileName_.c_str();
  // A regular file at the target is exchanged with the new one, and then removed from the
  // private folder, rather than renamed over: ext4 starts writing the new file to disk inside
  // a rename over an existing one (auto_da_alloc), 0.7 ms for a PNG of 760 KB on this machine
  // (docs/performance.md, Outputs).
  bool placed = false;
  if (isRegularFile(target_) &&
      ::renameat2(folderFd_, name, AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) == 0) {
    struct stat old {};
    placed = ::fstatat(folderFd_, name, &old, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(old.st_mode);
    // Something else took the target's place since it was looked at: it goes back.
    if (!placed) ::renameat2(folderFd_, name, AT_FDCWD, target_.c_str(), RENAME_EXCHANGE);
  }
  // Else a rename, which replaces a symbolic link at the target (never writing through it)
  // and fails on a folder.
  if (!placed && ::renameat(folderFd_, name, AT_FDCWD, target_.c_str()) != 0)
    fail(std::string("cannot replace file: ") + std::strerror(errno));
  removeAll();  // the old file, now in the private folder, and the folder
}

std::string OutputFile::diskFullNote() const {
  struct statvfs fs {};
  if (folderFd_ < 0 || ::fstatvfs(folderFd_, &fs) != 0) return "";
  // root may also fill the blocks kept for it.
  const uint64_t blocks = ::geteuid() == 0 ? fs.f_bfree : fs.f_bavail;
  return blocks * fs.f_frsize < (uint64_t(1) << 20) ? " (no space left on device)" : "";
}

void OutputFile::fail(const std::string& reason) const {
  throw InputError(target_.string() + ": " + reason);
}

void OutputFile::removeAll() {
  if (stream_)
    std::fclose(stream_);
  else if (fd_ >= 0)
    ::close(fd_);
  stream_ = nullptr;
  fd_ = -1;
  if (folderFd_ >= 0) {
    ::unlinkat(folderFd_, fileName_.c_str(), 0);
    inFlight_.fileMade.store(false);
    ::close(folderFd_);
    folderFd_ = -1;
  }
  if (inFlight_.folderMade.load()) {
    ::rmdir(inFlight_.folder.c_str());
    inFlight_.folderMade.store(false);
  }
  if (listed_) unlistInFlight(&inFlight_);
  listed_ = false;
}

void checkWritable(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw InputError(path.string() + ": cannot write file (a folder has that name)");
  const OutputFile probe(path);  // makes the missing parent folders, as the write will
}

void checkDistinctOutputs(const std::vector<NamedOutput>& outputs) {
  std::map<fs::path, const NamedOutput*> seen;
  std::map<fs::path, fs::path>
      folders;  // each folder resolved once: a turntable's frames share one
  for (const NamedOutput& output : outputs) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(output.path, ec);
    auto folder = folders.find(absolute.parent_path());
    if (folder == folders.end()) {
      const fs::path resolved = fs::weakly_canonical(absolute.parent_path(), ec);
      folder =
          folders.emplace(absolute.parent_path(), ec ? absolute.parent_path() : resolved).first;
    }
    const auto [it, fresh] = seen.emplace(folder->second / absolute.filename(), &output);
    if (!fresh) {
      throw InputError(std::string("command line: ") + it->second->option + " and " +
                       output.option + " both name " + output.path.string());
    }
  }
}

void writeFileAtomically(const fs::path& path, const std::string& bytes) {
  OutputFile file(path);
  file.write(bytes.data(), bytes.size());
  file.commit();
}

void appendFileAtomically(const fs::path& path, const std::string& bytes) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(path, ec);
  std::string whole;
  if (fs::is_regular_file(status)) {
    // A step summary is kilobytes; the limit keeps a mistaken target from filling memory.
    const FileText old(path.string(), size_t(64) << 20);
    whole = old.text();
  }
  writeFileAtomically(path, whole + bytes);
}

}  // namespace zrender
