#include "zrender/io/ObjLoader.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <tiny_obj_loader.h>

namespace zrender {

namespace {

namespace fs = std::filesystem;

// Longest excerpt of an offending field quoted in a message; a field can be megabytes long.
constexpr size_t kMaxExcerpt = 40;
constexpr size_t kMaxNameExcerpt = 300;
// Largest decimal exponent magnitude accepted; no finite double needs more than 324. Beyond it
// tinyobjloader's 5^exponent overflows (0e500 would read as NaN), and past 2^31 / 10 it gives up
// and silently reads 0. 1e400 passes and is then refused as infinite.
constexpr int kMaxExponent = 400;
constexpr int64_t kMaxIndex = std::numeric_limits<int32_t>::max();

// Quotes file text for a one-line message: control bytes escaped, long text cut. Names (of files,
// materials) keep their UTF-8 bytes; fields that should have been numbers escape them too.
std::string excerpt(std::string_view s, size_t limit = kMaxExcerpt, bool keepUtf8 = false) {
  std::string out;
  for (size_t i = 0; i < s.size() && i < limit; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7f || (c > 0x7f && !keepUtf8)) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  if (s.size() > limit) out += "...";
  return out;
}

std::string quoteName(std::string_view s) {
  return excerpt(s, kMaxNameExcerpt, true);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

// The statements whose fields the scan checks; the order matches the attribute arrays.
enum class Statement { kPosition = 0, kTexcoord = 1, kNormal = 2, kFace, kOther };

const char* const kKeyword[] = {"v", "vt", "vn"};
const char* const kIndexName[] = {"vertex", "texture coordinate", "normal"};
const char* const kPlural[] = {"vertices", "texture coordinates", "normals"};
// Fewest numbers each attribute statement needs (OBJ: v x y z [w], vt u [v [w]], vn i j k).
const int kMinNumbers[] = {3, 1, 3};

enum class NumberKind { kOk, kMalformed, kNonFinite, kOutOfRange };

// Whole-field check against the grammar tinyobjloader's tryParseDouble accepts:
// [+-] (digits [. digits] | . digits) [(e|E) [+-] digits]. tinyobjloader reads the longest
// valid prefix and defaults to 0 when there is none, so it cannot reject a field itself.
NumberKind classifyNumber(std::string_view s) {
  size_t i = 0;
  const size_t n = s.size();
  if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
  const size_t mantissaStart = i;
  size_t digits = 0;
  for (; i < n && isDigit(s[i]); ++i) ++digits;
  if (i < n && s[i] == '.') {
    for (++i; i < n && isDigit(s[i]); ++i) ++digits;
  }
  if (digits == 0) {
    // "nan", "inf", "infinity" (what printf writes) and MSVC's "1.#INF", "-1.#IND".
    char word[10] = {};
    size_t length = 0;
    for (size_t k = mantissaStart; k < n && length < sizeof word - 1; ++k) {
      word[length++] = static_cast<char>(std::tolower(static_cast<unsigned char>(s[k])));
    }
    const std::string_view w(word, length);
    if (mantissaStart + length == n && (w == "nan" || w == "inf" || w == "infinity")) {
      return NumberKind::kNonFinite;
    }
    return NumberKind::kMalformed;
  }
  if (i < n && s[i] == '#') return NumberKind::kNonFinite;
  if (i < n && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
    int exponent = 0;
    size_t expDigits = 0;
    for (; i < n && isDigit(s[i]); ++i, ++expDigits) {
      if (exponent <= kMaxExponent) exponent = exponent * 10 + (s[i] - '0');
    }
    if (expDigits == 0) return NumberKind::kMalformed;
    if (i == n && exponent > kMaxExponent) return NumberKind::kOutOfRange;
  }
  return i == n ? NumberKind::kOk : NumberKind::kMalformed;
}

// The validation scan. tinyobjloader rc10 alone cannot name a bad line: it reads "v 1 abc 3" as
// (1, 0, 3) and "v nan 0 0" as (0, 0, 0), "f 1 x 3" as index 0 and "f 1/ 2/ 3/" as texture
// index 2 (atoi reads on into the next field), and its callback API, which we use for the
// geometry, reports no line numbers and passes indices raw, unchecked.
// So one pass over the text, before tinyobjloader's, checks every v/vt/vn/f line's fields and
// index ranges, counting lines exactly as tinyobjloader's safeGetline splits them. It allocates
// nothing and never builds geometry; tinyobjloader stays the parser.
class Scanner {
 public:
  struct Counts {
    size_t attributes[3] = {0, 0, 0};  // v, vt, vn statements
    size_t faces = 0;
    size_t corners = 0;
  };

  Scanner(const std::string& file, std::string_view text) : file_(file), text_(text) {}

  // Throws InputError at the first bad line, or for a positive index past the final count.
  Counts validate() {
    Counts counts;
    // Positive indices may refer forward (OBJ allows it, tinyobjloader's own loader does too),
    // so they are checked against the totals at the end: the largest one, with its line.
    int64_t maxIndex[3] = {0, 0, 0};
    size_t maxIndexLine[3] = {0, 0, 0};
    reset();
    std::string_view line;
    while (nextLine(line)) {
      const Statement statement = classify(line);
      if (statement == Statement::kOther) continue;
      if (statement == Statement::kFace) {
        size_t corners = 0;
        std::string_view field;
        while (nextField(line, field)) {
          if (++corners > kMaxFaceCorners) {
            fail("face has more than " + std::to_string(kMaxFaceCorners) + " corners");
          }
          checkCorner(field, counts, maxIndex, maxIndexLine);
        }
        if (corners == 0) fail("malformed 'f' line: face has no vertices");
        ++counts.faces;
        counts.corners += corners;
        continue;
      }
      const int k = static_cast<int>(statement);
      int numbers = 0;
      std::string_view field;
      while (nextField(line, field)) {
        switch (classifyNumber(field)) {
          case NumberKind::kOk:
            break;
          case NumberKind::kMalformed:
            fail(std::string("malformed '") + kKeyword[k] + "' line: '" + excerpt(field) +
                 "' is not a number");
          case NumberKind::kNonFinite:
            fail("NaN or infinite coordinate '" + excerpt(field) + "'");
          case NumberKind::kOutOfRange:
            fail("number '" + excerpt(field) + "' out of range");
        }
        ++numbers;
      }
      if (numbers < kMinNumbers[k]) {
        fail(std::string("malformed '") + kKeyword[k] + "' line: expected at least " +
             std::to_string(kMinNumbers[k]) + " numbers, got " + std::to_string(numbers));
      }
      ++counts.attributes[k];
    }
    for (int k = 0; k < 3; ++k) {
      if (maxIndex[k] > static_cast<int64_t>(counts.attributes[k])) {
        lineNumber_ = maxIndexLine[k];
        fail(std::string(kIndexName[k]) + " index " + std::to_string(maxIndex[k]) +
             " out of range (model has " + std::to_string(counts.attributes[k]) + " " + kPlural[k] +
             ")");
      }
      // Corner stores int32 indices and Mesh::faceStart uint32 offsets.
      if (counts.attributes[k] > static_cast<size_t>(kMaxIndex)) {
        throw InputError(file_ + ": too many " + kPlural[k]);
      }
    }
    if (counts.corners > std::numeric_limits<uint32_t>::max()) {
      throw InputError(file_ + ": too many face corners");
    }
    return counts;
  }

  // Line number of the ordinal-th (0-based) statement of a kind; 0 if there is none.
  size_t lineOf(Statement kind, size_t ordinal) {
    reset();
    std::string_view line;
    while (nextLine(line)) {
      if (classify(line) == kind && ordinal-- == 0) return lineNumber_;
    }
    return 0;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(file_ + ":" + std::to_string(lineNumber_) + ": " + what);
  }

 private:
  void reset() {
    pos_ = 0;
    lineNumber_ = 0;
  }

  // Next line without its terminator (\n, \r\n or a lone \r, as tinyobjloader's safeGetline),
  // cut at the first NUL because tinyobjloader parses each line through c_str().
  bool nextLine(std::string_view& line) {
    const size_t size = text_.size();
    if (pos_ >= size) return false;
    const char* text = text_.data();
    size_t end = pos_;
    // The first test passes every printable byte, so most bytes cost one comparison.
    while (end < size && (static_cast<unsigned char>(text[end]) > '\r' ||
                          (text[end] != '\n' && text[end] != '\r' && text[end] != '\0'))) {
      ++end;
    }
    line = std::string_view(text + pos_, end - pos_);
    if (end < size && text[end] == '\0') {  // rare: skip the rest of the line
      while (end < size && text[end] != '\n' && text[end] != '\r') ++end;
    }
    if (end < size && text[end] == '\r' && end + 1 < size && text[end + 1] == '\n') ++end;
    pos_ = end + 1;
    ++lineNumber_;
    return true;
  }

  // Reads the statement keyword the way tinyobjloader matches it ("v" then a space or tab), and
  // leaves line at the fields. A bare "v" or "f" (no fields) counts too, so the scan rejects it.
  static Statement classify(std::string_view& line) {
    size_t i = 0;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
    const std::string_view keyword = line.substr(i, j - i);
    line.remove_prefix(j);
    if (keyword == "v") return Statement::kPosition;
    if (keyword == "vt") return Statement::kTexcoord;
    if (keyword == "vn") return Statement::kNormal;
    if (keyword == "f") return Statement::kFace;
    return Statement::kOther;
  }

  static bool nextField(std::string_view& line, std::string_view& field) {
    size_t i = 0;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i == line.size()) return false;
    size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
    field = line.substr(i, j - i);
    line.remove_prefix(j);
    return true;
  }

  // One face corner: v, v/vt, v//vn or v/vt/vn, each a nonzero integer in range.
  void checkCorner(std::string_view field, const Counts& counts, int64_t* maxIndex,
                   size_t* maxIndexLine) const {
    // One pass over the field: up to three '/'-separated parts, each empty or [+-]digits.
    std::string_view parts[3];
    int64_t values[3] = {0, 0, 0};
    int partCount = 0;
    bool ok = true;
    const size_t n = field.size();
    for (size_t i = 0;;) {
      const size_t begin = i;
      if (i < n && (field[i] == '+' || field[i] == '-')) ++i;
      int64_t value = 0;
      const size_t digitsBegin = i;
      for (; i < n && isDigit(field[i]); ++i) {
        if (value <= kMaxIndex) value = value * 10 + (field[i] - '0');  // saturates
      }
      if (i == digitsBegin && i != begin) ok = false;  // a sign alone
      parts[partCount] = field.substr(begin, i - begin);
      values[partCount] = begin < n && field[begin] == '-' ? -value : value;
      ++partCount;
      if (i == n) break;
      if (field[i] != '/' || partCount == 3) {
        ok = false;
        break;
      }
      ++i;
    }
    // "v//vn" leaves the middle part empty; any other empty part ("1/", "/2", "1/2/") would make
    // tinyobjloader atoi into the next field.
    ok = ok && !parts[0].empty() && !parts[partCount - 1].empty();
    if (!ok) {
      fail("malformed 'f' line: '" + excerpt(field) +
           "' is not a vertex reference (v, v/vt, v//vn or v/vt/vn)");
    }
    for (int k = 0; k < partCount; ++k) {
      if (parts[k].empty()) continue;
      const int64_t value = values[k];
      const size_t count = counts.attributes[k];
      if (value == 0) {
        fail(std::string(kIndexName[k]) + " index 0 is invalid (OBJ indices start at 1)");
      }
      if (value > kMaxIndex || value < -kMaxIndex) {
        fail(std::string(kIndexName[k]) + " index " + excerpt(parts[k]) + " out of range");
      }
      if (value < 0 && -value > static_cast<int64_t>(count)) {
        // A negative index counts back from the last attribute defined before this line.
        fail(std::string(kIndexName[k]) + " index " + std::to_string(value) + " out of range (" +
             std::to_string(count) + " " + kPlural[k] + " defined before this line)");
      }
      if (value > maxIndex[k]) {
        maxIndex[k] = value;
        maxIndexLine[k] = lineNumber_;
      }
    }
  }

  const std::string& file_;
  std::string_view text_;
  size_t pos_ = 0;
  size_t lineNumber_ = 0;
};

// A read-only streambuf over text already in memory, so tinyobjloader reads it without a copy.
class MemoryBuf : public std::streambuf {
 public:
  explicit MemoryBuf(std::string_view text) {
    char* p = const_cast<char*>(text.data());  // never written: no put area, no putback
    setg(p, p, p + text.size());
  }
};

// Opens the .mtl files named by mtllib, relative to the OBJ's folder. A missing one is a warning;
// only regular files are opened, so "mtllib /dev/zero" or a folder cannot hang the loader.
class MtlReader : public tinyobj::MaterialReader {
 public:
  MtlReader(const std::string& file, const fs::path& folder, Warnings& warnings)
      : file_(file), folder_(folder), warnings_(warnings) {}

