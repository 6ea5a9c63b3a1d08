// Test helper: a UTF-8 text in another code page, as a program on a Windows (or a Japanese,
// Polish, ... system) with that code page writes it. Shared by the record encoding and layout
// tests.
#pragma once

#include <iconv.h>

#include <stdexcept>
#include <string>

namespace fiberbridge::test_support {

/// `utf8` in code page `encoding` (glibc's iconv names: "CP1250", "SHIFT_JIS", "UTF-16LE", ...).
/// Throws when iconv lacks the code page or a character has no representation in it.
inline std::string encoded(const std::string& utf8, const char* encoding) {
  iconv_t cd = iconv_open(encoding, "UTF-8");
  if (cd == reinterpret_cast<iconv_t>(-1))
    throw std::runtime_error(std::string("iconv has no ") + encoding);
  std::string out(4 * utf8.size() + 16, '\0');
  char* in = const_cast<char*>(utf8.data());
  std::size_t in_left = utf8.size(), out_left = out.size();
  char* o = out.data();
  const std::size_t r = iconv(cd, &in, &in_left, &o, &out_left);
  iconv_close(cd);
  if (r == static_cast<std::size_t>(-1))
    throw std::runtime_error(std::string("not representable in ") + encoding);
  out.resize(out.size() - out_left);
  return out;
}

} // namespace fiberbridge::test_support
