// input_text.h - reading the fields of a text input file (a profile CSV, a
// measured profile history) and quoting its lines back in messages.
#pragma once

#include <cstddef>
#include <string>

namespace linerlife {

/// Parses `field` (blanks, tabs and a carriage return around it ignored) as a
/// decimal number: an optional sign, digits with an optional decimal point (at
/// least one digit), and an optional exponent (e or E, an optional sign,
/// digits); "0.075", "-1e-3", ".5", "7." are numbers. Hexadecimal numbers
/// ("0x1p-3"), "inf", "nan" and anything else strtod would take are not.
/// Returns false, `value` unchanged, for a field that is not such a number or
/// whose value a double cannot hold (1e400, 1e-400).
bool parse_decimal(const std::string& field, double& value);

/// `text` as it may be quoted in a message: each byte that is not printable
/// (a control character, DEL, a byte that is not part of valid UTF-8) written
/// as \xHH (a NUL as \x00), valid UTF-8 kept; text longer than `max_bytes` is
/// cut there, on a character boundary, with "... (N bytes)" giving its length.
std::string printable(const std::string& text, std::size_t max_bytes = 120);

/// `text` without a UTF-8 byte order mark (EF BB BF) at its start, which
/// spreadsheets write at the head of a "CSV UTF-8" file; other text unchanged.
/// The mark is invisible where a message quotes the line it starts.
std::string without_utf8_bom(const std::string& text);

}  // namespace linerlife
