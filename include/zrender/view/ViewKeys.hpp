#pragma once

// The keys of `zrender view` (docs/design.md, The viewer): one table gives each key's code, its
// name in --keys and in the help, and what it does.

#include <optional>
#include <string>
#include <vector>

namespace zrender {

// What a key does to the viewer (ViewControls::press).
enum class ViewAction {
  NextAlgorithm,  // space
  PickAlgorithm,  // 1..5: the algorithm of that rank (makeAlgorithm's order)
  TiltUp,         // w
  TiltDown,       // s
  TurnLeft,       // a
  TurnRight,      // d
  Closer,         // + (or =, the same key without shift)
  Farther,        // -
  TogglePause,    // p
  ToggleMsaa,     // m
  NextShading,    // t
  ToggleCulling,  // c
  SaveFrame,      // enter
  Quit            // q, esc
};

// A key as the window reports it: the character for printable keys (lower case for letters, as
// OpenCV's waitKey gives them), 13 for enter, 27 for escape.
struct ViewKey {
  int code;
  const char* name;  // in --keys and in messages
  ViewAction action;
  int rank;  // PickAlgorithm: 0..4; otherwise 0
};

// Every key the viewer knows, in the order the help lists them.
const std::vector<ViewKey>& viewKeys();

// The key of a window key code (letters in either case), or nullopt for a key that does nothing.
std::optional<ViewKey> viewKeyForCode(int code);

// The keys named in a comma-separated list ("space,space,w,s,m,t,q"): the names of viewKeys(),
// letters in either case, "plus" and "minus" for + and -. Throws InputError naming `option` and
// the first unknown name.
std::vector<ViewKey> parseViewKeys(const std::string& list, const char* option);

// The keys table of `zrender view --help`, one line per key.
std::string viewKeysHelp();

}  // namespace zrender
