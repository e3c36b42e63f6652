#include "zrender/io/ObjScanner.hpp"

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>

#include "zrender/base/Error.hpp"
#include "zrender/io/ObjLoader.hpp"

namespace zrender {

namespace {

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

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

using Statement = ObjStatement;

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

class Scanner {
 public:
  using Counts = ObjCounts;

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

}  // namespace

std::string quoteName(std::string_view s) {
  return excerpt(s, kMaxNameExcerpt, true);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

ObjCounts scanObj(const std::string& file, std::string_view text) {
  return Scanner(file, text).validate();
}

size_t objStatementLine(std::string_view text, ObjStatement kind, size_t ordinal) {
  const std::string unnamed;
  return Scanner(unnamed, text).lineOf(kind, ordinal);
}

}  // namespace zrender
