#pragma once
// The text encoding of a machine export, detected from its bytes or given by the user, and the
// conversion to UTF-8 with glibc's iconv (no code-page tables of our own). docs/design.md
// section 6, "Text encodings", documents the heuristic and its limits:
//  - a byte-order mark decides (UTF-8, UTF-16LE/BE);
//  - without one, NUL bytes at every other position say UTF-16LE or BE (lab exports are mostly
//    ASCII digits, whose UTF-16 high byte is 0);
//  - text that is valid UTF-8 is UTF-8 (legacy code pages rarely form valid UTF-8 sequences);
//  - otherwise each candidate code page (windows-1252, windows-1250, Shift-JIS (CP932), GB18030,
//    EUC-KR) that converts the whole file strictly is scored by the plausibility of the characters
//    it gives, and the best one wins; ISO-8859-1 (which cannot fail) is the last resort.
// Short headers with few non-ASCII letters can be ambiguous (a Czech "čas" is also a French
// "èas"; a few Korean syllables are also valid Chinese): the user overrides with Test/Encoding
// or --encoding.
#include <string>

namespace fiberbridge {

struct DecodedText {
  std::string utf8;     ///< the text converted to UTF-8, without a byte-order mark
  std::string encoding; ///< "UTF-8", "UTF-16LE", "windows-1250", "Shift-JIS (CP932)", ...
  std::string how;      ///< "byte-order mark", "detected", "NUL pattern", "given" ...
};

/// Converts `raw` to UTF-8. `encoding` empty or "auto" detects it (see the file comment);
/// otherwise it is an iconv name (UTF-8, UTF-16LE, CP1250, SHIFT_JIS, CP932, GBK, GB18030,
/// EUC-KR, ...) and the file must convert under it. Throws InputError naming `source`, the byte,
/// its line and the encoding when the text does not convert (an odd byte count in UTF-16 says a
/// byte was lost), and for an encoding name iconv does not know (`where` names the key).
DecodedText decode_text(const std::string& raw, const std::string& encoding,
                        const std::string& source,
                        const std::string& where = "Test/Encoding or --encoding");

/// `text` for a message: at most `max_chars` bytes (cut at a character boundary, "..." added),
/// control characters (NUL included) written as \xNN so that a message is one readable line.
std::string message_excerpt(const std::string& text, std::size_t max_chars = 80);

} // namespace fiberbridge
