// Reading unit strings from machine exports (unit_parse.h).
#include "fiberbridge/core/unit_parse.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <iterator>

namespace fiberbridge::units {

namespace {

struct KnownUnit {
  const char* symbol;
  Dimension dimension;
  double si;
};

// The inch is 25.4 mm and the pound-force 4.4482216152605 N by definition (international yard
// and pound, 1959; standard gravity 9.80665 m/s^2). Spellings are those machine software writes:
// Bluehill "sec", testXpert "s", MTS "in", "lbf".
constexpr KnownUnit known[] = {{"N", Dimension::force, 1.0},
                               {"kN", Dimension::force, 1e3},
                               {"mN", Dimension::force, 1e-3},
                               {"daN", Dimension::force, 10.0},
                               {"lbf", Dimension::force, 4.4482216152605},
                               {"lb", Dimension::force, 4.4482216152605},
                               {"mm", Dimension::length, mm},
                               {"m", Dimension::length, 1.0},
                               {"cm", Dimension::length, 1e-2},
                               {"um", Dimension::length, um},
                               {"\xC2\xB5m", Dimension::length, um},
                               {"in", Dimension::length, 25.4 * mm},
                               {"inch", Dimension::length, 25.4 * mm},
                               {"s", Dimension::time, 1.0},
                               {"sec", Dimension::time, 1.0},
                               {"ms", Dimension::time, 1e-3},
                               {"min", Dimension::time, 60.0},
                               {"h", Dimension::time, 3600.0}};

const KnownUnit* find(const std::string& unit) {
  for (const auto& k : known)
    if (unit == k.symbol)
      return &k;
  return nullptr;
}

} // namespace

const char* dimension_name(Dimension d) {
  switch (d) {
  case Dimension::length:
    return "length";
  case Dimension::force:
    return "force";
  case Dimension::time:
    return "time";
  }
  return "?";
}

NamedUnit split_header_unit(const std::string& header) {
  const std::string h = trim_blanks(header, cell_blanks);
  if (h.size() >= 2 && (h.back() == ')' || h.back() == ']')) {
    const char open = h.back() == ')' ? '(' : '[';
    const auto b = h.find_last_of(open);
    if (b != std::string::npos && b > 0)
      return {trim_blanks(h.substr(0, b), cell_blanks),
              trim_blanks(h.substr(b + 1, h.size() - b - 2), cell_blanks)};
  }
  return {h, ""};
}

std::string strip_unit_brackets(const std::string& cell) {
  std::string c = trim_blanks(cell, cell_blanks);
  if (c.size() >= 2 &&
      ((c.front() == '(' && c.back() == ')') || (c.front() == '[' && c.back() == ']')))
    c = trim_blanks(c.substr(1, c.size() - 2), cell_blanks);
  return c;
}

bool is_known_unit(const std::string& unit) {
  return find(unit) != nullptr;
}

double si_factor(const std::string& unit, Dimension d, const std::string& where) {
  const KnownUnit* k = find(unit);
  if (k && k->dimension == d)
    return k->si;
  std::string expected;
  for (const auto& u : known)
    if (u.dimension == d)
      expected += (expected.empty() ? "" : ", ") + std::string(u.symbol);
  throw InputError(where + ": unit '" + unit + "' " +
                   (k ? std::string("is a ") + dimension_name(k->dimension) + ", not a "
                      : std::string("is not one this reader knows for a ")) +
                   dimension_name(d) + "; expected one of " + expected);
}

} // namespace fiberbridge::units
