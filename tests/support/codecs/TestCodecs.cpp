// OpenCV's image and video files for the tests (support/TestImages.hpp), built as
// libzrender_test_codecs.so and loaded by zrender_tests only when a test reads or writes one.

#include <vector>

#include <opencv2/core/mat.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

extern "C" {

__attribute__((visibility("default"))) void zrenderTestImread(const char* path, int flags,
                                                              cv::Mat* out) {
  *out = cv::imread(path, flags);
}

__attribute__((visibility("default"))) bool zrenderTestImwrite(const char* path,
                                                               const cv::Mat* image) {
  return cv::imwrite(path, *image);
}

__attribute__((visibility("default"))) bool zrenderTestImencode(const char* ext,
                                                                const cv::Mat* image,
                                                                std::vector<unsigned char>* bytes) {
  return cv::imencode(ext, *image, *bytes);
}

__attribute__((visibility("default"))) int zrenderTestVideoFrameCount(const char* path) {
  cv::VideoCapture video(path);
  if (!video.isOpened()) return -1;
  return int(video.get(cv::CAP_PROP_FRAME_COUNT));
}
}
