// The triangles of a frame in bands of 32 sample rows (TriangleBands): sorted by the band of
// their first sample row (the first row whose centre is at or below the top corner, row 0 for a
// triangle reaching above the image), in submission order within a band, and the triangles that
// reach no sample of the image left out. Worked out by hand: row j has its centre at j + 0.5
// (sample units), and so does column i at i + 0.5.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "support/ScreenGeometry.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/raster/TriangleBands.hpp"

namespace zrender {
namespace {

using test::makeTriangle;

// A triangle over columns 2 to 30 whose rows run from `top` to `bottom` (sample units).
ScreenTriangle rows(double top, double bottom, uint32_t id) {
  return makeTriangle(2, top, 30, top, 16, bottom, id, 0.5);
}

// A triangle over rows 5 to 20 whose columns run from `left` to `right`.
ScreenTriangle columns(double left, double right, uint32_t id) {
  return makeTriangle(left, 5, right, 5, right, 20, id, 0.5);
}

// Triangles 0 to 15 for a 40 x 100 sample image: bands of rows 0-31, 32-63, 64-95 and 96-99.
FrameGeometry sixteenTriangles() {
  FrameGeometry g;
  g.width = 40;
  g.height = 100;
  g.triangles = {
      rows(40.2, 50, 0),       // first row 40: band 1
      rows(3, 10, 1),          // first row 3: band 0
      rows(96.6, 120, 2),      // first row 97, reaching below the image: band 3
      rows(-20, 5, 3),         // reaching above the image: first row 0, band 0
      rows(31.6, 33, 4),       // top in row 31 but its centre (31.5) above it: first row 32, band 1
      rows(31.4, 40, 5),       // first row 31: band 0
      rows(100.6, 110, 6),     // below the image: left out
      columns(-10, -0.6, 7),   // left of the image (last column -2): left out
      columns(39.6, 50, 8),    // right of the image (first column 40): left out
      columns(10.6, 11.4, 9),  // between the centres of columns 10 and 11: left out
      rows(20.6, 21.4, 10),    // between the centres of rows 20 and 21: left out
      rows(-10, -0.6, 11),     // above the image: left out
      rows(0, 100, 12),        // every row: band 0
      rows(64.2, 70, 13),      // first row 64: band 2
      rows(99.2, 99.8, 14),    // only row 99, the last of the image: band 3
      rows(63.6, 80, 15),      // first row 64: band 2
  };
  return g;
}

std::vector<uint32_t> idsOf(const GeometryVector<ScreenTriangle>& triangles) {
  std::vector<uint32_t> ids;
  for (const ScreenTriangle& t : triangles) ids.push_back(t.id);
  return ids;
}

std::vector<uint32_t> bandStarts(const TriangleBands& bands) {
  std::vector<uint32_t> starts;
  for (int b = 0; b <= bands.bandCount(); ++b) starts.push_back(bands.bandStart(b));
  return starts;
}

TEST(TriangleBands, SortedByTheBandOfTheirFirstSampleRowInSubmissionOrder) {
  EXPECT_EQ(TriangleBands::kBandShift, 5);  // bands of 32 rows
  const FrameGeometry g = sixteenTriangles();
  TriangleBands bands;
  const GeometryVector<ScreenTriangle>& sorted = bands.sort(g, g.width, g.height);
  EXPECT_EQ(idsOf(sorted), (std::vector<uint32_t>{1, 3, 5, 12, 0, 4, 13, 15, 2, 14}));
  ASSERT_EQ(bands.bandCount(), 4);
  EXPECT_EQ(bandStarts(bands), (std::vector<uint32_t>{0, 4, 6, 8, 10}));
  // Copies of the triangles, corners and all.
  for (const ScreenTriangle& t : sorted) {
    const ScreenTriangle& original = g.triangles[t.id];
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(t.v[k].x, original.v[k].x) << t.id;
      EXPECT_EQ(t.v[k].y, original.v[k].y) << t.id;
    }
  }
}

TEST(TriangleBands, TrianglesFromAnIndexOnAreSortedAlone) {
  // Triangles 6 to 15: of those, 12 (band 0), 13 and 15 (band 2) and 14 (band 3) reach the image.
  const FrameGeometry g = sixteenTriangles();
  TriangleBands bands;
  const GeometryVector<ScreenTriangle>& sorted = bands.sort(g, 6, g.width, g.height);
  EXPECT_EQ(idsOf(sorted), (std::vector<uint32_t>{12, 13, 15, 14}));
  ASSERT_EQ(bands.bandCount(), 4);
  EXPECT_EQ(bandStarts(bands), (std::vector<uint32_t>{0, 1, 1, 3, 4}));
}

TEST(TriangleBands, BandsFollowTheImageHeightFromOneSortToTheNext) {
  // The scratch kept from a sort of many bands does not leak into the next, smaller one.
  TriangleBands bands;
  const FrameGeometry big = sixteenTriangles();
  bands.sort(big, big.width, big.height);
  FrameGeometry small;
  small.width = 40;
  small.height = 32;  // one band
  small.triangles = {rows(10, 20, 5), rows(0, 5, 2), rows(31.6, 40, 9), rows(31.4, 40, 7)};
  const GeometryVector<ScreenTriangle>& sorted = bands.sort(small, small.width, small.height);
  EXPECT_EQ(idsOf(sorted), (std::vector<uint32_t>{5, 2, 7}));  // 9 starts below the image
  ASSERT_EQ(bands.bandCount(), 1);
  EXPECT_EQ(bandStarts(bands), (std::vector<uint32_t>{0, 3}));
  // 33 rows make two bands, the second of one row.
  small.height = 33;
  EXPECT_EQ(idsOf(bands.sort(small, small.width, small.height)),
            (std::vector<uint32_t>{5, 2, 7, 9}));
  ASSERT_EQ(bands.bandCount(), 2);
  EXPECT_EQ(bandStarts(bands), (std::vector<uint32_t>{0, 3, 4}));
}

}  // namespace
}  // namespace zrender
