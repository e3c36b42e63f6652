// Reading a model file (FileText): bounded, whatever the file is.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <string>
#include <thread>

#include "support/TestSupport.hpp"
#include "zrender/base/Error.hpp"
#include "zrender/io/files/FileText.hpp"

namespace zrender {
namespace {

std::string errorOf(const std::string& path, size_t maxBytes) {
  try {
    FileText text(path, maxBytes);
    return "read " + std::to_string(text.text().size()) + " bytes";
  } catch (const InputError& e) {
    return e.what();
  }
}

TEST(FileText, AFileOverTheLimitIsRefused) {
  test::TempDir dir;
  dir.write("a.obj", std::string(3 << 20, 'v'));
  EXPECT_EQ(errorOf(dir.file("a.obj"), 3 << 20), "read 3145728 bytes");
  EXPECT_EQ(errorOf(dir.file("a.obj"), 2 << 20),
            dir.file("a.obj") + ": file too large (over 2 MiB)");
}

TEST(FileText, APipeIsReadUpToTheLimitOnly) {
  // A writer that would go on for ever: the reader stops past the limit, and the writer then
  // gets EPIPE.
  test::TempDir dir;
  const std::string fifo = dir.file("endless.obj");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] {
    sigset_t pipe;  // EPIPE rather than the signal, which would end the tests
    sigemptyset(&pipe);
    sigaddset(&pipe, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe, nullptr);
    const int fd = ::open(fifo.c_str(), O_WRONLY);
    const std::string chunk(1 << 16, 'v');
    while (fd >= 0 && ::write(fd, chunk.data(), chunk.size()) > 0) {
    }
    if (fd >= 0) ::close(fd);
  });
  EXPECT_EQ(errorOf(fifo, 1 << 20), fifo + ": file too large (over 1 MiB)");
  writer.join();
}

TEST(FileText, ADeviceIsRefused) {
  EXPECT_EQ(errorOf("/dev/zero", 1 << 20), "/dev/zero: cannot read a device as a file");
}

}  // namespace
}  // namespace zrender