  bool operator()(const std::string& matId, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* matMap, std::string* warn,
                  std::string* err) override {
    const std::string name(trim(matId));
    if (name.empty()) return false;
    const fs::path path = folder_ / name;
    std::error_code ec;
    std::ifstream in;
    if (fs::is_regular_file(path, ec)) in.open(path, std::ios::binary);
    if (!in.is_open() || !in) {
      if (reported_.insert(name).second) {
        warnings_.push_back(file_ + ": material file '" + quoteName(name) + "' not found");
      }
      missing_ = true;
      return false;
    }
    tinyobj::LoadMtl(matMap, materials, &in, warn, err);
    return true;
  }

  bool missing() const { return missing_; }

 private:
  const std::string& file_;
  fs::path folder_;
  Warnings& warnings_;
  std::unordered_set<std::string> reported_;
  bool missing_ = false;
};

// Receives tinyobjloader's callbacks, which arrive in file order, one per statement. Values come
// as tinyobj::real_t: float with the tinyobjloader::tinyobjloader target, double with
// tinyobjloader::tinyobjloader_double; either is widened to double here.
struct Builder {
  Mesh mesh;
  std::vector<tinyobj::material_t> materials;
  std::unordered_map<std::string, int32_t> materialIndex;
  std::vector<std::string> unknownMaterials;  // each name once, in order of first use
  std::unordered_set<std::string> unknownSeen;
  int32_t currentMaterial = -1;
  // Ordinal of the first v / vt / vn statement with a non-finite value (overflow), or npos.
  size_t firstNonFinite[3] = {std::string::npos, std::string::npos, std::string::npos};

