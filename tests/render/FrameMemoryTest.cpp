// Frame buffers made ahead of a renderer (FrameMemory, Renderer::adoptMemory): written once,
// adopted as they are when the frame has their size, and the frames drawn into them the same
// as into the renderer's own.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <utility>

#include "support/TestSupport.hpp"
#include "zrender/render/FrameMemory.hpp"
#include "zrender/render/Renderer.hpp"

namespace zrender {
namespace {

FrameMemory touched(int width, int height, int msaa) {
  FrameMemory m(width, height, msaa);
  for (size_t part = 0; part < m.parts(); ++part) m.touchPart(part);
  return m;
}

TEST(FrameMemory, TouchedBuffersHoldTheClearKeyAndBlack) {
  for (int msaa : {1, 4}) {
    const FrameMemory m = touched(7, 5, msaa);
    const int scale = msaa == 4 ? 2 : 1;
    ASSERT_EQ(m.buffer.width(), 7 * scale);
    ASSERT_EQ(m.buffer.height(), 5 * scale);
    for (size_t i = 0; i < m.buffer.size(); ++i) ASSERT_EQ(m.buffer.data()[i], kClearKey);
    ASSERT_EQ(m.color.mat().cols, 7);
    ASSERT_EQ(m.color.mat().rows, 5);
    ASSERT_EQ(m.color.mat().type(), CV_8UC3);
    EXPECT_EQ(cv::countNonZero(m.color.mat().reshape(1)), 0);
  }
}

// Buffers of several parts each: every part written, every key and byte, once.
TEST(FrameMemory, PartsCoverEveryByte) {
  FrameMemory m(1000, 900, 4);  // 28.8 MB of keys, 2.7 MB of color
  ASSERT_EQ(m.parts(), 14u + 2u);
  std::fill(m.buffer.data(), m.buffer.data() + m.buffer.size(), DepthKey(0));
  m.color.mat().setTo(cv::Scalar::all(7));
  for (size_t part = 0; part < m.parts(); ++part) m.touchPart(part);
  EXPECT_EQ(std::count(m.buffer.data(), m.buffer.data() + m.buffer.size(), kClearKey),
            std::ptrdiff_t(m.buffer.size()));
  EXPECT_EQ(cv::countNonZero(m.color.mat().reshape(1)), 0);
}

TEST(FrameMemory, AColorImageKeepsItsPixelsWhereTheyAreWhenMoved) {
  ColorImage a;
  EXPECT_TRUE(a.resize(4, 3));
  EXPECT_FALSE(a.resize(4, 3));  // the same size: the same memory
  a.mat().setTo(cv::Scalar(1, 2, 3));
  const unsigned char* pixels = a.mat().data;
  ColorImage b(std::move(a));
  EXPECT_EQ(b.mat().data, pixels);
  EXPECT_EQ(b.mat().at<cv::Vec3b>(2, 3), cv::Vec3b(1, 2, 3));
  EXPECT_TRUE(b.resize(3, 4));  // another size: new memory
  EXPECT_EQ(b.mat().cols, 3);
  EXPECT_EQ(b.mat().rows, 4);
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
