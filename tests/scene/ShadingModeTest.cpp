// The names of the shading modes (ShadingMode; docs/design.md, Faces, ids and shading): in the
// documented order, parsed and printed back, unknown ones rejected.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "zrender/scene/ShadingMode.hpp"

namespace zrender {
namespace {

TEST(ShadingMode, NamesInDocumentedOrderAndRoundTrip) {
  const std::vector<std::string> expected{"normal",  "flat", "phong", "random",
                                          "texture", "id",   "depth"};
  EXPECT_EQ(shadingModeNames(), expected);
  EXPECT_EQ(parseShadingMode("normal"), ShadingMode::Normal);
  EXPECT_EQ(parseShadingMode("texture"), ShadingMode::Texture);
  EXPECT_EQ(parseShadingMode("depth"), ShadingMode::Depth);
  EXPECT_EQ(shadingModeName(ShadingMode::Flat), "flat");
  EXPECT_EQ(shadingModeName(ShadingMode::Id), "id");
  for (const auto& name : expected) {
    const auto mode = parseShadingMode(name);
    ASSERT_TRUE(mode.has_value()) << name;
    EXPECT_EQ(shadingModeName(*mode), name);
  }
}

TEST(ShadingMode, UnknownNamesAreRejected) {
  EXPECT_FALSE(parseShadingMode("gouraud").has_value());
  EXPECT_FALSE(parseShadingMode("Normal").has_value());  // names are case-sensitive
  EXPECT_FALSE(parseShadingMode("").has_value());
}

}  // namespace
}  // namespace zrender
