#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace zrender {

// What an output name's fields stand for (docs/design.md, Views: names).
struct NameFields {
  std::string scene, algorithm, shading;
  size_t view = 0;
};

// An output file name with fields: {scene}, {alg}, {shading}, {view} and {view:W} or {view:0W}
// (the view number padded to W characters with spaces or zeros, W up to 9); {{ and }} are
// literal braces. A printf pattern with one integer directive (frames/%03d.png, the turntable's
// form) is read as {view:03} when `printfViews` is set; otherwise % is a plain character.
class NameTemplate {
 public:
  NameTemplate() = default;
  // Throws InputError naming `option` for an unknown field or a lone brace.
  NameTemplate(const std::string& pattern, const std::string& option, bool printfViews);

  const std::string& pattern() const { return pattern_; }
  bool hasView() const { return hasView_; }
  std::filesystem::path expand(const NameFields& fields) const;

 private:
  enum class Kind { Text, Scene, Algorithm, Shading, View };
  struct Piece {
    Kind kind = Kind::Text;
    std::string text;  // Kind::Text
    int width = 0;     // Kind::View: the least number of characters
    bool zeros = false;
  };
  void parseBraces(const std::string& option);
  bool parsePrintf();

  std::string pattern_;
  std::vector<Piece> pieces_;
  bool hasView_ = false;
};

}  // namespace zrender
