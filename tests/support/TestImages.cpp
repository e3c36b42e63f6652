#include "support/TestImages.hpp"

#include <dlfcn.h>

#include <stdexcept>

namespace zrender::test {
namespace {

// The module's functions, looked up once; a missing module or symbol throws, which fails the
// test that called it.
struct TestCodecs {
  void (*imread)(const char*, int, cv::Mat*);
  bool (*imwrite)(const char*, const cv::Mat*);
  bool (*imencode)(const char*, const cv::Mat*, std::vector<unsigned char>*);
  int (*videoFrameCount)(const char*);
};

template <typename Function>
Function symbol(void* module, const char* name) {
  void* address = dlsym(module, name);
  if (!address) throw std::runtime_error(std::string(ZRENDER_TEST_CODECS) + " lacks " + name);
  return reinterpret_cast<Function>(address);
}

const TestCodecs& testCodecs() {
  static const TestCodecs codecs = [] {
    void* module = dlopen(ZRENDER_TEST_CODECS, RTLD_NOW | RTLD_LOCAL);
    if (!module) throw std::runtime_error(std::string("cannot load ") + dlerror());
    return TestCodecs{symbol<void (*)(const char*, int, cv::Mat*)>(module, "zrenderTestImread"),
                      symbol<bool (*)(const char*, const cv::Mat*)>(module, "zrenderTestImwrite"),
                      symbol<bool (*)(const char*, const cv::Mat*, std::vector<unsigned char>*)>(
                          module, "zrenderTestImencode"),
                      symbol<int (*)(const char*)>(module, "zrenderTestVideoFrameCount")};
  }();
  return codecs;
}

}  // namespace

cv::Mat imread(const std::string& path, int flags) {
  cv::Mat image;
  testCodecs().imread(path.c_str(), flags, &image);
  return image;
}

bool imwrite(const std::string& path, const cv::Mat& image) {
  return testCodecs().imwrite(path.c_str(), &image);
}

bool imencode(const std::string& ext, const cv::Mat& image, std::vector<unsigned char>& bytes) {
  return testCodecs().imencode(ext.c_str(), &image, &bytes);
}

int videoFrameCount(const std::string& path) {
  return testCodecs().videoFrameCount(path.c_str());
}

}  // namespace zrender::test
