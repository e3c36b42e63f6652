#include "zrender/io/obj/ObjParser.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

#include "zrender/io/obj/ObjLexer.hpp"
#include "zrender/io/obj/ObjLoader.hpp"

namespace zrender {

namespace {

constexpr size_t kNone = std::numeric_limits<size_t>::max();

// f(0) to f(n - 1): on `threads`, or in order on the calling thread if it is null.
template <typename F>
void forEachOn(const Threads* threads, size_t n, const F& f) {
  if (threads)
    threads->forEach(n, f);
  else
    for (size_t i = 0; i < n; ++i) f(i);
}

// The first pass over one part.
void countPart(std::string_view text, ObjPart& part) {
  ObjLines lines(text.substr(part.begin, part.end - part.begin));
  std::string_view line;
  while (lines.next(line)) {
    const std::string_view whole = line;
    const std::string_view keyword = objKeyword(line);
    const ObjStatement statement = objStatementOf(keyword);
    std::string_view field;
    if (statement == ObjStatement::kFace) {
      ++part.faces;
      while (nextObjField(line, field)) ++part.corners;
    } else if (statement != ObjStatement::kOther) {
      ++part.attributes[static_cast<int>(statement)];
    } else {
      bool use = false;
      if (isObjMaterialLine(keyword, line, use)) {
        part.materialLines.push_back({whole, use});
        part.uses += use ? 1 : 0;
      }
    }
  }
}

// A field of the scan's number grammar, correctly rounded; false if it breaks the grammar.
// Past a double's range: what strtod gives, infinity or zero.
bool readNumber(std::string_view field, double& value) {
  if (classifyObjNumber(field) != ObjNumberKind::kOk) return false;
  const char* begin = field.data();
  const char* end = begin + field.size();
  if (*begin == '+') ++begin;  // from_chars takes no plus sign
  const std::from_chars_result result = std::from_chars(begin, end, value);
  if (result.ec == std::errc::result_out_of_range) {
    value = std::strtod(std::string(begin, end).c_str(), nullptr);
    return true;
  }
  return result.ec == std::errc() && result.ptr == end;
}

// An OBJ index (1-based, or negative: back from the `before` attributes defined so far) to a
// 0-based one below `total`, or -1 for an absent part; false if out of range or 0.
bool resolveIndex(std::string_view part, int64_t value, size_t before, size_t total,
                  int32_t& index) {
  if (part.empty()) {
    index = -1;
    return true;
  }
  if (value > 0 && value <= static_cast<int64_t>(total)) {
    index = static_cast<int32_t>(value - 1);
    return true;
  }
  if (value < 0 && -value <= static_cast<int64_t>(before)) {
    index = static_cast<int32_t>(static_cast<int64_t>(before) + value);
    return true;
  }
  return false;
}

// The second pass over one part; false at the first statement that breaks the rules.
bool parsePart(std::string_view text, const ObjLayout& layout, const ObjPart& part, Mesh& mesh,
               ObjNonFinite& nonFinite) {
  size_t count[3] = {part.attributesBefore[0], part.attributesBefore[1], part.attributesBefore[2]};
  size_t face = part.facesBefore;
  size_t corner = part.cornersBefore;
  int32_t use = static_cast<int32_t>(part.usesBefore) - 1;  // the usemtl line in effect
  // The counts of the first pass, which split lines the same way; guards, never reached.
  const size_t cornersEnd = part.cornersBefore + part.corners;
  const size_t facesEnd = part.facesBefore + part.faces;
  ObjLines lines(text.substr(part.begin, part.end - part.begin));
  std::string_view line;
  while (lines.next(line)) {
    const std::string_view keyword = objKeyword(line);
    const ObjStatement statement = objStatementOf(keyword);
    std::string_view field;
    if (statement == ObjStatement::kFace) {
      const size_t first = corner;
      while (nextObjField(line, field)) {
        if (corner - first == kMaxFaceCorners || corner == cornersEnd) return false;
        const ObjCorner raw = splitObjCorner(field);
        if (!raw.wellFormed) return false;
        Corner& c = mesh.corners[corner++];
        int32_t* const out[3] = {&c.position, &c.texcoord, &c.normal};
        for (int k = 0; k < 3; ++k) {
          const std::string_view written = k < raw.partCount ? raw.parts[k] : std::string_view();
          if (!resolveIndex(written, raw.values[k], count[k], layout.attributes[k], *out[k]))
            return false;
        }
      }
      if (corner == first || face == facesEnd) return false;
      mesh.faceMaterial[face] = use;
      mesh.faceStart[++face] = static_cast<uint32_t>(corner);
      continue;
    }
    if (statement == ObjStatement::kOther) {
      bool isUse = false;
      if (isObjMaterialLine(keyword, line, isUse) && isUse) ++use;
      continue;
    }
    const int k = static_cast<int>(statement);
    double values[3] = {0.0, 0.0, 0.0};
    int numbers = 0;
    while (nextObjField(line, field)) {
      double value;
      if (!readNumber(field, value)) return false;
      if (numbers < 3) values[numbers] = value;
      ++numbers;
    }
    if (numbers < kObjMinNumbers[k]) return false;
    if (count[k] == part.attributesBefore[k] + part.attributes[k]) return false;  // a guard
    const size_t ordinal = count[k]++;
    if (k == 1) {
      mesh.texcoords[ordinal] = cv::Vec2d(values[0], values[1]);
    } else {
      (k == 0 ? mesh.positions : mesh.normals)[ordinal] =
          cv::Vec3d(values[0], values[1], values[2]);
    }
    const bool finite = std::isfinite(values[0]) && std::isfinite(values[1]) &&
                        (k == 1 || std::isfinite(values[2]));
    if (!finite && nonFinite.ordinal[k] == kNone) nonFinite.ordinal[k] = ordinal;
  }
  return true;
}

}  // namespace

ObjLayout layOutObj(std::string_view text, const Threads* threads, size_t partBytes) {
  ObjLayout layout;
  partBytes = std::max<size_t>(partBytes, 1);
  for (size_t begin = 0; begin < text.size();) {
    size_t end = begin + std::min(partBytes, text.size() - begin);
    if (end < text.size()) {
      // After a '\n', which always ends a line (alone or in "\r\n").
      const void* newline = std::memchr(text.data() + end - 1, '\n', text.size() - end + 1);
      end = newline ? static_cast<const char*>(newline) - text.data() + 1 : text.size();
    }
    ObjPart part;
    part.begin = begin;
    part.end = end;
    layout.parts.push_back(part);
    begin = end;
  }
  forEachOn(threads, layout.parts.size(), [&](size_t i) { countPart(text, layout.parts[i]); });

  for (ObjPart& part : layout.parts) {
    for (int k = 0; k < 3; ++k) {
      part.attributesBefore[k] = layout.attributes[k];
      layout.attributes[k] += part.attributes[k];
    }
    part.facesBefore = layout.faces;
    part.cornersBefore = layout.corners;
    part.usesBefore = layout.uses;
    layout.materialLines.insert(layout.materialLines.end(), part.materialLines.begin(),
                                part.materialLines.end());
    layout.faces += part.faces;
    layout.corners += part.corners;
    layout.uses += part.uses;
  }
  return layout;
}

bool parseObj(std::string_view text, const ObjLayout& layout, const Threads* threads, Mesh& mesh,
              ObjNonFinite& nonFinite) {
  for (int k = 0; k < 3; ++k) {
    nonFinite.ordinal[k] = kNone;
    if (layout.attributes[k] > static_cast<size_t>(kObjMaxIndex)) return false;
  }
  if (layout.corners > std::numeric_limits<uint32_t>::max()) return false;
  // New memory, which the kernel zeroes page by page: the corners (the most of it) beside the
  // rest.
  const auto allocate = [&](size_t job) {
    if (job == 0) {
      mesh.corners.resize(layout.corners);
      return;
    }
    mesh.positions.resize(layout.attributes[0]);
    mesh.texcoords.resize(layout.attributes[1]);
    mesh.normals.resize(layout.attributes[2]);
    mesh.faceStart.assign(layout.faces + 1, 0);
    mesh.faceMaterial.resize(layout.faces);
  };

  forEachOn(threads, 2, allocate);

  const size_t parts = layout.parts.size();
  std::vector<ObjNonFinite> partNonFinite(parts);
  std::atomic<bool> ok{true};
  const auto parse = [&](size_t i) {
    if (!ok.load(std::memory_order_relaxed)) return;
    ObjNonFinite& mine = partNonFinite[i];
    std::fill(std::begin(mine.ordinal), std::end(mine.ordinal), kNone);
    if (!parsePart(text, layout, layout.parts[i], mesh, mine))
      ok.store(false, std::memory_order_relaxed);
  };
  forEachOn(threads, parts, parse);
  if (!ok.load()) return false;
  for (const ObjNonFinite& part : partNonFinite)
    for (int k = 0; k < 3; ++k)
      nonFinite.ordinal[k] = std::min(nonFinite.ordinal[k], part.ordinal[k]);
  return true;
}

}  // namespace zrender
