// Text encodings of machine exports: detection and conversion with iconv (text_encoding.h).
#include "fiberbridge/core/text_encoding.h"

#include "fiberbridge/core/error.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <iconv.h>
#include <optional>
#include <vector>

namespace fiberbridge {

namespace {

/// Result of one strict conversion: the text, or where it failed.
struct Conversion {
  bool ok = false;
  std::string utf8;
  std::size_t bad_offset = 0; ///< byte offset in the input of the first byte that did not convert
  bool incomplete = false;    ///< the input ended inside a character
};

/// Strict conversion (no //IGNORE, no //TRANSLIT): an invalid byte stops it.
Conversion convert(const std::string& raw, std::size_t from, const char* encoding) {
  Conversion c;
  iconv_t cd = iconv_open("UTF-8", encoding);
  if (cd == reinterpret_cast<iconv_t>(-1))
    return c;
  std::vector<char> out(4096);
  char* in = const_cast<char*>(raw.data()) + from;
  std::size_t in_left = raw.size() - from;
  c.utf8.reserve(in_left + in_left / 2);
  while (true) {
    char* o = out.data();
    std::size_t o_left = out.size();
    const std::size_t r = iconv(cd, &in, &in_left, &o, &o_left);
    c.utf8.append(out.data(), o - out.data());
    if (r != static_cast<std::size_t>(-1)) {
      if (in_left == 0) {
        c.ok = true;
        break;
      }
      continue;
    }
    if (errno == E2BIG)
      continue;
    c.bad_offset = static_cast<std::size_t>(in - raw.data());
    c.incomplete = errno == EINVAL;
    break;
  }
  iconv_close(cd);
  return c;
}

bool known_to_iconv(const std::string& encoding) {
  iconv_t cd = iconv_open("UTF-8", encoding.c_str());
  if (cd == reinterpret_cast<iconv_t>(-1))
    return false;
  iconv_close(cd);
  return true;
}

std::string upper(std::string s) {
  for (auto& c : s)
    if (c >= 'a' && c <= 'z')
      c = static_cast<char>(c - 'a' + 'A');
  return s;
}

/// Next code point of UTF-8 text at i (the text came from iconv: valid).
char32_t next_code_point(const std::string& s, std::size_t& i) {
  const auto c = static_cast<unsigned char>(s[i]);
  const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : 4;
  char32_t cp = n == 1 ? c : n == 2 ? (c & 0x1F) : n == 3 ? (c & 0x0F) : (c & 0x07);
  for (std::size_t k = 1; k < n && i + k < s.size(); ++k)
    cp = (cp << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
  i += n;
  return cp;
}

bool ascii_letter(char32_t c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

/// Letters of Central European languages that windows-1252 does not have (where windows-1250
/// puts them, windows-1252 has symbols such as '¹' and '¿'): evidence for windows-1250.
bool central_european_letter(char32_t c) {
  static const char32_t letters[] = {0x104, 0x105, 0x118, 0x119, 0x141, 0x142, 0x143, 0x144, 0x15A,
                                     0x15B, 0x179, 0x17A, 0x17B, 0x17C, 0x106, 0x107, 0x158, 0x159,
                                     0x11A, 0x11B, 0x16E, 0x16F, 0x150, 0x151, 0x170, 0x171, 0x164,
                                     0x165, 0x10E, 0x10F, 0x13D, 0x13E, 0x139, 0x13A, 0x147, 0x148};
  return std::find(std::begin(letters), std::end(letters), c) != std::end(letters);
}

/// How plausible the characters `utf8` holds are as a lab export's text in `encoding`: a sum
/// over non-ASCII characters, positive for letters and scripts the encoding is written for,
/// negative for what a wrong guess produces (C1 controls, stray symbols, half-width katakana,
/// private-use and rare ideographs). The weights are judgement, documented in docs/design.md
/// section 6 with their limits; the user overrides with Test/Encoding.
double plausibility(const std::string& utf8, const std::string& encoding) {
  const bool korean = encoding == "EUC-KR";
  double score = 0;
  char32_t before = 0;
  std::size_t i = 0;
  char32_t c = utf8.empty() ? 0 : next_code_point(utf8, i);
  while (c) {
    const char32_t after = i < utf8.size() ? next_code_point(utf8, i) : 0;
    if (c >= 0x80) {
      const bool latin_letter = c >= 0xC0 && c <= 0x24F && c != 0xD7 && c != 0xF7;
      if (latin_letter) {
        // A letter inside a word of ASCII letters is what text looks like; a lone one between
        // other non-ASCII characters is what a multi-byte text read byte by byte looks like.
        const bool in_word = ascii_letter(before) || ascii_letter(after);
        score += in_word ? (central_european_letter(c) ? 3 : 2) : 0.5;
      } else if ((c == 0xB2 || c == 0xB3) && (before == 'm' || before == 'M')) {
        score += 3; // mm², mm³
      } else if (c == 0xB0 || c == 0xB5 || c == 0xB1 || c == 0xB2 || c == 0xB3 || c == 0x20AC ||
                 c == 0xA7) {
        score += 1; // °, µ, ±, ², ³, €, §
      } else if (c >= 0x80 && c <= 0x9F) {
        score -= 3; // C1 controls: no code page writes them for text
      } else if (c >= 0xA0 && c <= 0xBF) {
        score -= 2; // '¹', '¿', '¤', '¦', ... where another code page has letters
      } else if (c >= 0x3000 && ascii_letter(before) && ascii_letter(after)) {
        score -= 2; // an ideograph inside a Latin word: a Latin letter's byte and the next
                    // letter read as one double-byte character ("Déplacement" as Shift-JIS)
      } else if (c >= 0x3040 && c <= 0x30FF) {
        score += 4; // hiragana, katakana
      } else if (c >= 0xAC00 && c <= 0xD7A3) {
        score += 4; // hangul syllables
      } else if (c >= 0x4E00 && c <= 0x9FFF) {
        score += korean ? 1 : 3; // hanja are rare in modern Korean text
      } else if ((c >= 0x3000 && c <= 0x303F) || (c >= 0xFF01 && c <= 0xFF5E)) {
        score += 2; // CJK punctuation, full-width forms
      } else if (c >= 0xFF61 && c <= 0xFF9F) {
        score -= 1; // half-width katakana: Latin-1 bytes read as Shift-JIS
      } else if ((c >= 0xE000 && c <= 0xF8FF) || (c >= 0x3400 && c <= 0x4DBF) ||
                 (c >= 0xF900 && c <= 0xFAFF) || c >= 0x10000) {
        score -= 3; // private use, rare ideographs: a wrong multi-byte guess
      }
    }
    before = c;
    c = after;
  }
  return score;
}

/// GB18030 reads most byte pairs; Japanese or Korean text read as GB18030 falls into its
/// extension areas (lead byte below 0xB0 or trail below 0xA1, four-byte sequences) where rare
/// ideographs are. Chinese text in GB2312's main area (both bytes 0xB0/0xA1-0xFE) does not.
double gb18030_rarity(const std::string& raw) {
  double penalty = 0;
  for (std::size_t i = 0; i + 1 < raw.size();) {
    const auto lead = static_cast<unsigned char>(raw[i]);
    const auto trail = static_cast<unsigned char>(raw[i + 1]);
    if (lead < 0x80) {
      ++i;
      continue;
    }
    if (trail >= 0x30 && trail <= 0x39) {
      penalty += 4;
      i += 4;
      continue;
    }
    if (lead >= 0xAA && (lead < 0xB0 || trail < 0xA1))
      penalty += 4;
    else if (lead >= 0x81 && lead < 0xA1)
      penalty += 4;
    i += 2;
  }
  return penalty;
}

std::size_t line_at(const std::string& utf8_so_far) {
  return 1 + static_cast<std::size_t>(std::count(utf8_so_far.begin(), utf8_so_far.end(), '\n'));
}

std::string hex_byte(unsigned char b) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%02X", b);
  return buf;
}

/// The error for a file that does not convert under `encoding`.
[[noreturn]] void not_convertible(const std::string& raw, const Conversion& c,
                                  const std::string& encoding, const std::string& how,
                                  const std::string& source, const std::string& where) {
  const std::string at = source + ":" + std::to_string(line_at(c.utf8));
  const bool utf16 = encoding.rfind("UTF-16", 0) == 0;
  if (utf16 && c.incomplete)
    throw InputError(at + ": the text is " + encoding + " (" + how + ") but has an odd number of " +
                     "bytes (" + std::to_string(raw.size()) +
                     "): a byte was lost or the file was cut, and the text after the loss is "
                     "misaligned; re-export the file");
  if (c.incomplete)
    throw InputError(at + ": the file ends inside a character of " + encoding + " (" + how +
                     "): it was cut; re-export it, or give the encoding with " + where);
  throw InputError(at + ": byte " + hex_byte(static_cast<unsigned char>(raw[c.bad_offset])) +
                   " at offset " + std::to_string(c.bad_offset) + " is not " + encoding + " (" +
                   how + "); give the file's encoding with " + where +
                   " (e.g. CP1252, CP1250, CP932, GB18030, EUC-KR, UTF-16LE)");
}

/// UTF-16 without a byte-order mark: ASCII text has a NUL high byte in every other position.
std::optional<std::string> utf16_by_nul_pattern(const std::string& raw) {
  const std::size_t n = std::min<std::size_t>(raw.size(), 4096) / 2 * 2;
  if (n < 16)
    return std::nullopt;
  std::size_t even = 0, odd = 0;
  for (std::size_t i = 0; i < n; i += 2) {
    even += raw[i] == '\0';
    odd += raw[i + 1] == '\0';
  }
  const std::size_t pairs = n / 2;
  if (odd * 10 >= pairs * 3 && even * 20 <= pairs)
    return std::string("UTF-16LE");
  if (even * 10 >= pairs * 3 && odd * 20 <= pairs)
    return std::string("UTF-16BE");
  return std::nullopt;
}

/// The encoding a user may write for what we report ("windows-1250" -> CP1250).
std::string iconv_name(const std::string& given) {
  const std::string u = upper(given);
  if (u.rfind("WINDOWS-", 0) == 0)
    return "CP" + u.substr(8);
  if (u == "SHIFT-JIS" || u == "SHIFT_JIS (CP932)" || u == "SHIFT-JIS (CP932)")
    return "CP932";
  if (u == "LATIN-1" || u == "LATIN1")
    return "ISO-8859-1";
  return u;
}

} // namespace

DecodedText decode_text(const std::string& raw, const std::string& encoding,
                        const std::string& source, const std::string& where) {
  const auto starts = [&](const char* bom, std::size_t n) {
    return raw.compare(0, n, bom, n) == 0;
  };
  const bool bom8 = starts("\xEF\xBB\xBF", 3), bom16le = starts("\xFF\xFE", 2),
             bom16be = starts("\xFE\xFF", 2);
  const std::string given = encoding == "auto" ? "" : encoding;
  DecodedText d;
  std::size_t from = 0;
  if (!given.empty()) {
    const std::string name = iconv_name(given);
    if (!known_to_iconv(name))
      throw InputError(source + ": " + where + ": encoding '" + given +
                       "' is not known to iconv; expected auto or a name such as UTF-8, UTF-16LE, "
                       "UTF-16BE, CP1252, CP1250, CP932 (Shift-JIS), GB18030, GBK, EUC-KR "
                       "(`iconv -l` lists them)");
    d.encoding = name;
    d.how = "given";
    const bool utf16 = name.rfind("UTF-16", 0) == 0;
    from = (name == "UTF-8" && bom8) ? 3 : (utf16 && (bom16le || bom16be)) ? 2 : 0;
  } else if (bom8) {
    d = {"", "UTF-8", "byte-order mark"};
    from = 3;
  } else if (bom16le || bom16be) {
    d = {"", bom16le ? "UTF-16LE" : "UTF-16BE", "byte-order mark"};
    from = 2;
  } else if (const auto utf16 = utf16_by_nul_pattern(raw)) {
    d = {"", *utf16, "no byte-order mark; detected from the NUL bytes"};
  } else {
    Conversion utf8 = convert(raw, 0, "UTF-8");
    if (utf8.ok) {
      d = {std::move(utf8.utf8), "UTF-8", "detected"};
      return d;
    }
    // Not UTF-8: the code page whose reading is the most plausible. windows-1252 first: on a
    // tie the Western code page wins, being the commonest.
    static const char* const candidates[][2] = {{"CP1252", "windows-1252"},
                                                {"CP1250", "windows-1250"},
                                                {"CP932", "Shift-JIS (CP932)"},
                                                {"GB18030", "GB18030"},
                                                {"EUC-KR", "EUC-KR"}};
    double best = 0;
    bool found = false;
    std::string report;
    for (const auto& candidate : candidates) {
      Conversion c = convert(raw, 0, candidate[0]);
      if (!c.ok)
        continue;
      double score = plausibility(c.utf8, candidate[1]);
      if (std::string(candidate[0]) == "GB18030")
        score -= gb18030_rarity(raw);
      if (!found || score > best) {
        found = true;
        best = score;
        d.utf8 = std::move(c.utf8);
        d.encoding = candidate[1];
      }
    }
    if (found) {
      d.how = "detected: not UTF-8, the most plausible of windows-1252, windows-1250, "
              "Shift-JIS, GB18030 and EUC-KR";
      return d;
    }
    // Every byte is a character in ISO-8859-1: the last resort, stated as such.
    Conversion latin1 = convert(raw, 0, "ISO-8859-1");
    d = {std::move(latin1.utf8), "ISO-8859-1",
         "detected: not UTF-8 nor any code page tried (" + std::string("byte ") +
             hex_byte(static_cast<unsigned char>(raw[utf8.bad_offset])) + " at offset " +
             std::to_string(utf8.bad_offset) + " fits none)"};
    return d;
  }
  Conversion c = convert(raw, from, d.encoding.c_str());
  if (!c.ok) {
    not_convertible(raw, c, d.encoding, d.how, source, where);
  }
  d.utf8 = std::move(c.utf8);
  return d;
}

std::string message_excerpt(const std::string& text, std::size_t max_chars) {
  std::string out;
  std::size_t i = 0;
  for (; i < text.size() && out.size() < max_chars; ++i) {
    const auto b = static_cast<unsigned char>(text[i]);
    if (b < 0x20 || b == 0x7F)
      out += "\\x" + hex_byte(b).substr(2);
    else
      out += text[i];
  }
  // Not inside a UTF-8 sequence: continuation bytes are 10xxxxxx.
  while (i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80)
    out += text[i++];
  if (i < text.size())
    out += "...";
  return out;
}

} // namespace fiberbridge
