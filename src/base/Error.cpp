#include "zrender/base/Error.hpp"

#include <algorithm>

namespace zrender {

namespace {

// Whether byte i starts a UTF-8 character (is not a continuation byte 10xxxxxx).
bool startsCharacter(const std::string& s, size_t i) {
  return i >= s.size() || (static_cast<unsigned char>(s[i]) & 0xC0) != 0x80;
}

}  // namespace

std::string messageLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  if (text.size() <= kMaxMessageBytes) return text;
  const std::string cut = " ... ";
  size_t head = (kMaxMessageBytes - cut.size()) * 3 / 5;
  size_t tail = text.size() - (kMaxMessageBytes - cut.size() - head);
  while (head > 0 && !startsCharacter(text, head)) --head;
  while (!startsCharacter(text, tail)) ++tail;
  return text.substr(0, head) + cut + text.substr(tail);
}

}  // namespace zrender
