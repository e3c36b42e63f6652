#include "zrender/cli/NameTemplate.hpp"

#include <cctype>

#include "zrender/base/Error.hpp"

namespace zrender {

namespace {

constexpr int kMaxWidth = 9;  // digits of a view number's width

}  // namespace

NameTemplate::NameTemplate(const std::string& pattern, const std::string& option, bool printfViews)
    : pattern_(pattern) {
  if (printfViews && pattern.find('{') == std::string::npos && parsePrintf()) return;
  parseBraces(option);
}

// The turntable's form: exactly one %d, %0Nd or %Nd, and %% for a percent sign. False (and no
// pieces) when the pattern is not of that form.
bool NameTemplate::parsePrintf() {
  std::vector<Piece> pieces(1);
  int directives = 0;
  for (size_t i = 0; i < pattern_.size(); ++i) {
    if (pattern_[i] != '%') {
      pieces.back().text += pattern_[i];
      continue;
    }
    if (i + 1 < pattern_.size() && pattern_[i + 1] == '%') {
      pieces.back().text += '%';
      ++i;
      continue;
    }
    Piece view;
    view.kind = Kind::View;
    size_t j = i + 1;
    if (j < pattern_.size() && pattern_[j] == '0') view.zeros = true, ++j;
    const size_t digits = j;
    while (j < pattern_.size() && std::isdigit(static_cast<unsigned char>(pattern_[j]))) ++j;
    if (j >= pattern_.size() || pattern_[j] != 'd' || j - digits > 1) return false;
    if (j > digits) view.width = pattern_[digits] - '0';
    pieces.push_back(view);
    pieces.emplace_back();
    ++directives;
    i = j;
  }
  if (directives != 1) return false;
  pieces_ = std::move(pieces);
  hasView_ = true;
  return true;
}

void NameTemplate::parseBraces(const std::string& option) {
  const auto bad = [&](const std::string& what) {
    throw InputError("command line: " + option + ": " + what + " in '" + pattern_ +
                     "' (fields: {scene} {alg} {shading} {view} {view:04}; {{ and }} for braces)");
  };
  pieces_.assign(1, Piece{});
  for (size_t i = 0; i < pattern_.size(); ++i) {
    const char c = pattern_[i];
    if ((c == '{' || c == '}') && i + 1 < pattern_.size() && pattern_[i + 1] == c) {
      pieces_.back().text += c;
      ++i;
      continue;
    }
    if (c == '}') bad("a lone '}'");
    if (c != '{') {
      pieces_.back().text += c;
      continue;
    }
    const size_t close = pattern_.find('}', i);
    if (close == std::string::npos) bad("a '{' without its '}'");
    const std::string field = pattern_.substr(i + 1, close - i - 1);
    Piece piece;
    if (field == "scene") {
      piece.kind = Kind::Scene;
    } else if (field == "alg") {
      piece.kind = Kind::Algorithm;
    } else if (field == "shading") {
      piece.kind = Kind::Shading;
    } else if (field.rfind("view", 0) == 0) {
      piece.kind = Kind::View;
      std::string spec = field.substr(4);
      if (!spec.empty()) {
        if (spec[0] != ':' || spec.size() < 2) bad("a bad field {" + field + "}");
        spec.erase(0, 1);
        if (spec[0] == '0' && spec.size() > 1) piece.zeros = true, spec.erase(0, 1);
        for (char d : spec)
          if (!std::isdigit(static_cast<unsigned char>(d))) bad("a bad field {" + field + "}");
        if (spec.size() > 1 || std::stoi(spec) > kMaxWidth)
          bad("a width above " + std::to_string(kMaxWidth));
        piece.width = std::stoi(spec);
      }
      hasView_ = true;
    } else {
      bad("an unknown field {" + field + "}");
    }
    pieces_.push_back(piece);
    pieces_.emplace_back();
    i = close;
  }
}

std::filesystem::path NameTemplate::expand(const NameFields& fields) const {
  std::string name;
  for (const Piece& piece : pieces_) {
    switch (piece.kind) {
      case Kind::Text:
        name += piece.text;
        break;
      case Kind::Scene:
        name += fields.scene;
        break;
      case Kind::Algorithm:
        name += fields.algorithm;
        break;
      case Kind::Shading:
        name += fields.shading;
        break;
      case Kind::View: {
        const std::string number = std::to_string(fields.view);
        if (int(number.size()) < piece.width)
          name.append(size_t(piece.width) - number.size(), piece.zeros ? '0' : ' ');
        name += number;
        break;
      }
    }
  }
  return name;
}

}  // namespace zrender
