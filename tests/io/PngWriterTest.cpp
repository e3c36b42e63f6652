// PNG files encoded in strips on several threads (PngWriter): whatever the size, type, strip
// height and number of threads, the file is a valid PNG (chunks and CRCs, one zlib stream whose
// Adler-32 holds) of unfiltered rows, and decodes, by OpenCV and by libpng, to exactly the
// pixels given; a failed write leaves nothing and says why.

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/core/mat.hpp>

#include "support/PngFiles.hpp"
#include "support/TestImages.hpp"
#include "support/TestSupport.hpp"
#include "zrender/base/Error.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/io/images/ImageCodecs.hpp"
#include "zrender/io/images/ImageOutput.hpp"
#include "zrender/io/images/PngWriter.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

const int kThreadCounts[] = {1, 2, 3, 7};

// Random samples (fixed seed) of the given type.
cv::Mat noise(int width, int height, int type) {
  cv::Mat image(height, width, type);
  cv::RNG rng(uint64(width) * 7919 + uint64(height) * 31 + uint64(type));
  rng.fill(image, cv::RNG::UNIFORM, 0, image.depth() == CV_16U ? 65536 : 256);
  return image;
}

// Everything a reader can check of the PNG file at `path`, which should hold `image`.
void expectPngOf(const std::string& path, const cv::Mat& image) {
  const test::PngParts parts = test::readPngParts(path);
  ASSERT_TRUE(parts.signatureOk);
  ASSERT_GE(parts.chunks.size(), 3u);
  EXPECT_EQ(parts.chunks.front().type, "IHDR");
  EXPECT_EQ(parts.chunks.back().type, "IEND");
  EXPECT_TRUE(parts.endsAtIend);
  for (size_t i = 0; i < parts.chunks.size(); ++i) {
    const test::PngChunk& c = parts.chunks[i];
    EXPECT_TRUE(c.crcOk) << c.type << " chunk " << i;
    if (i > 0 && i + 1 < parts.chunks.size()) {
      EXPECT_EQ(c.type, "IDAT");
    }
    if (c.type == "IDAT") {
      EXPECT_LE(c.length, kPngChunkBytes);
    }
  }
  EXPECT_EQ(parts.width, image.cols);
  EXPECT_EQ(parts.height, image.rows);
  EXPECT_EQ(parts.bitDepth, image.depth() == CV_16U ? 16 : 8);
  EXPECT_EQ(parts.colorType, image.channels() == 3 ? 2 : 0);
  EXPECT_EQ(parts.compression, 0);
  EXPECT_EQ(parts.filter, 0);
  EXPECT_EQ(parts.interlace, 0);
  EXPECT_EQ(parts.uncompressStatus, 0);  // Z_OK: one zlib stream, its Adler-32 right
  EXPECT_TRUE(parts.inflated == test::unfilteredRows(image)) << "the rows inflated differ";

  EXPECT_TRUE(samePixels(test::imread(path, cv::IMREAD_UNCHANGED), image)) << "OpenCV";
  std::string error;
  const cv::Mat decoded = test::readPngWithLibpng(path, error);
  EXPECT_EQ(error, "");
  EXPECT_TRUE(samePixels(decoded, image)) << "libpng";
}

// `image` encoded into `path` by encodePng with strips of about `stripBytes`.
void encodeInto(const std::string& path, const cv::Mat& image, const Threads& threads,
                size_t stripBytes) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  std::string error;
  EXPECT_TRUE(encodePng(file, image, threads, error, stripBytes)) << error;
  EXPECT_EQ(std::fclose(file), 0);
}

struct Case {
  const char* name;
  cv::Mat image;
};

std::vector<Case> oddImages() {
  return {
      {"1x1", noise(1, 1, CV_8UC3)},
      {"3x1000", noise(3, 1000, CV_8UC3)},
      {"1000x3", noise(1000, 3, CV_8UC3)},
      {"1801x37", noise(1801, 37, CV_8UC3)},
      {"one color 1801x900", cv::Mat(900, 1801, CV_8UC3, cv::Scalar(40, 150, 220))},
      {"gray 333x77", noise(333, 77, CV_8UC1)},
      {"depth 1x1", noise(1, 1, CV_16UC1)},
      {"depth 1801x37", noise(1801, 37, CV_16UC1)},
  };
}

TEST(PngWriter, OddSizesAndTypesDecodeToTheirPixels) {
  TempDir dir;
  for (const int count : kThreadCounts) {
    const Threads threads(count);
    for (const Case& c : oddImages()) {
      SCOPED_TRACE(std::string(c.name) + ", threads " + std::to_string(count));
      writeImageAtomically(dir.file("a.png"), c.image, &threads);
      expectPngOf(dir.file("a.png"), c.image);
    }
  }
}

