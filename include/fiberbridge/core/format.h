#pragma once
// Numbers in notes and progress lines: one formatter for every model (significant digits, the
// stream's default notation).
#include <sstream>
#include <string>

namespace fiberbridge {

inline std::string fmt(double v, int precision = 4) {
  std::ostringstream s;
  s.precision(precision);
  s << v;
  return s.str();
}

} // namespace fiberbridge
