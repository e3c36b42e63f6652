#include "zrender/io/files/FileText.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <string>

#include "zrender/base/Error.hpp"

namespace zrender {

namespace {

// Closes a descriptor when it goes out of scope.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

FileText::FileText(const std::string& path, size_t maxBytes) {
  const auto tooLarge = [&] {
    return InputError(path + ": file too large (over " + std::to_string(maxBytes >> 20) + " MiB)");
  };
  const Descriptor in{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (in.fd < 0) throw InputError(path + ": cannot open file");
  struct stat status {};
  if (::fstat(in.fd, &status) != 0) throw InputError(path + ": cannot read file");
  if (S_ISDIR(status.st_mode)) throw InputError(path + ": cannot open file (it is a folder)");
  if (S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode))
    throw InputError(path + ": cannot read a device as a file");
  if (S_ISREG(status.st_mode) && uint64_t(status.st_size) > maxBytes) throw tooLarge();
  // A regular file is mapped at the size it has now: what is appended later is not read.
  if (S_ISREG(status.st_mode) && status.st_size > 0) {
    size_ = static_cast<size_t>(status.st_size);
    void* map = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, in.fd, 0);
    if (map != MAP_FAILED) {
      mapped_ = static_cast<const char*>(map);
      return;
    }
    size_ = 0;
  }
  // Not mappable (a pipe, an empty or special file): read to its end.
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(in.fd, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(path + ": cannot read file");
    if (read_.size() + size_t(n) > maxBytes) throw tooLarge();
    read_.append(buffer, static_cast<size_t>(n));
  }
}

FileText::~FileText() {
  if (mapped_) ::munmap(const_cast<char*>(mapped_), size_);
}

}  // namespace zrender
