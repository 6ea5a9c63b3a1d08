#pragma once
// Numbers in notes and progress lines: one formatter for every model (significant digits, the
// stream's default notation); one trim of blanks around a cell or list entry, and one splitter of
// the lists a scene or a command line writes ("beam, fem"; "a_mm: Crack, load_N: Force").
#include <sstream>
#include <string>
#include <vector>

namespace fiberbridge {

inline std::string fmt(double v, int precision = 4) {
  std::ostringstream s;
  s.precision(precision);
  s << v;
  return s.str();
}

/// The blanks around a cell of a file read line by line: a file with CRLF line ends leaves the
/// '\r' on the last cell of each line.
inline constexpr const char* cell_blanks = " \t\r";

/// `s` without the `blanks` (spaces and tabs unless told) around it.
inline std::string trim_blanks(const std::string& s, const char* blanks = " \t") {
  const auto b = s.find_first_not_of(blanks);
  if (b == std::string::npos)
    return "";
  return s.substr(b, s.find_last_not_of(blanks) - b + 1);
}

/// The items of a list as a scene writes them ("beam, fem"; "Key = 1, 2"), split at every
/// `separator` (no quoting), `blanks` around each item removed, empty items dropped.
inline std::vector<std::string> split_list(const std::string& s, char separator,
                                           const char* blanks = " \t") {
  std::vector<std::string> out;
  for (std::size_t b = 0; b <= s.size();) {
    auto e = s.find(separator, b);
    if (e == std::string::npos)
      e = s.size();
    std::string item = trim_blanks(s.substr(b, e - b), blanks);
    if (!item.empty())
      out.push_back(std::move(item));
    b = e + 1;
  }
  return out;
}

} // namespace fiberbridge
