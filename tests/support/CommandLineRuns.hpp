#pragma once

// Helpers of the tests that run the built executable on the command line (cli/, e2e/).

#include <json/json.h>

#include <string>
#include <vector>

#include "support/TestSupport.hpp"

namespace zrender::test {

// A square [-1, 1]^2 at z = 0 facing +Z (counter-clockwise seen from +Z), as two triangles:
// f 1 2 3 (face 0, lower right) and f 1 3 4 (face 1, upper left).
extern const char* const kSquareObj;

// A settings file with one scene `sq` drawing `model` on a `size` x `size` image (32 x 32 by
// default), eye (0, 0, 2), project [90, 0, 0.1, 10]; `extra` is appended inside the scene
// object (", \"msaa\": 4").
std::string settingsFor(const std::string& model, const std::string& extra = "",
                        const std::string& size = "32");

// Whether `text` is `pattern` with each '#' standing for a number (one or more of 0-9 and '.'):
// the form of a line whose times vary from run to run. (std::regex trips GCC 12's
// maybe-uninitialized warning in the sanitizer build, where warnings are errors.)
bool matchesWithNumbers(const std::string& text, const std::string& pattern);

// One JSON object parsed from `text` (null, and a test failure naming the text, if it is not).
Json::Value parseJson(const std::string& text);

// Exit status 2 and one line on stderr, "zrender: error: ...", containing every piece of
// `mustName`.
void expectCleanError(const RunResult& r, const std::vector<std::string>& mustName);

}  // namespace zrender::test