  void noteFinite(int kind, bool finite, size_t ordinal) {
    if (!finite && firstNonFinite[kind] == std::string::npos) firstNonFinite[kind] = ordinal;
  }

  // OBJ index (1-based, or negative = relative to the `count` attributes so far) to 0-based;
  // tinyobjloader passes 0 for an absent vt or vn. The scan has checked the range.
  static int32_t resolve(int index, size_t count) {
    if (index > 0) return index - 1;
    if (index < 0) return static_cast<int32_t>(static_cast<int64_t>(count) + index);
    return -1;
  }

  static void onVertex(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z,
                       tinyobj::real_t /*w*/) {
    auto& b = *static_cast<Builder*>(self);
    b.noteFinite(0, std::isfinite(x) && std::isfinite(y) && std::isfinite(z),
                 b.mesh.positions.size());
    b.mesh.positions.emplace_back(x, y, z);
  }

  static void onTexcoord(void* self, tinyobj::real_t u, tinyobj::real_t v, tinyobj::real_t /*w*/) {
    auto& b = *static_cast<Builder*>(self);
    b.noteFinite(1, std::isfinite(u) && std::isfinite(v), b.mesh.texcoords.size());
    b.mesh.texcoords.emplace_back(u, v);
  }

  static void onNormal(void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z) {
    auto& b = *static_cast<Builder*>(self);
    b.noteFinite(2, std::isfinite(x) && std::isfinite(y) && std::isfinite(z),
                 b.mesh.normals.size());
    b.mesh.normals.emplace_back(x, y, z);
  }

