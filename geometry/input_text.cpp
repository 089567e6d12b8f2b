#include "geometry/input_text.h"

#include <cstdio>
#include <stdexcept>

namespace linerlife {
namespace {

bool digit(char c) { return c >= '0' && c <= '9'; }

/// The length of the valid UTF-8 sequence of a printable character starting
/// at s[i] (a multi-byte one: s[i] >= 0x80), or 0 when there is none.
std::size_t utf8_length(const std::string& s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // the allowed range of the second byte
  if (c >= 0xC2 && c <= 0xDF) n = 2;
  else if (c >= 0xE0 && c <= 0xEF) n = 3, lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
  else if (c >= 0xF0 && c <= 0xF4) n = 4, lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
  else return 0;
  if (i + n > s.size() || b(i + 1) < lo || b(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (b(i + k) < 0x80 || b(i + k) > 0xBF) return 0;
  if (c == 0xC2 && b(i + 1) <= 0x9F) return 0;  // U+0080 to U+009F: control characters
  return n;
}

}  // namespace

bool parse_decimal(const std::string& field, double& value) {
  const auto b = field.find_first_not_of(" \t\r");
  if (b == std::string::npos) return false;
  const std::string t = field.substr(b, field.find_last_not_of(" \t\r") - b + 1);
  // [+-]? (digits [. digits?] | . digits) ([eE] [+-]? digits)?
  std::size_t i = 0;
  if (t[i] == '+' || t[i] == '-') ++i;
  std::size_t mantissa_digits = 0;
  while (i < t.size() && digit(t[i])) ++i, ++mantissa_digits;
  if (i < t.size() && t[i] == '.') {
    ++i;
    while (i < t.size() && digit(t[i])) ++i, ++mantissa_digits;
  }
  if (mantissa_digits == 0) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    std::size_t exponent_digits = 0;
    while (i < t.size() && digit(t[i])) ++i, ++exponent_digits;
    if (exponent_digits == 0) return false;
  }
  if (i != t.size()) return false;
  try {
    std::size_t pos = 0;
    const double v = std::stod(t, &pos);  // out_of_range beyond a double (1e400, 1e-400)
    if (pos != t.size()) return false;
    value = v;
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

std::string printable(const std::string& text, std::size_t max_bytes) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size() && i < max_bytes) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7F) {
      out += static_cast<char>(c);
      ++i;
      continue;
    }
    const std::size_t n = c >= 0x80 ? utf8_length(text, i) : 0;
    if (n > 0 && i + n <= max_bytes) {
      out.append(text, i, n);
      i += n;
      continue;
    }
    if (n > 0) break;  // a character that would pass the cut
    char hex[5];
    std::snprintf(hex, sizeof hex, "\\x%02X", c);
    out += hex;
    ++i;
  }
  if (i < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
  return out;
}

std::string without_utf8_bom(const std::string& text) {
  return text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? text.substr(3) : text;
}

}  // namespace linerlife
