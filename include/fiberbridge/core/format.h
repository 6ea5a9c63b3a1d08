#pragma once
// Numbers in notes and progress lines: one formatter for every model (significant digits, the
// stream's default notation); and one trim of blanks around a cell or list entry.
#include <sstream>
#include <string>

namespace fiberbridge {

inline std::string fmt(double v, int precision = 4) {
  std::ostringstream s;
  s.precision(precision);
  s << v;
  return s.str();
}

/// `s` without the spaces and tabs around it.
inline std::string trim_blanks(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos)
    return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

} // namespace fiberbridge
