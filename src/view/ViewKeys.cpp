#include "zrender/view/ViewKeys.hpp"

#include <algorithm>
#include <cctype>

#include "zrender/base/Error.hpp"

namespace zrender {

namespace {

// What viewKeysHelp says of each action.
const char* describe(ViewAction action) {
  switch (action) {
    case ViewAction::NextAlgorithm:
      return "next algorithm";
    case ViewAction::PickAlgorithm:
      return "zbuffer, scanline, interval, hierarchical, octree";
    case ViewAction::TiltUp:
      return "tilt the camera up, 10 degrees";
    case ViewAction::TiltDown:
      return "tilt the camera down, 10 degrees";
    case ViewAction::TurnLeft:
      return "turn the camera left, 15 degrees";
    case ViewAction::TurnRight:
      return "turn the camera right, 15 degrees";
    case ViewAction::Closer:
      return "move closer (distance x 0.8)";
    case ViewAction::Farther:
      return "move farther (distance x 1.25)";
    case ViewAction::TogglePause:
      return "pause or resume the orbit";
    case ViewAction::ToggleMsaa:
      return "MSAA 4 on or off";
    case ViewAction::NextShading:
      return "next shading mode";
    case ViewAction::ToggleCulling:
      return "back-face culling on or off";
    case ViewAction::SaveFrame:
      return "save the frame as SCENE-view-NNN.png (without the overlay)";
    case ViewAction::Quit:
      return "quit";
  }
  return "";
}

}  // namespace

const std::vector<ViewKey>& viewKeys() {
  static const std::vector<ViewKey> keys = {
      {' ', "space", ViewAction::NextAlgorithm, 0},
      {'1', "1", ViewAction::PickAlgorithm, 0},
      {'2', "2", ViewAction::PickAlgorithm, 1},
      {'3', "3", ViewAction::PickAlgorithm, 2},
      {'4', "4", ViewAction::PickAlgorithm, 3},
      {'5', "5", ViewAction::PickAlgorithm, 4},
      {'w', "w", ViewAction::TiltUp, 0},
      {'s', "s", ViewAction::TiltDown, 0},
      {'a', "a", ViewAction::TurnLeft, 0},
      {'d', "d", ViewAction::TurnRight, 0},
      {'+', "+", ViewAction::Closer, 0},
      {'=', "=", ViewAction::Closer, 0},
      {'-', "-", ViewAction::Farther, 0},
      {'p', "p", ViewAction::TogglePause, 0},
      {'m', "m", ViewAction::ToggleMsaa, 0},
      {'t', "t", ViewAction::NextShading, 0},
      {'c', "c", ViewAction::ToggleCulling, 0},
      {13, "enter", ViewAction::SaveFrame, 0},
      {'q', "q", ViewAction::Quit, 0},
      {27, "esc", ViewAction::Quit, 0},
  };
  return keys;
}

std::optional<ViewKey> viewKeyForCode(int code) {
  if (code >= 'A' && code <= 'Z') code += 'a' - 'A';
  for (const ViewKey& key : viewKeys())
    if (key.code == code) return key;
  return std::nullopt;
}

std::vector<ViewKey> parseViewKeys(const std::string& list, const char* option) {
  std::vector<ViewKey> keys;
  size_t start = 0;
  while (start <= list.size()) {
    const size_t comma = std::min(list.find(',', start), list.size());
    std::string name = list.substr(start, comma - start);
    for (char& c : name) c = char(std::tolower(static_cast<unsigned char>(c)));
    std::optional<ViewKey> key;
    if (name == "plus") name = "+";
    if (name == "minus") name = "-";
    for (const ViewKey& k : viewKeys())
      if (name == k.name) key = k;
    if (!key) {
      std::string names;
      for (const ViewKey& k : viewKeys()) names += (names.empty() ? "" : " ") + std::string(k.name);
      throw InputError("command line: " + std::string(option) + ": unknown key '" +
                       list.substr(start, comma - start) + "' (keys: " + names + ")");
    }
    keys.push_back(*key);
    start = comma + 1;
  }
  return keys;
}

std::string viewKeysHelp() {
  std::string help;
  for (size_t i = 0; i < viewKeys().size();) {
    // Keys of one action share a line ("1 2 3 4 5", "q esc").
    const ViewKey& first = viewKeys()[i];
    std::string names = first.name;
    size_t j = i + 1;
    while (j < viewKeys().size() && viewKeys()[j].action == first.action)
      names += std::string(" ") + viewKeys()[j++].name;
    names.resize(std::max<size_t>(names.size(), 12), ' ');
    help += "  " + names + describe(first.action) + "\n";
    i = j;
  }
  return help;
}

}  // namespace zrender