  static void onFace(void* self, tinyobj::index_t* indices, int count) {
    auto& b = *static_cast<Builder*>(self);
    Mesh& m = b.mesh;
    for (int i = 0; i < count; ++i) {
      Corner c;
      c.position = resolve(indices[i].vertex_index, m.positions.size());
      c.texcoord = resolve(indices[i].texcoord_index, m.texcoords.size());
      c.normal = resolve(indices[i].normal_index, m.normals.size());
      m.corners.push_back(c);
    }
    m.faceStart.push_back(static_cast<uint32_t>(m.corners.size()));
    m.faceMaterial.push_back(b.currentMaterial);
  }

  // Looked up by our own trimmed name: tinyobjloader keeps trailing blanks of a usemtl line.
  static void onUseMaterial(void* self, const char* name, int /*tinyobjId*/) {
    auto& b = *static_cast<Builder*>(self);
    const std::string key(trim(name));
    const auto it = b.materialIndex.find(key);
    b.currentMaterial = it == b.materialIndex.end() ? -1 : it->second;
    if (it == b.materialIndex.end() && !key.empty() && b.unknownSeen.insert(key).second) {
      b.unknownMaterials.push_back(key);
    }
  }

  // Called after each mtllib with every material loaded so far.
  static void onMaterials(void* self, const tinyobj::material_t* materials, int count) {
    auto& b = *static_cast<Builder*>(self);
    b.materials.assign(materials, materials + count);
    b.materialIndex.clear();
    for (int i = 0; i < count; ++i) {
      b.materialIndex.emplace(std::string(trim(materials[i].name)), i);  // first one wins
    }
  }
};

float unitClamp(double v) {
  return v > 0.0 ? (v < 1.0 ? static_cast<float>(v) : 1.0f) : 0.0f;
}

// map_Kd relative to the OBJ's folder ("" if the file does not exist). Exporters on Windows
// write backslashes, so those are tried as slashes when the name as written is not found.
std::string resolveTexture(const fs::path& folder, const std::string& name) {
  std::error_code ec;
  fs::path path = folder / name;
  if (fs::is_regular_file(path, ec)) return path.string();
  if (name.find('\\') != std::string::npos) {
    std::string slashed = name;
    for (char& c : slashed) {
      if (c == '\\') c = '/';
    }
    path = folder / slashed;
    if (fs::is_regular_file(path, ec)) return path.string();
  }
  return "";
}

std::string readFile(const fs::path& path, const std::string& file) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(file + ": cannot open file (it is a folder)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(file + ": cannot open file");
  std::string text;
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if (size > 0 && in) {
    text.resize(static_cast<size_t>(size));
    in.read(text.data(), size);
    if (in.gcount() != size) throw InputError(file + ": cannot read file");
  } else {
    // Not seekable (a pipe): read it as a stream.
    in.clear();
    std::ostringstream all;
    all << in.rdbuf();
    text = all.str();
  }
  if (in.bad()) throw InputError(file + ": cannot read file");
  return text;
}

}  // namespace

Mesh loadObj(const std::filesystem::path& path, Warnings& warnings) {
  return loadObjFromText(readFile(path, path.string()), path, warnings);
}

Mesh loadObjFromText(const std::string& data, const std::filesystem::path& path,
                     Warnings& warnings) {
  const std::string file = path.string();
  std::string_view text(data);
  // tinyobjloader does not skip a UTF-8 byte order mark; the first statement would be lost.
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  // UTF-16 text reads as lines cut at their NUL bytes, so the scan would only report "no
  // faces"; the byte order mark tells what is really wrong.
  if (text.substr(0, 2) == "\xFF\xFE" || text.substr(0, 2) == "\xFE\xFF") {
    throw InputError(file + ":1: UTF-16 text is not supported (save the file as UTF-8 or ASCII)");
  }

  Scanner scanner(file, text);
  const Scanner::Counts counts = scanner.validate();
  if (counts.faces == 0) throw InputError(file + ": model has no faces");

  // The callback API rather than ObjReader/LoadObj, whose shapes cannot hold this mesh: they
  // store a face's corner count in an unsigned char (faces above 255 corners wrap), drop faces
  // below 3 corners (shifting every later face id), and split faces into shapes by g/o/usemtl.
  // The callbacks arrive one per statement in file order, with the corner count as an int.
  Builder builder;
  Mesh& mesh = builder.mesh;
  mesh.positions.reserve(counts.attributes[0]);
  mesh.texcoords.reserve(counts.attributes[1]);
  mesh.normals.reserve(counts.attributes[2]);
  mesh.corners.reserve(counts.corners);
  mesh.faceStart.reserve(counts.faces + 1);
  mesh.faceMaterial.reserve(counts.faces);
  mesh.faceStart.push_back(0);

  tinyobj::callback_t callbacks;
  callbacks.vertex_cb = &Builder::onVertex;
  callbacks.texcoord_cb = &Builder::onTexcoord;
  callbacks.normal_cb = &Builder::onNormal;
  callbacks.index_cb = &Builder::onFace;
  callbacks.usemtl_cb = &Builder::onUseMaterial;
  callbacks.mtllib_cb = &Builder::onMaterials;

  const fs::path folder = path.parent_path();
  MtlReader mtlReader(file, folder, warnings);
  MemoryBuf buffer(text);
  std::istream stream(&buffer);
  std::string tinyWarnings, tinyErrors;  // ours are more precise; these are dropped
  tinyobj::LoadObjWithCallback(stream, callbacks, &builder, &mtlReader, &tinyWarnings, &tinyErrors);

  // The scan and tinyobjloader split lines and match statements the same way; if they ever
  // disagreed, the indices checked by the scan would not be the ones stored.
  if (mesh.positions.size() != counts.attributes[0] ||
      mesh.texcoords.size() != counts.attributes[1] ||
      mesh.normals.size() != counts.attributes[2] || mesh.faceCount() != counts.faces ||
      mesh.corners.size() != counts.corners) {
    throw std::logic_error(file + ": OBJ scan and tinyobjloader disagree on the statements");
  }
  for (const Corner& c : mesh.corners) {
    if (c.position < 0 || static_cast<size_t>(c.position) >= mesh.positions.size() ||
        c.texcoord < -1 || c.texcoord >= static_cast<int64_t>(mesh.texcoords.size()) ||
        c.normal < -1 || c.normal >= static_cast<int64_t>(mesh.normals.size())) {
      throw std::logic_error(file + ": face index escaped the OBJ scan");
    }
  }

  // Numbers that pass the scan can still overflow to infinity (1e400, 400 digits); the
  // statement's ordinal leads back to its line.
  const Statement kinds[] = {Statement::kPosition, Statement::kTexcoord, Statement::kNormal};
  for (int k = 0; k < 3; ++k) {
    if (builder.firstNonFinite[k] == std::string::npos) continue;
    const size_t line = scanner.lineOf(kinds[k], builder.firstNonFinite[k]);
    throw InputError(file + ":" + std::to_string(line) +
                     ": NaN or infinite coordinate (a number overflows)");
  }

  // After a missing .mtl every usemtl would be unknown; that file's warning says enough.
  if (!mtlReader.missing()) {
    for (const std::string& name : builder.unknownMaterials) {
      warnings.push_back(file + ": material '" + quoteName(name) + "' not found");
    }
  }

  mesh.materials.reserve(builder.materials.size());
  for (const tinyobj::material_t& source : builder.materials) {
    Material material;
    material.name = std::string(trim(source.name));
    material.diffuse = cv::Vec3f(unitClamp(source.diffuse[0]), unitClamp(source.diffuse[1]),
                                 unitClamp(source.diffuse[2]));
    const std::string texture(trim(source.diffuse_texname));
    if (!texture.empty()) {
      material.diffuseTexture = resolveTexture(folder, texture);
      if (material.diffuseTexture.empty()) {
        warnings.push_back(file + ": texture '" + quoteName(texture) + "' not found");
      }
    }
    mesh.materials.push_back(std::move(material));
  }
  return std::move(builder.mesh);  // mesh is a reference into builder: move, not copy
}

}  // namespace zrender
