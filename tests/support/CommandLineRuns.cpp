#include "support/CommandLineRuns.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

namespace zrender::test {

const char* const kSquareObj =
    "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
    "f 1 2 3\nf 1 3 4\n";

std::string settingsFor(const std::string& model, const std::string& extra,
                        const std::string& size) {
  return R"({"sq": {"path": ")" + model + R"(", "width": )" + size + R"(, "height": )" + size +
         R"(, "eye": [0, 0, 2], "project": [90, 0, 0.1, 10])" + extra + "}}";
}

bool matchesWithNumbers(const std::string& text, const std::string& pattern) {
  const auto isNumber = [](char c) { return (c >= '0' && c <= '9') || c == '.'; };
  size_t t = 0;
  for (const char p : pattern) {
    if (p != '#') {
      if (t >= text.size() || text[t] != p) return false;
      ++t;
      continue;
    }
    const size_t start = t;
    while (t < text.size() && isNumber(text[t])) ++t;
    if (t == start) return false;
  }
  return t == text.size();
}

Json::Value parseJson(const std::string& text) {
  Json::Value j;
  std::string errors;
  std::unique_ptr<Json::CharReader> reader(Json::CharReaderBuilder().newCharReader());
  EXPECT_TRUE(reader->parse(text.data(), text.data() + text.size(), &j, &errors)) << text;
  return j;
}

void expectCleanError(const RunResult& r, const std::vector<std::string>& mustName) {
  EXPECT_EQ(r.status, 2) << r.err;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.rfind("zrender: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  for (const auto& piece : mustName) EXPECT_NE(r.err.find(piece), std::string::npos) << r.err;
}

}  // namespace zrender::test
