#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace zrender {

// Bad input from the user (a file, a setting, an option). The command line prints
// "zrender: error: " + what() on one line and exits with status 2. The message names the file
// and the line or key, then says what is wrong, e.g. "models/a.obj:12: vertex index 9 out of
// range".
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Non-fatal problems (an unknown settings key, a missing texture) collected while loading; the
// command line prints each as "zrender: warning: <text>".
using Warnings = std::vector<std::string>;

}  // namespace zrender
