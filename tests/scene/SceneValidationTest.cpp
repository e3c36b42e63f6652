// The rules of a scene's keys (validateScene; docs/design.md, Settings and Camera and
// transforms): the eye, up and target rules, the ranges, and projections that overflow.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "support/SettingsParsing.hpp"
#include "zrender/base/Error.hpp"
#include "zrender/io/settings/SettingsFile.hpp"
#include "zrender/scene/SceneValidation.hpp"

namespace zrender {
namespace {

using test::validateError;
using test::validScene;

TEST(SceneValidation, ValidateSceneEyeRules) {
  EXPECT_EQ(validateError(validScene()), "no error");

  SceneSettings noEye = validScene();
  noEye.eye.reset();
  EXPECT_EQ(validateError(noEye), "command line: key 'eye': missing (required unless fit is on)");
  noEye.fit = true;
  EXPECT_EQ(validateError(noEye), "no error");

  SceneSettings same = validScene();
  same.eye = cv::Vec3d(1, 2, 3);
  same.target = cv::Vec3d(1, 2, 3);
  EXPECT_EQ(validateError(same),
            "command line: key 'eye': must differ from target [1, 2, 3], got [1, 2, 3]");

  SceneSettings parallel = validScene();  // looks down -z
  parallel.up = cv::Vec3d(0, 0, -2);
  EXPECT_EQ(validateError(parallel),
            "command line: key 'up': must not be parallel to the viewing direction target - eye "
            "[0, 0, -5], got [0, 0, -2]");
  parallel.up = cv::Vec3d(0, 0.01, 1);  // nearly but not exactly parallel is allowed
  EXPECT_EQ(validateError(parallel), "no error");
}

TEST(SceneValidation, ValidateSceneRanges) {
  SceneSettings s = validScene();
  s.width = 0;
  EXPECT_EQ(validateError(s),
            "command line: key 'width': expected an integer from 1 to 16384, got 0");
  s = validScene();
  s.fovy = 180;
  EXPECT_EQ(validateError(s),
            "command line: key 'project': fovy must be greater than 0 and less than 180 degrees, "
            "got 180");
  s = validScene();
  s.near = 2;
  s.far = 2;
  EXPECT_EQ(validateError(s),
            "command line: key 'project': far must be greater than near, got "
            "near 2 and far 2");
  s = validScene();
  s.msaa = 2;
  EXPECT_EQ(validateError(s), "command line: key 'msaa': expected 1 or 4, got 2");
  s = validScene();
  s.up = cv::Vec3d(0, 0, 0);
  EXPECT_EQ(validateError(s), "command line: key 'up': must have a non-zero length, got [0, 0, 0]");
  s = validScene();
  s.axis = cv::Vec3d(0, std::numeric_limits<double>::infinity(), 0);
  EXPECT_EQ(validateError(s),
            "command line: key 'axis': expected 3 finite numbers, got [0, inf, 0]");
  s = validScene();
  s.eye = cv::Vec3d(0, std::nan(""), 5);
  EXPECT_EQ(validateError(s),
            "command line: key 'eye': expected 3 finite numbers, got [0, nan, 5]");
}

// Fovy 1e-320 and 1.4e-186 with fit (which replaces near and far): validation refuses them,
// naming the settings key rather than leaving makeCamera to fail naming the model. The two
// scenes are files of the settings fuzz corpus (regression-denormal-fovy-with-fit.json and
// regression-tiny-fovy-with-fit.json).
TEST(SceneValidation, TinyFovyWithFitNamesTheProjectKey) {
  for (const char* name :
       {"regression-denormal-fovy-with-fit.json", "regression-tiny-fovy-with-fit.json"}) {
    SCOPED_TRACE(name);
    std::ifstream in(std::string(ZRENDER_SOURCE_DIR "/fuzz/corpus/settings/") + name);
    std::stringstream text;
    text << in.rdbuf();
    Warnings warnings;
    const SettingsFile file = parseSettings(text.str(), "fuzz.json", warnings);
    ASSERT_EQ(file.scenes.size(), 1u);
    try {
      validateScene(file.scenes.begin()->second, "fuzz.json: scene 'far'");
      ADD_FAILURE() << "validateScene accepted the tiny fovy";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("key 'project'"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace zrender
