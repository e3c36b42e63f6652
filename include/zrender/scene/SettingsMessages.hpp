#pragma once

#include <string>

#include <opencv2/core.hpp>

namespace zrender {

// The pieces of the settings' error messages, which name the file, the scene and the key
// (docs/design.md, Errors).

// `s` with control characters escaped, so that a message stays on one line whatever the file
// holds.
std::string printable(const std::string& s);

// The shortest text that reads back as the same double ("0.1", not "0.10000000000000001");
// whole numbers as written ("180").
std::string formatNumber(double v);

// "[x, y, z]" with formatNumber.
std::string formatVec(const cv::Vec3d& v);

// Throws InputError "WHERE: key 'KEY': WHAT".
[[noreturn]] void failKey(const std::string& where, const std::string& key,
                          const std::string& what);

}  // namespace zrender
