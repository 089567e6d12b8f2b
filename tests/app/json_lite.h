// A small JSON reader for the CLI tests: enough of RFC 8259 to read what
// `linerlife ... --json` prints (objects, arrays, strings without unicode
// escapes, numbers, true/false/null; null reads as NaN). Throws on anything
// malformed, so a test that parses output also checks it is valid JSON.
#pragma once

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace linerlife::test {

class JsonValue {
 public:
  enum class Kind { Null, Bool, Number, String, Array, Object };
  Kind kind = Kind::Null;
  bool b = false;
  double n = std::nan("");
  std::string s;
  std::vector<JsonValue> a;
  std::map<std::string, JsonValue> o;

  const JsonValue& operator[](const std::string& key) const {
    auto it = o.find(key);
    if (kind != Kind::Object || it == o.end()) throw std::runtime_error("JSON: no key " + key);
    return it->second;
  }
  const JsonValue& operator[](size_t i) const { return items().at(i); }
  bool has(const std::string& key) const { return kind == Kind::Object && o.count(key) > 0; }
  double num() const {
    if (kind == Kind::Null) return std::nan("");
    if (kind != Kind::Number) throw std::runtime_error("JSON: not a number");
    return n;
  }
  const std::string& str() const {
    if (kind != Kind::String) throw std::runtime_error("JSON: not a string");
    return s;
  }
  const std::vector<JsonValue>& items() const {
    if (kind != Kind::Array) throw std::runtime_error("JSON: not an array");
    return a;
  }
  std::vector<double> nums() const {
    std::vector<double> v;
    for (const auto& e : items()) v.push_back(e.num());
    return v;
  }
};

namespace detail {
struct JsonParser {
  const std::string& t;
  size_t i = 0;
  void ws() {
    while (i < t.size() && std::isspace(static_cast<unsigned char>(t[i]))) ++i;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("JSON: " + what + " at offset " + std::to_string(i));
  }
  void expect(char c) {
    ws();
    if (i >= t.size() || t[i] != c) fail(std::string("expected '") + c + "'");
    ++i;
  }
  std::string string() {
    expect('"');
    std::string out;
    while (i < t.size() && t[i] != '"') {
      if (t[i] == '\\') {
        ++i;
        if (i >= t.size()) fail("bad escape");
        const char e = t[i];
        out += e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e == 'b' ? '\b' : e == 'f' ? '\f' : e;
        if (e == 'u') fail("unicode escapes are not read by this test reader");
      } else {
        out += t[i];
      }
      ++i;
    }
    if (i >= t.size()) fail("unterminated string");
    ++i;
    return out;
  }
  JsonValue value() {
    ws();
    if (i >= t.size()) fail("unexpected end");
    JsonValue v;
    const char c = t[i];
    if (c == '{') {
      ++i;
      v.kind = JsonValue::Kind::Object;
      ws();
      if (i < t.size() && t[i] == '}') return ++i, v;
      for (;;) {
        const std::string k = string();
        expect(':');
        v.o[k] = value();
        ws();
        if (i < t.size() && t[i] == ',') { ++i; continue; }
        expect('}');
        return v;
      }
    }
    if (c == '[') {
      ++i;
      v.kind = JsonValue::Kind::Array;
      ws();
      if (i < t.size() && t[i] == ']') return ++i, v;
      for (;;) {
        v.a.push_back(value());
        ws();
        if (i < t.size() && t[i] == ',') { ++i; continue; }
        expect(']');
        return v;
      }
    }
    if (c == '"') {
      v.kind = JsonValue::Kind::String;
      v.s = string();
      return v;
    }
    for (const char* w : {"true", "false", "null"})
      if (t.compare(i, std::string(w).size(), w) == 0) {
        i += std::string(w).size();
        if (w[0] == 'n') return v;
        v.kind = JsonValue::Kind::Bool;
        v.b = w[0] == 't';
        return v;
      }
    char* end = nullptr;
    v.n = std::strtod(t.c_str() + i, &end);
    if (end == t.c_str() + i) fail("bad value");
    i = static_cast<size_t>(end - t.c_str());
    v.kind = JsonValue::Kind::Number;
    return v;
  }
};
}  // namespace detail

/// Parses one JSON document (trailing white space allowed, nothing else).
inline JsonValue parse_json(const std::string& text) {
  detail::JsonParser p{text};
  JsonValue v = p.value();
  p.ws();
  if (p.i != text.size()) p.fail("trailing characters");
  return v;
}

}  // namespace linerlife::test
