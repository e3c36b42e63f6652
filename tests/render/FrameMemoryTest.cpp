// Frame buffers made ahead of a renderer (FrameMemory, Renderer::adoptMemory): their pages
// faulted in part by part, adopted as they are when the frame has their size, whatever they
// hold, and the frames drawn into them the same as into the renderer's own.

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "support/TestSupport.hpp"
#include "zrender/render/FrameMemory.hpp"
#include "zrender/render/Renderer.hpp"

namespace zrender {
namespace {

// Buffers whose pages were faulted in, then filled with what no frame would leave: the
// nearest key there is and a gray, which a renderer that relied on them would show.
FrameMemory touched(int width, int height, int msaa) {
  FrameMemory m(width, height, msaa);
  for (size_t part = 0; part < m.parts(); ++part) m.touchPart(part);
  std::fill(m.buffer.data(), m.buffer.data() + m.buffer.size(), DepthKey(0));
  m.color.image().setTo(cv::Scalar::all(7));
  return m;
}

// How many of the pages of [data, data + bytes) are in memory (mincore).
size_t residentPages(const void* data, size_t bytes) {
  const size_t page = size_t(sysconf(_SC_PAGESIZE));
  const auto begin = reinterpret_cast<uintptr_t>(data) / page * page;
  const size_t length = reinterpret_cast<uintptr_t>(data) + bytes - begin;
  std::vector<unsigned char> resident((length + page - 1) / page);
  if (mincore(reinterpret_cast<void*>(begin), length, resident.data()) != 0) return 0;
  return size_t(std::count_if(resident.begin(), resident.end(),
                              [](unsigned char r) { return (r & 1) != 0; }));
}

TEST(FrameMemory, BuffersHaveTheFramesSize) {
  for (int msaa : {1, 4}) {
    const FrameMemory m(7, 5, msaa);
    const int scale = msaa == 4 ? 2 : 1;
    EXPECT_EQ(m.buffer.width(), 7 * scale);
    EXPECT_EQ(m.buffer.height(), 5 * scale);
    EXPECT_EQ(m.color.image().cols, 7);
    EXPECT_EQ(m.color.image().rows, 5);
    EXPECT_EQ(m.color.image().type(), CV_8UC3);
  }
}

// Buffers of several parts each, in new memory: not in memory before, every page of both in
// memory once every part was touched.
TEST(FrameMemory, PartsFaultInEveryPage) {
  FrameMemory m(1000, 900, 4);  // 28.8 MB of keys, 2.7 MB of color
  ASSERT_EQ(m.parts(), 14u + 2u);
  const size_t keyBytes = m.buffer.size() * sizeof(DepthKey);
  const size_t colorBytes = m.color.image().total() * m.color.image().elemSize();
  const size_t page = size_t(sysconf(_SC_PAGESIZE));
  EXPECT_LT(residentPages(m.buffer.data(), keyBytes), keyBytes / page / 2);
  EXPECT_LT(residentPages(m.color.image().data, colorBytes), colorBytes / page / 2);
  for (size_t part = 0; part < m.parts(); ++part) m.touchPart(part);
  EXPECT_EQ(residentPages(m.buffer.data(), keyBytes), (keyBytes + page - 1) / page);
  EXPECT_EQ(residentPages(m.color.image().data, colorBytes), (colorBytes + page - 1) / page);
}

TEST(FrameMemory, AColorImageKeepsItsPixelsWhereTheyAreWhenMoved) {
  ColorImage a;
  EXPECT_TRUE(a.resize(4, 3));
  EXPECT_FALSE(a.resize(4, 3));  // the same size: the same memory
  a.image().setTo(cv::Scalar(1, 2, 3));
  const unsigned char* pixels = a.image().data;
  ColorImage b(std::move(a));
  EXPECT_EQ(b.image().data, pixels);
  EXPECT_EQ(b.image().at<cv::Vec3b>(2, 3), cv::Vec3b(1, 2, 3));
  EXPECT_TRUE(b.resize(3, 4));  // another size: new memory
  EXPECT_EQ(b.image().cols, 3);
  EXPECT_EQ(b.image().rows, 4);
}

// A frame drawn into adopted buffers, of the frame's size or another, against one drawn into
// the renderer's own, on one thread and on two.
TEST(FrameMemory, FramesInAdoptedBuffersAreTheSame) {
  auto mesh = test::randomSoup(7, 60, true);
  for (int msaa : {1, 4}) {
    SceneSettings s = test::tinySettings(24);
    s.msaa = msaa;
    const Scene scene = makeScene(s, mesh);
    const Camera camera = makeCamera(scene);
    for (int threads : {1, 2}) {
      Renderer own(scene, "zbuffer", threads);
      own.renderFrame(camera);
      for (int size : {24, 17}) {
        Renderer adopting(scene, "zbuffer", threads);
        adopting.adoptMemory(touched(size, size, msaa));
        // Not cleared between frames either: a second frame finds the first one's keys.
        for (int frame = 0; frame < 2; ++frame) {
          adopting.renderFrame(camera);
          EXPECT_TRUE(
              identicalFrames(own.buffer(), own.color(), adopting.buffer(), adopting.color()))
              << "msaa " << msaa << ", threads " << threads << ", made for " << size << ", frame "
              << frame;
        }
      }
    }
  }
}

}  // namespace
}  // namespace zrender
