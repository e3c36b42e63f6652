#include "zrender/scene/SettingsMessages.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "zrender/base/Error.hpp"

namespace zrender {

std::string printable(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

std::string formatNumber(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[40];
  // Whole numbers as written ("180", not "1.8e+02"); below 1e15 every one is exact.
  if (v == std::floor(v) && std::abs(v) < 1e15) {
    std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
  }
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

std::string formatVec(const cv::Vec3d& v) {
  return "[" + formatNumber(v[0]) + ", " + formatNumber(v[1]) + ", " + formatNumber(v[2]) + "]";
}

[[noreturn]] void failKey(const std::string& where, const std::string& key,
                          const std::string& what) {
  throw InputError(where + ": key '" + key + "': " + what);
}

}  // namespace zrender
