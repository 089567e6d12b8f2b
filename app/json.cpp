#include "app/json.h"

#include <cmath>

#include <fmt/format.h>

namespace linerlife {

std::string json_escape(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (c < 0x20) out += fmt::format("\\u{:04x}", c);
        else out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

namespace {
std::string number(double v) { return std::isfinite(v) ? fmt::format("{}", v) : "null"; }
}  // namespace

Json Json::object() { Json j; j.kind_ = Kind::Object; return j; }
Json Json::array() { Json j; j.kind_ = Kind::Array; return j; }
Json Json::raw(std::string s) { Json j; j.kind_ = Kind::Raw; j.raw_ = std::move(s); return j; }

Json& Json::set(const std::string& k, const Json& v) { items_.emplace_back(k, v); return *this; }
Json& Json::set(const std::string& k, double v) { return set(k, raw(number(v))); }
Json& Json::set(const std::string& k, int v) { return set(k, raw(fmt::format("{}", v))); }
Json& Json::set(const std::string& k, long long v) { return set(k, raw(fmt::format("{}", v))); }
Json& Json::set(const std::string& k, bool v) { return set(k, raw(v ? "true" : "false")); }
Json& Json::set(const std::string& k, const std::string& v) { return set(k, raw(json_escape(v))); }
Json& Json::set(const std::string& k, const char* v) { return set(k, std::string(v)); }
Json& Json::set_or_null(const std::string& k, const std::string& v) {
  return v.empty() ? set(k, raw("null")) : set(k, v);
}
Json& Json::set(const std::string& k, const std::vector<double>& v) {
  Json a = array();
  for (double x : v) a.push(x);
  return set(k, a);
}
Json& Json::push(const Json& v) { items_.emplace_back("", v); return *this; }
Json& Json::push(double v) { return push(raw(number(v))); }

void Json::dump_to(std::string& out, int indent, int level) const {
  if (kind_ == Kind::Raw) {
    out += raw_;
    return;
  }
  const bool obj = kind_ == Kind::Object;
  out += obj ? '{' : '[';
  if (items_.empty()) {
    out += obj ? '}' : ']';
    return;
  }
  // arrays of scalars stay on one line
  bool flat = !obj;
  for (auto& it : items_) flat = flat && it.second.kind_ == Kind::Raw;
  const std::string pad(static_cast<size_t>(indent * (level + 1)), ' ');
  for (size_t i = 0; i < items_.size(); ++i) {
    if (i) out += flat ? ", " : ",";
    if (!flat && indent > 0) out += "\n" + pad;
    if (obj) out += json_escape(items_[i].first) + (indent > 0 ? ": " : ":");
    items_[i].second.dump_to(out, indent, level + 1);
  }
  if (!flat && indent > 0) out += "\n" + std::string(static_cast<size_t>(indent * level), ' ');
  out += obj ? '}' : ']';
}

std::string Json::dump(int indent) const {
  std::string out;
  dump_to(out, indent, 0);
  return out;
}

}  // namespace linerlife
