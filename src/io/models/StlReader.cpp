#include "zrender/io/models/StlReader.hpp"

#include <charconv>
#include <cstdint>
#include <cstring>

#include "zrender/base/Error.hpp"
#include "zrender/io/models/ModelFormats.hpp"
#include "zrender/io/models/PositionIndex.hpp"
#include "zrender/io/obj/ObjLoader.hpp"
#include "zrender/io/obj/ObjScanner.hpp"

namespace zrender {

namespace {

Mesh readBinary(std::string_view bytes) {
  const uint32_t count = littleEndian32(bytes, 80);
  Mesh mesh;
  PositionIndex index(mesh.positions);
  mesh.corners.reserve(size_t(count) * 3);
  mesh.faceStart.reserve(size_t(count) + 1);
  mesh.faceStart.push_back(0);
  const char* p = bytes.data() + 84;
  for (uint32_t t = 0; t < count; ++t, p += 50) {
    float v[9];
    std::memcpy(v, p + 12, sizeof v);  // after the facet normal
    for (int c = 0; c < 3; ++c) {
      Corner corner;
      corner.position = index.find(Vec3(v[3 * c], v[3 * c + 1], v[3 * c + 2]));
      mesh.corners.push_back(corner);
    }
    mesh.faceStart.push_back(uint32_t(mesh.corners.size()));
  }
  mesh.faceMaterial.assign(count, -1);
  return mesh;
}

// ASCII STL, word by word: a `vertex` word and three numbers add a corner to the facet being
// read, `endloop` ends it; every other word (solid and its name, facet normal and its numbers,
// outer, loop, endfacet, endsolid) is read past.
class AsciiStl {
 public:
  AsciiStl(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  Mesh read() {
    Mesh mesh;
    PositionIndex index(mesh.positions);
    mesh.faceStart.push_back(0);
    std::string_view word;
    while (next(word)) {
      if (word == "vertex") {
        double v[3];
        for (double& x : v) {
          if (!next(word)) fail("a vertex with fewer than 3 numbers");
          const char* first = word.data() + (word[0] == '+' ? 1 : 0);
          const auto [ptr, ec] = std::from_chars(first, word.data() + word.size(), x);
          if (ec == std::errc::result_out_of_range) {
            fail("NaN or infinite coordinate (a number overflows)");
          } else if (ec != std::errc() || ptr != word.data() + word.size()) {
            fail("malformed number '" + quoteName(word) + "'");
          }
        }
        if (mesh.corners.size() - mesh.faceStart.back() >= kMaxFaceCorners)
          fail("a facet of more than " + std::to_string(kMaxFaceCorners) + " vertices");
        Corner corner;
        corner.position = index.find(Vec3(v[0], v[1], v[2]));
        mesh.corners.push_back(corner);
      } else if (word == "endloop" && mesh.corners.size() > mesh.faceStart.back()) {
        mesh.faceStart.push_back(uint32_t(mesh.corners.size()));
        mesh.faceMaterial.push_back(-1);
      }
    }
    if (mesh.corners.size() > mesh.faceStart.back()) fail("the last facet has no endloop");
    return mesh;
  }

 private:
  bool next(std::string_view& word) {
    while (pos_ < text_.size() && std::strchr(" \t\r\n\f\v", text_[pos_]) && text_[pos_] != '\0') {
      line_ += text_[pos_] == '\n';
      ++pos_;
    }
    if (pos_ >= text_.size()) return false;
    size_t end = pos_;
    while (end < text_.size() && !std::strchr(" \t\r\n\f\v", text_[end])) ++end;
    if (end == pos_) ++end;  // a NUL: a word of its own, which no rule takes
    word = text_.substr(pos_, end - pos_);
    pos_ = end;
    return true;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(file_ + ":" + std::to_string(line_) + ": " + what);
  }

  std::string_view text_;
  const std::string& file_;
  size_t pos_ = 0, line_ = 1;
};

}  // namespace

Mesh readStl(std::string_view bytes, const std::string& file) {
  if (isBinaryStl(bytes, bytes.size())) return readBinary(bytes);
  return AsciiStl(bytes, file).read();
}

}  // namespace zrender
