// wear_laws.h - the table of wear laws (DESIGN.md §2, LAMMPS-style: one row
// per law, no macros, no self-registering statics). Each law declares its
// parameters with unit, valid range and default; the [wear] configuration
// keys are generated from this table, and make_wear_model() checks values
// against it.
#pragma once

#include <string>
#include <vector>

#include "wear/wear_spec.h"

namespace linerlife {

enum class WearKind { Abrasion, Impact };

/// One parameter of a law, as the [wear] section sees it.
struct LawParameter {
  std::string key;   // [wear] key, e.g. "finnie_cutting_fraction"
  std::string unit;  // "-", "J/m3", "s/m"
  std::string help;  // one line, with its source
  double lo = 0, hi = 0;
  bool lo_open = true, hi_open = false;
  double default_value = 0;
  std::vector<std::string> choices;  // non-empty: the parameter is a name; default_choice applies
  std::string default_choice;
};

struct WearLawEntry {
  std::string name;  // "abrasion/radziszewski", ...
  WearKind kind;
  std::string source;  // where the formula comes from (thesis equation and original paper)
  std::string description;
  std::vector<LawParameter> parameters;
};

/// The table of wear laws.
const std::vector<WearLawEntry>& wear_laws();

/// The law named `name`; throws InputError (key "wear.laws") listing the names otherwise.
const WearLawEntry& find_wear_law(const std::string& name);

/// Value of a numeric law parameter: spec.parameters[key] or the table's default.
/// Throws InputError (key "wear.<key>") if it is outside the declared range.
double law_parameter(const WearSpec& spec, const LawParameter& p);
/// Value of a name parameter: spec.choices[key] or the default; InputError if not one of the choices.
std::string law_choice(const WearSpec& spec, const LawParameter& p);

/// Parses "abrasion/radziszewski, impact/bitter" (commas or spaces) into names;
/// "none" or "" gives no laws.
std::vector<std::string> parse_law_list(const std::string& text);
std::string law_list_text(const std::vector<std::string>& laws);

}  // namespace linerlife
