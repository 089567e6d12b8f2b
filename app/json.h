// json.h - the one-object JSON summaries printed by --json. Keys keep their
// insertion order; non-finite numbers are written as null.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace linerlife {

class Json {
 public:
  static Json object();
  static Json array();
  Json& set(const std::string& key, const Json& v);
  Json& set(const std::string& key, double v);
  Json& set(const std::string& key, int v);
  Json& set(const std::string& key, long long v);
  Json& set(const std::string& key, bool v);
  Json& set(const std::string& key, const std::string& v);
  Json& set(const std::string& key, const char* v);
  Json& set(const std::string& key, const std::vector<double>& v);
  /// A string, or null when `v` is empty (a value that may be absent, such
  /// as a relining date when no criterion was reached).
  Json& set_or_null(const std::string& key, const std::string& v);
  Json& push(const Json& v);
  Json& push(double v);
  std::string dump(int indent = 2) const;

 private:
  enum class Kind { Object, Array, Raw } kind_ = Kind::Raw;
  std::string raw_;                                   // a scalar, already encoded
  std::vector<std::pair<std::string, Json>> items_;  // object members or array items (key empty)
  static Json raw(std::string s);
  void dump_to(std::string& out, int indent, int level) const;
};

std::string json_escape(const std::string& s);

}  // namespace linerlife
