#pragma once
// Numbers in notes, messages and progress lines: one formatter for every library (significant
// digits, the stream's default notation); one trim of blanks around a cell or list entry, one
// splitter of the lists a scene or a command line writes ("beam, fem"; "a_mm: Crack, load_N:
// Force"), and one way to make a name part of a file name.
#include <cctype>
#include <sstream>
#include <string>
#include <vector>

namespace fiberbridge {

/// `v` with `precision` significant digits in the stream's default notation (printf's %.<p>g:
/// "0.0275", "347", "1e+06", "nan", "inf").
inline std::string fmt(double v, int precision = 4) {
  std::ostringstream s;
  s.precision(precision);
  s << v;
  return s.str();
}

/// `v` as a stream prints it unless told otherwise (6 significant digits): the form of the input
/// readers' and checks' messages, so that a value quoted back reads as the user wrote it.
inline std::string num(double v) {
  return fmt(v, 6);
}

/// `text` as a part of a file name: letters, digits, '-' and '_' kept, every other byte '_'
/// ("PVA control" -> "PVA_control").
inline std::string file_name_part(const std::string& text) {
  std::string o;
  for (char c : text)
    o += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
  return o;
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
