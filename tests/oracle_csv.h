// The oracle tables of tests/charge/oracles (copied from reference/oracles)
// as rows of string fields, for the tests that check against them.
#pragma once

#include <fstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

namespace linerlife::test {

/// CSV rows (after the header) as string fields; quoted fields may hold commas.
inline std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::ifstream f(path);
  REQUIRE(f.good());
  std::vector<std::vector<std::string>> rows;
  std::string line;
  std::getline(f, line);  // header
  while (std::getline(f, line)) {
    if (line.empty()) continue;
    std::vector<std::string> fields;
    std::string cur;
    bool quoted = false;
    for (char c : line) {
      if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) fields.push_back(cur), cur.clear();
      else cur += c;
    }
    fields.push_back(cur);
    rows.push_back(fields);
  }
  return rows;
}

}  // namespace linerlife::test