TEST(PngWriter, ManyStripsJoinIntoOneStream) {
  // Strips of one row (stripBytes 1), of a few rows, and of rows that do not divide the height:
  // every join between strips is crossed, by threads that finish in any order.
  TempDir dir;
  const size_t stripSizes[] = {1, 700, 5000};
  for (const int count : kThreadCounts) {
    const Threads threads(count);
    for (const Case& c : oddImages()) {
      for (const size_t stripBytes : stripSizes) {
        SCOPED_TRACE(std::string(c.name) + ", threads " + std::to_string(count) + ", strips of " +
                     std::to_string(stripBytes) + " bytes");
        encodeInto(dir.file("s.png"), c.image, threads, stripBytes);
        expectPngOf(dir.file("s.png"), c.image);
      }
    }
  }
}

// Rows like a render's: flat background, runs of a few colors, gradients, repeats; the
// deflater finds matches in them (in noise it finds none).
cv::Mat picture(int width, int height) {
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(40, 30, 20));
  for (int y = 0; y < height; ++y) {
    for (int x = width / 5; x < width - width / 7; ++x) {
      const int band = (x / 37 + y / 23) % 5;
      image.at<cv::Vec3b>(y, x) =
          band == 0 ? cv::Vec3b(uchar(x), uchar(y), uchar(x + y))
                    : cv::Vec3b(uchar(60 * band), uchar(255 - 40 * band), uchar(band * y / 8));
    }
  }
  return image;
}

TEST(PngWriter, TheFileDoesNotDependOnTheThreads) {
  TempDir dir;
  for (const cv::Mat& image : {noise(640, 480, CV_8UC3), picture(1800, 700)}) {
    writeImageAtomically(dir.file("one.png"), image);  // no threads given: one
    const std::string one = test::readFile(dir.file("one.png"));
    expectPngOf(dir.file("one.png"), image);
    for (const int count : kThreadCounts) {
      const Threads threads(count);
      for (int again = 0; again < 3; ++again) {  // threads finish in another order each time
        SCOPED_TRACE(std::to_string(count) + " threads, time " + std::to_string(again));
        writeImageAtomically(dir.file("n.png"), image, &threads);
        EXPECT_TRUE(test::readFile(dir.file("n.png")) == one);
      }
    }
  }
}

TEST(PngWriter, NoiseSpansSeveralChunks) {
  // 1801 x 300 random colors: 1.6 MB that level 1 cannot shrink, more than one IDAT chunk.
  TempDir dir;
  const cv::Mat image = noise(1801, 300, CV_8UC3);
  const Threads threads(2);
  writeImageAtomically(dir.file("n.png"), image, &threads);
  expectPngOf(dir.file("n.png"), image);
  size_t idats = 0;
  for (const test::PngChunk& c : test::readPngParts(dir.file("n.png")).chunks)
    idats += c.type == "IDAT";
  EXPECT_GE(idats, 2u);
}

TEST(PngWriter, AFullDeviceGivesItsReason) {
  // A large file fails while written, a small one only when the stream's buffer is flushed.
  for (const int count : {1, 2}) {
    for (const int size : {300, 4}) {
      SCOPED_TRACE(std::to_string(count) + " threads, size " + std::to_string(size));
      std::FILE* full = std::fopen("/dev/full", "wb");
      ASSERT_NE(full, nullptr);
      std::string error;
      EXPECT_FALSE(encodePng(full, noise(size, size, CV_8UC3), Threads(count), error));
      EXPECT_EQ(error, std::strerror(ENOSPC));
      std::fclose(full);
    }
  }
}

TEST(PngWriter, AWriteCutShortLeavesTheOldFile) {
  // Files of this process limited to 4 KB: the write stops part way with EFBIG (the signal it
  // would also send ignored), as on a full disk; the old file stays, no temporary is left.
  TempDir dir;
  const std::string old = "the previous picture\n";
  const std::string path = dir.write("out.png", old);
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = saved;
  small.rlim_cur = 4096;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  for (const int count : {1, 2}) {
    const Threads threads(count);
    try {
      writeImageAtomically(path, noise(256, 256, CV_8UC3), &threads);
    } catch (const InputError& e) {
      message += std::string(e.what()) + "\n";
    }
  }
  setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, oldHandler);
  const std::string expected = path + ": cannot write file: " + std::strerror(EFBIG) + "\n";
  EXPECT_EQ(message, expected + expected);
  EXPECT_TRUE(test::readFile(path) == old) << "the old file was replaced";
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()), 1);
}

TEST(PngWriter, ImpossiblePathsAndTypesFailAsBefore) {
  TempDir dir;
  dir.write("file", "a regular file\n");
  const Threads threads(2);
  const cv::Mat image(4, 4, CV_8UC3, cv::Scalar(1, 2, 3));
  try {
    writeImageAtomically(dir.file("file/x.png"), image, &threads);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(dir.file("file/x.png") + ": cannot create folder: ", 0),
              0u)
        << e.what();
  }
  try {
    writeImageAtomically(dir.file("f.png"), cv::Mat(4, 4, CV_32FC1, 0.5), &threads);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), dir.file("f.png") + ": PNG cannot hold this image type");
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()), 1);
}

}  // namespace
}  // namespace zrender
