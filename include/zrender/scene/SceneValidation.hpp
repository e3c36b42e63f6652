#pragma once

#include <array>
#include <map>
#include <string>

#include <opencv2/core.hpp>

#include "zrender/scene/SceneSettings.hpp"

namespace zrender {

// The rules of the settings keys (docs/design.md, Settings), shared by the settings file's
// reader and the check after command-line options, so that a value from either gets the same
// message. Each throws InputError "WHERE: key 'KEY': what is wrong".

constexpr long long kMaxInstances = 1000000;  // grid instances in all

bool isFiniteVec(const cv::Vec3d& v);
// A direction must survive v / |v|: a zero length, or one that under- or overflows, does not.
bool isUsableDirection(const cv::Vec3d& v);

void checkSize(const std::string& where, const std::string& key, int value);
// `nearBeforeFar`: whether far > near is checked here (not when fit supplies one of them, from
// the model: makeCamera checks it then).
void checkProjection(const std::string& where, double fovy, double aspect, double near, double far,
                     bool nearBeforeFar = true);
void checkMsaa(const std::string& where, int msaa);
void checkFinite(const std::string& where, const std::string& key, const cv::Vec3d& v);
void checkDirection(const std::string& where, const std::string& key, const cv::Vec3d& v);
void checkGridCount(const std::string& where, const std::array<int, 3>& count);

// For validateScene: the command-line options that set what a key's rule checks, by key
// ("project" -> "--near, --far"), so that an error names them as well as the scene.
using KeyOrigins = std::map<std::string, std::string>;

// Checks the cross-key rules (size range, near < far, fov range, eye present unless fit, ...)
// after command-line overrides; `where` prefixes messages ("settings.json: scene 'bunny'" or
// "command line"), followed by " with OPTIONS" when `origins` has the key. Throws InputError.
void validateScene(const SceneSettings& scene, const std::string& where,
                   const KeyOrigins& origins = {});

}  // namespace zrender
