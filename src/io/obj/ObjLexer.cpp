#include "zrender/io/obj/ObjLexer.hpp"

#include <cctype>

namespace zrender {

ObjNumberKind classifyObjNumber(std::string_view s) {
  size_t i = 0;
  const size_t n = s.size();
  if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
  const size_t mantissaStart = i;
  size_t digits = 0;
  for (; i < n && isObjDigit(s[i]); ++i) ++digits;
  if (i < n && s[i] == '.') {
    for (++i; i < n && isObjDigit(s[i]); ++i) ++digits;
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
      return ObjNumberKind::kNonFinite;
    }
    return ObjNumberKind::kMalformed;
  }
  if (i < n && s[i] == '#') return ObjNumberKind::kNonFinite;
  if (i < n && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
    int exponent = 0;
    size_t expDigits = 0;
    for (; i < n && isObjDigit(s[i]); ++i, ++expDigits) {
      if (exponent <= kObjMaxExponent) exponent = exponent * 10 + (s[i] - '0');
    }
    if (expDigits == 0) return ObjNumberKind::kMalformed;
    if (i == n && exponent > kObjMaxExponent) return ObjNumberKind::kOutOfRange;
  }
  return i == n ? ObjNumberKind::kOk : ObjNumberKind::kMalformed;
}

ObjCorner splitObjCorner(std::string_view field) {
  // One pass over the field: up to three '/'-separated parts, each empty or [+-]digits.
  ObjCorner corner;
  bool ok = true;
  const size_t n = field.size();
  for (size_t i = 0;;) {
    const size_t begin = i;
    if (i < n && (field[i] == '+' || field[i] == '-')) ++i;
    int64_t value = 0;
    const size_t digitsBegin = i;
    for (; i < n && isObjDigit(field[i]); ++i) {
      if (value <= kObjMaxIndex) value = value * 10 + (field[i] - '0');  // saturates
    }
    if (i == digitsBegin && i != begin) ok = false;  // a sign alone
    corner.parts[corner.partCount] = field.substr(begin, i - begin);
    corner.values[corner.partCount] = begin < n && field[begin] == '-' ? -value : value;
    ++corner.partCount;
    if (i == n) break;
    if (field[i] != '/' || corner.partCount == 3) {
      ok = false;
      break;
    }
    ++i;
  }
  // "v//vn" leaves the middle part empty; any other empty part ("1/", "/2", "1/2/") would make
  // tinyobjloader atoi into the next field.
  corner.wellFormed = ok && !corner.parts[0].empty() && !corner.parts[corner.partCount - 1].empty();
  return corner;
}

}  // namespace zrender
