#pragma once
// Units as testing machines write them in column headers ("Load (kN)", "Extension [mm]") or in a
// units row under the header ("(sec)", "mm"): split from the name and turned into SI factors.
// The factors themselves are units.h's and the exact definitions of the inch and the pound-force.
#include <string>

namespace fiberbridge::units {

/// What a column measures, for checking that its unit fits (a load in mm is an error).
enum class Dimension { length, force, time };

/// "length", "force", "time" (for messages).
const char* dimension_name(Dimension d);

/// A header split into its name and its unit: "Load (kN)" -> {"Load", "kN"}, "Extension [mm]"
/// -> {"Extension", "mm"}, "Time" -> {"Time", ""}. Only a bracketed unit at the end counts.
struct NamedUnit {
  std::string name;
  std::string unit; ///< without brackets; empty when the header carries none
};
NamedUnit split_header_unit(const std::string& header);

/// A unit cell of a units row without its brackets and spaces: "(sec)" -> "sec", "[N]" -> "N".
std::string strip_unit_brackets(const std::string& cell);

/// True when `unit` (brackets stripped) is one this reader converts, of any dimension.
bool is_known_unit(const std::string& unit);

/// SI factor of `unit` for a quantity of dimension `d`: N, kN, mN, daN, lbf (lb); mm, m, cm, um,
/// in; s, sec, ms, min, h. Throws InputError "`where`: unit 'X' ... expected one of ..." for an
/// unknown unit or one of another dimension.
double si_factor(const std::string& unit, Dimension d, const std::string& where);

} // namespace fiberbridge::units
