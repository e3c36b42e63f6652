#include "zrender/io/models/PlyReader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "zrender/base/Error.hpp"
#include "zrender/io/obj/ObjLoader.hpp"
#include "zrender/io/obj/ObjScanner.hpp"

namespace zrender {

namespace {

enum class PlyType { Int8, Uint8, Int16, Uint16, Int32, Uint32, Float32, Float64 };

bool typeOf(std::string_view name, PlyType& type) {
  static const struct {
    const char* name;
    PlyType type;
  } types[] = {
      {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::Uint8},
      {"uint8", PlyType::Uint8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::Uint16},  {"uint16", PlyType::Uint16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},    {"uint", PlyType::Uint32},     {"uint32", PlyType::Uint32},
      {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (const auto& t : types) {
    if (name == t.name) {
      type = t.type;
      return true;
    }
  }
  return false;
}

size_t sizeOf(PlyType type) {
  switch (type) {
    case PlyType::Int8:
    case PlyType::Uint8:
      return 1;
    case PlyType::Int16:
    case PlyType::Uint16:
      return 2;
    case PlyType::Float64:
      return 8;
    default:
      return 4;
  }
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;
  bool list = false;
  PlyType countType = PlyType::Uint8;
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyFormat { Ascii, LittleEndian, BigEndian };

std::vector<std::string_view> wordsOf(std::string_view line) {
  std::vector<std::string_view> words;
  for (size_t i = 0; i < line.size();) {
    const size_t j = std::min(line.find_first_of(" \t", i), line.size());
    if (j > i) words.push_back(line.substr(i, j - i));
    i = j + 1;
  }
  return words;
}

// The values of an element's entries, one after another, from the body's text or bytes.
class PlyBody {
 public:
  PlyBody(std::string_view body, PlyFormat format, const std::string& file)
      : body_(body), format_(format), file_(file) {}

  // The next value, of `type`; false at the end of the body.
  bool next(PlyType type, double& value) {
    if (format_ == PlyFormat::Ascii) return nextText(value);
    const size_t size = sizeOf(type);
    if (body_.size() - pos_ < size) return false;
    unsigned char b[8];
    std::memcpy(b, body_.data() + pos_, size);
    pos_ += size;
    if (format_ == PlyFormat::BigEndian) std::reverse(b, b + size);
    switch (type) {
      case PlyType::Int8:
        value = double(int8_t(b[0]));
        break;
      case PlyType::Uint8:
        value = double(b[0]);
        break;
      case PlyType::Int16:
        value = double(int16_t(uint16_t(b[0] | b[1] << 8)));
        break;
      case PlyType::Uint16:
        value = double(uint16_t(b[0] | b[1] << 8));
        break;
      case PlyType::Int32: {
        int32_t v;
        std::memcpy(&v, b, 4);
        value = double(v);
        break;
      }
      case PlyType::Uint32: {
        uint32_t v;
        std::memcpy(&v, b, 4);
        value = double(v);
        break;
      }
      case PlyType::Float32: {
        float v;
        std::memcpy(&v, b, 4);
        value = double(v);
        break;
      }
      case PlyType::Float64:
        std::memcpy(&value, b, 8);
        break;
    }
    return true;
  }

  // Whether `count` entries of at least `bytes` each can still follow (ASCII: one character).
  bool room(uint64_t count, uint64_t bytes) const {
    const uint64_t left = body_.size() - pos_;
    return count <= left / std::max<uint64_t>(format_ == PlyFormat::Ascii ? 1 : bytes, 1);
  }

 private:
  bool nextText(double& value) {
    while (pos_ < body_.size() && std::strchr(" \t\r\n\f\v", body_[pos_]) && body_[pos_] != '\0')
      ++pos_;
    if (pos_ >= body_.size()) return false;
    const char* first = body_.data() + pos_;
    const char* last = body_.data() + body_.size();
    const char* end = first;
    while (end < last && !std::strchr(" \t\r\n\f\v", *end)) ++end;
    if (*first == '+') ++first;  // from_chars takes no plus sign
    const auto [ptr, ec] = std::from_chars(first, end, value);
    if (ec == std::errc::result_out_of_range) {
      value = HUGE_VAL;  // refused as infinite by the caller's checks
    } else if (ec != std::errc() || ptr != end) {
      throw InputError(file_ + ": malformed number '" +
                       quoteName(std::string_view(body_.data() + pos_, size_t(end - first))) +
                       "' in the PLY body");
    }
    pos_ = size_t(end - body_.data());
    return true;
  }

  std::string_view body_;
  PlyFormat format_;
  const std::string& file_;
  size_t pos_ = 0;
};

}  // namespace

Mesh readPly(std::string_view bytes, const std::string& file) {
  // The header, line by line.
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  size_t pos = 0, lineNumber = 0;
  bool ended = false;
  while (!ended) {
    if (pos >= bytes.size() || pos > (size_t(1) << 20))
      throw InputError(file + ": the PLY header has no end_header line (is the file cut short?)");
    size_t end = bytes.find('\n', pos);
    if (end == std::string_view::npos) end = bytes.size();
    std::string_view line = bytes.substr(pos, end - pos);
    pos = end + 1;
    ++lineNumber;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::vector<std::string_view> w = wordsOf(line);
    const auto bad = [&] {
      throw InputError(file + ":" + std::to_string(lineNumber) + ": malformed PLY header line '" +
                       quoteName(line) + "'");
    };
    if (lineNumber == 1) {
      if (w.size() != 1 || w[0] != "ply") bad();
    } else if (lineNumber == 2) {
      if (w.size() != 3 || w[0] != "format") bad();
      if (w[1] == "ascii")
        format = PlyFormat::Ascii;
      else if (w[1] == "binary_little_endian")
        format = PlyFormat::LittleEndian;
      else if (w[1] == "binary_big_endian")
        format = PlyFormat::BigEndian;
      else
        bad();
    } else if (w.empty() || w[0] == "comment" || w[0] == "obj_info") {
      continue;
    } else if (w[0] == "element") {
      PlyElement e;
      if (w.size() != 3) bad();
      e.name = std::string(w[1]);
      const auto [ptr, ec] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
      if (ec != std::errc() || ptr != w[2].data() + w[2].size()) bad();
      // One of each: the vertices' positions, normals, uvs and colors are read as parallel lists.
      if ((e.name == "vertex" || e.name == "face") &&
          std::any_of(elements.begin(), elements.end(),
                      [&](const PlyElement& other) { return other.name == e.name; })) {
        throw InputError(file + ":" + std::to_string(lineNumber) + ": a second '" + e.name +
                         "' element in the PLY header");
      }
      elements.push_back(std::move(e));
    } else if (w[0] == "property") {
      PlyProperty p;
      if (elements.empty()) bad();
      if (w.size() == 3 && typeOf(w[1], p.type)) {
        p.name = std::string(w[2]);
      } else if (w.size() == 5 && w[1] == "list" && typeOf(w[2], p.countType) &&
                 typeOf(w[3], p.type)) {
        p.list = true;
        p.name = std::string(w[4]);
      } else {
        bad();
      }
      elements.back().properties.push_back(std::move(p));
    } else if (w.size() == 1 && w[0] == "end_header") {
      ended = true;
    } else if (w[0] == "format" || w[0] == "end_header") {
      bad();
    }
    // Other lines: the free text some exporters write in the header (Blender 2.4's).
  }

  Mesh mesh;
  mesh.faceStart.push_back(0);
  PlyBody body(bytes.substr(std::min(pos, bytes.size())), format, file);
  bool colors = false;
  std::vector<cv::Vec3f> vertexColors;
  for (const PlyElement& e : elements) {
    uint64_t fixedBytes = 0;
    for (const PlyProperty& p : e.properties)
      fixedBytes += p.list ? sizeOf(p.countType) : sizeOf(p.type);
    if (!body.room(e.count, fixedBytes)) {
      throw InputError(file + ": the PLY body is too short for the " + std::to_string(e.count) +
                       " '" + quoteName(e.name) + "' elements its header announces");
    }
    const bool vertex = e.name == "vertex", face = e.name == "face";
    // Which property gives what: 1-3 x y z, 4-6 nx ny nz, 7-8 u v, 9-11 red green blue; 0 none.
    const auto roleOf = [](const std::string& n) {
      static const char* const names[][4] = {{"x", "", "", ""},
                                             {"y", "", "", ""},
                                             {"z", "", "", ""},
                                             {"nx", "", "", ""},
                                             {"ny", "", "", ""},
                                             {"nz", "", "", ""},
                                             {"u", "s", "texture_u", "texture_s"},
                                             {"v", "t", "texture_v", "texture_t"},
                                             {"red", "r", "diffuse_red", ""},
                                             {"green", "g", "diffuse_green", ""},
                                             {"blue", "b", "diffuse_blue", ""}};
      for (int r = 0; r < 11; ++r)
        for (const char* alias : names[r])
          if (*alias && n == alias) return r + 1;
      return 0;
    };
    bool has[12] = {};
    std::vector<int> roles;
    for (const PlyProperty& p : e.properties) {
      roles.push_back(p.list ? 0 : roleOf(p.name));
      if (!p.list) has[roles.back()] = true;
    }
    const bool normals = vertex && has[4] && has[5] && has[6];
    const bool uvs = vertex && has[7] && has[8];
    const bool rgb = vertex && has[9] && has[10] && has[11];
    if (vertex) {
      colors = rgb;
      if (e.count > uint64_t(INT32_MAX)) throw InputError(file + ": too many vertices for zrender");
      mesh.positions.reserve(size_t(e.count));
    }
    for (uint64_t i = 0; i < e.count; ++i) {
      double values[12] = {};
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        double value = 0.0;
        const auto cut = [&] {
          throw InputError(file + ": the PLY body ends in '" + quoteName(e.name) + "' element " +
                           std::to_string(i) + " of " + std::to_string(e.count) +
                           " (is the file cut short?)");
        };
        if (!p.list) {
          if (!body.next(p.type, value)) cut();
          // uchar colors as n / 255 in float, as assimp and most readers take them.
          values[roles[k]] =
              roles[k] >= 9 && p.type == PlyType::Uint8 ? double(float(value) / 255.0f) : value;
          continue;
        }
        double count = 0.0;
        if (!body.next(p.countType, count)) cut();
        if (!(count >= 0.0) || count > double(kMaxFaceCorners) || count != std::floor(count)) {
          throw InputError(file + ": '" + quoteName(e.name) + "' element " + std::to_string(i) +
                           ": a list of " + quoteName(std::to_string(count)) + " entries (0 to " +
                           std::to_string(kMaxFaceCorners) + " are read)");
        }
        const bool indices = face && (p.name == "vertex_indices" || p.name == "vertex_index");
        if (!body.room(uint64_t(count), sizeOf(p.type))) cut();
        for (uint32_t c = 0; c < uint32_t(count); ++c) {
          if (!body.next(p.type, value)) cut();
          if (!indices) continue;
          if (!(value >= 0.0 && value < double(mesh.positions.size())) ||
              value != std::floor(value)) {
            throw InputError(file + ": face " + std::to_string(i) + ": vertex index " +
                             quoteName(std::to_string(value)) + " out of range (" +
                             std::to_string(mesh.positions.size()) + " vertices)");
          }
          Corner corner;
          corner.position = int32_t(value);
          if (!mesh.normals.empty()) corner.normal = corner.position;
          if (!mesh.texcoords.empty()) corner.texcoord = corner.position;
          mesh.corners.push_back(corner);
        }
        if (indices) {
          mesh.faceStart.push_back(uint32_t(mesh.corners.size()));
          mesh.faceMaterial.push_back(-1);
        }
      }
      if (vertex) {
        mesh.positions.emplace_back(values[1], values[2], values[3]);
        if (normals) mesh.normals.emplace_back(values[4], values[5], values[6]);
        if (uvs) mesh.texcoords.emplace_back(values[7], values[8]);
        if (rgb) vertexColors.emplace_back(float(values[9]), float(values[10]), float(values[11]));
      }
    }
  }
  if (colors) {
    // A face's color: the mean of its corners' (docs/design.md, Model formats).
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
      cv::Vec3f sum(0, 0, 0);
      const uint32_t n = mesh.cornerCount(f);
      for (uint32_t c = 0; c < n; ++c) {
        const cv::Vec3f& v = vertexColors[size_t(mesh.faceCorners(f)[c].position)];
        for (int a = 0; a < 3; ++a) sum[a] += std::clamp(v[a], 0.0f, 1.0f);
      }
      if (n > 0) sum *= 1.0f / float(n);
      mesh.faceColors.push_back(sum);
    }
  }
  return mesh;
}

}  // namespace zrender
