#pragma once

#include <cstddef>
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

// zrender's exit statuses (the README, docs/design.md, Errors, and docs/bench.md list them).
enum ExitStatus : int {
  kExitSuccess = 0,
  kExitInternalError = 1,  // a bug or the machine (out of memory): not the user's input
  kExitBadInput = 2,       // InputError
  kExitCheckFailed = 3,    // a slowdown beyond --max-slowdown, or an image unlike --reference's
  kExitDisagree = 4,       // an algorithm's buffers differ from the z-buffer's
};

// The most bytes of one message line that zrender prints (an error or a warning, after its
// "zrender: error: " prefix): a message can carry a path or a list of any length.
inline constexpr size_t kMaxMessageBytes = 1000;

// `text` as one printed line: line breaks become spaces, trailing spaces go, and past
// kMaxMessageBytes the middle is cut to " ... ": the start names the file, the end says why.
std::string messageLine(std::string text);

// Non-fatal problems (an unknown settings key, a missing texture) collected while loading; the
// command line prints each as "zrender: warning: <text>".
using Warnings = std::vector<std::string>;

}  // namespace zrender
