// Output names with fields (NameTemplate; docs/design.md, Views: names): {scene}, {alg},
// {shading}, {view} with a width, brace escapes, the turntable's printf form, and errors that
// name the option.

#include <gtest/gtest.h>

#include "zrender/base/Error.hpp"
#include "zrender/cli/NameTemplate.hpp"

namespace zrender {
namespace {

NameFields fields(size_t view) {
  NameFields f;
  f.scene = "bunny";
  f.algorithm = "octree";
  f.shading = "phong";
  f.view = view;
  return f;
}

std::string expand(const std::string& pattern, size_t view, bool printfViews = true) {
  return NameTemplate(pattern, "-o", printfViews).expand(fields(view)).string();
}

TEST(NameTemplate, FieldsAndWidths) {
  EXPECT_EQ(expand("out/{scene}-{alg}-{shading}-{view}.png", 7), "out/bunny-octree-phong-7.png");
  EXPECT_EQ(expand("{view:04}.png", 7), "0007.png");
  EXPECT_EQ(expand("{view:4}.png", 7), "   7.png");
  EXPECT_EQ(expand("{view:03}.png", 12345), "12345.png");
  EXPECT_EQ(expand("{{{view}}}.png", 3), "{3}.png");
  EXPECT_EQ(expand("plain.png", 3), "plain.png");
  EXPECT_TRUE(NameTemplate("{view:02}.png", "-o", true).hasView());
  EXPECT_FALSE(NameTemplate("{scene}.png", "-o", true).hasView());
}

TEST(NameTemplate, ThePrintfFormOnlyForSeveralViews) {
  EXPECT_EQ(expand("f/%03d.png", 7), "f/007.png");
  EXPECT_EQ(expand("f/%d%%.png", 7), "f/7%.png");
  EXPECT_EQ(expand("f/%3d.png", 7), "f/  7.png");
  EXPECT_EQ(expand("100%.png", 7, false), "100%.png");
  EXPECT_FALSE(NameTemplate("100%.png", "-o", false).hasView());
  // Two directives, or a string one, are not the printf form: plain characters, no view.
  EXPECT_FALSE(NameTemplate("%d-%d.png", "-o", true).hasView());
  EXPECT_FALSE(NameTemplate("f%5s.png", "-o", true).hasView());
  // Braces win: % is a plain character beside them.
  EXPECT_EQ(expand("{view}-%d.png", 2), "2-%d.png");
}

TEST(NameTemplate, BadFieldsNameTheOption) {
  for (const char* bad : {"{frame}.png", "{view.png", "x}.png", "{view:x}.png", "{view:10}.png",
                          "{view:}.png", "{}.png"}) {
    SCOPED_TRACE(bad);
    try {
      NameTemplate(bad, "--depth", true);
      FAIL() << "no error";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("command line: --depth: ", 0), 0u) << what;
      EXPECT_NE(what.find(bad), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace zrender
