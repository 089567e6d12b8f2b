// drive_notes.h - the notes of many charge drives (a forecast's, a wear
// run's), gathered: what the charge model told the user in one drive (a
// sub-stepped time step, a charge that centrifuges, DEM contacts dropped...)
// must not be lost because a forecast ran it 150 times.
#pragma once

#include <cctype>
#include <string>
#include <vector>

namespace linerlife {

struct DriveNote {
  std::string text;           // the first drive's note, in full
  long long first_drive = 0;  // 1-based drive it first came from
  long long drives = 0;       // drives that gave it (or one like it)
};

/// The note with every number replaced by '#': notes that differ only in
/// their numbers (a count, a time step) are one kind.
inline std::string note_kind(const std::string& text) {
  auto digit = [&](size_t i) { return i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])) != 0; };
  std::string k;
  size_t i = 0;
  while (i < text.size()) {
    if (!digit(i)) {
      k += text[i++];
      continue;
    }
    // a number: digits, a fraction, an exponent (1, 0.45, 3e-05, 1.5e+07)
    while (digit(i)) ++i;
    if (i < text.size() && text[i] == '.' && digit(i + 1))
      for (++i; digit(i);) ++i;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
      const size_t j = i + 1 < text.size() && (text[i + 1] == '+' || text[i + 1] == '-') ? i + 2 : i + 1;
      if (digit(j))
        for (i = j; digit(i);) ++i;
    }
    k += '#';
  }
  return k;
}

/// Adds the notes of drive `drive` (1-based) to `all`.
inline void add_drive_notes(std::vector<DriveNote>& all, const std::vector<std::string>& notes, long long drive) {
  for (const std::string& n : notes) {
    const std::string k = note_kind(n);
    bool found = false;
    for (DriveNote& d : all)
      if (note_kind(d.text) == k) {
        ++d.drives;
        found = true;
        break;
      }
    if (!found) all.push_back({n, drive, 1});
  }
}

}  // namespace linerlife
