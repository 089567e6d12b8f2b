// Fields of text input files: decimal numbers only, and lines quoted back
// with their unprintable bytes escaped.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "geometry/input_text.h"

using namespace linerlife;

TEST_CASE("input fields are decimal numbers, not hexadecimal, nan or inf", "[geometry][csv][input]") {
  auto value = [](const std::string& s) {
    double v = -12345;
    REQUIRE(parse_decimal(s, v));
    return v;
  };
  CHECK(value("0.075") == 0.075);
  CHECK(value(" -1e-3\t") == -1e-3);
  CHECK(value("+7.5E-2\r") == 7.5e-2);
  CHECK(value(".5") == 0.5);
  CHECK(value("7.") == 7.0);
  CHECK(value("1000") == 1000.0);
  // a review: strtod took hexadecimal numbers, so "0x1p-3" was 0.125 m
  const std::vector<std::string> refused = {"0x1p-3", "0X1P-3", "0x10", "nan", "NaN", "inf", "-infinity", "1e400", "1e-400",
                                            "",       " ",      "1e",   "e5",  ".",   "-",   "1.2.3",     "1,5",
                                            "0.1m",   "1 2",    "0x",   "1e+", "--1", std::string("0\0", 2)};
  for (const std::string& bad : refused) {
    double v = -12345;
    INFO("field \"" << bad << "\"");
    CHECK_FALSE(parse_decimal(bad, v));
    CHECK(v == -12345);
  }
}

TEST_CASE("a line quoted in a message has its unprintable bytes escaped and its length bounded",
          "[geometry][csv][input]") {
  CHECK(printable("0.2,0.075") == "0.2,0.075");
  // a review: binary bytes were echoed raw (a NUL cut the message short)
  CHECK(printable(std::string("0.2,") + '\0' + "\x01\x1b[31m\x7f") == "0.2,\\x00\\x01\\x1B[31m\\x7F");
  CHECK(printable("a\tb") == "a\\x09b");
  CHECK(printable("\xff\xfe,0.1") == "\\xFF\\xFE,0.1");                // not UTF-8
  CHECK(printable("y_\xc2\xb5m") == "y_\xc2\xb5m");                   // UTF-8 kept (a micro sign)
  CHECK(printable("\xc2\x85") == "\\xC2\\x85");                       // a C1 control character
  CHECK(printable("\xe2\x82") == "\\xE2\\x82");                       // a cut-off sequence
  CHECK(printable("\xed\xa0\x80") == "\\xED\\xA0\\x80");               // a UTF-16 surrogate
  CHECK(printable(std::string(200, 'x')) == std::string(120, 'x') + "... (200 bytes)");
  CHECK(printable(std::string(119, 'x') + "\xc2\xb5" + "yz") == std::string(119, 'x') + "... (123 bytes)");
}
