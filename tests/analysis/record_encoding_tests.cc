// Text encodings of machine exports (core/text_encoding.h) and damaged files (issue 42): each
// code page detected from a header as the program writes it, the override, the messages that
// name the encoding, and a damaged tail refused instead of set aside as "results".
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/exported_table.h"
#include "fiberbridge/core/text_encoding.h"

#include "encoded_text.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

using namespace fiberbridge;
using namespace fiberbridge::analysis;

namespace {

const std::string shared = std::string(FIBERBRIDGE_DATA_DIR) + "/dcb_records/DCB-01_Toughness.csv";
const std::string shared_map = "time_s: Time, opening_mm: Disp, load_N: Force, a_mm: CrackExt";

using test_support::encoded;

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class TempFile {
public:
  TempFile(const std::string& name, const std::string& content)
      : path_(::testing::TempDir() + "fb_" + std::to_string(::getpid()) + "_" + name) {
    std::ofstream(path_, std::ios::binary) << content;
  }
  ~TempFile() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

private:
  std::string path_;
};

RecordReadOptions with_map(const std::string& map, const std::string& encoding = "") {
  RecordReadOptions o;
  o.columns = RecordColumnMap::parse(map, "test");
  o.encoding = encoding;
  return o;
}

std::string refusal(const std::string& path, const RecordReadOptions& o) {
  try {
    read_test_records(path, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

/// The shared record with its header replaced by `header` (UTF-8), then encoded.
std::string shared_with_header(const std::string& header, const char* encoding) {
  std::string text = file_text(shared);
  text = header + text.substr(text.find('\n'));
  return encoded(text, encoding);
}

} // namespace

// Headers as the programs write them in each language; the code page is detected from the text
// alone. (A Czech header whose only non-ASCII letters are shared with French, such as "č" read
// as "è", is a documented limit: docs/design.md section 6; the override covers it.)
TEST(RecordEncodings, CodePagesAreDetected) {
  struct Case {
    const char* header;
    const char* encoding;
    const char* detected;
  };
  const Case cases[] = {
      {"Czas,Wydłużenie,Obciążenie,Długość pęknięcia", "CP1250", "windows-1250"},
      {"Temps,Déplacement,Force,Longueur de fissure", "CP1252", "windows-1252"},
      {"Prüfzeit,Standardweg,Standardkraft,Risslänge", "CP1252", "windows-1252"},
      {"時間,ストローク,試験力,き裂長さ", "CP932", "Shift-JIS (CP932)"},
      {"时间,位移,载荷,裂纹长度", "GB18030", "GB18030"},
      {"시간,변위,하중,균열 길이", "EUC-KR", "EUC-KR"},
      {"Time,Disp,Force,CrackExt", "UTF-8", "UTF-8"},
      {"Zeit,Weg,Kraft,Risslänge µm", "UTF-8", "UTF-8"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.header);
    const std::string raw = shared_with_header(c.header, c.encoding);
    const DecodedText d = decode_text(raw, "", "x");
    EXPECT_EQ(d.encoding, c.detected) << d.how;
    EXPECT_EQ(d.utf8.substr(0, d.utf8.find('\n')), c.header);
  }
  // UTF-16 without a byte-order mark, either byte order.
  for (const char* e : {"UTF-16LE", "UTF-16BE"}) {
    const DecodedText d = decode_text(shared_with_header("Time,Disp,Force,CrackExt", e), "", "x");
    EXPECT_EQ(d.encoding, e);
    EXPECT_TRUE(contains(d.how, "NUL bytes")) << d.how;
  }
}

// A Polish Bluehill file read as windows-1252 (here forced, as a wrong guess would): the map
// entry matches nothing, and the message lists the headers as decoded, numbered, and names the
// encoding assumed; the right encoding given reads it.
TEST(RecordEncodings, UnmatchedMapNamesTheEncodingAndTheOverrideReads) {
  TempFile f("pl.csv", shared_with_header("Czas,Wydłużenie,Obciążenie,Pęknięcie", "CP1250"));
  const std::string map =
      "time_s: Czas, opening_mm: Wydłużenie, load_N: Obciążenie, a_mm: Pęknięcie";
  const std::string m = refusal(f.path(), with_map(map, "CP1252"));
  EXPECT_TRUE(contains(m, "pl.csv:1: no column 'Wydłużenie' for opening_mm")) << m;
  EXPECT_TRUE(contains(m, "#3 'Obci¹¿enie'")) << m;
  EXPECT_TRUE(contains(m, "text read as CP1252 (given)")) << m;
  const auto r = read_test_records(f.path(), with_map(map, "windows-1250")).at(0);
  const auto plain = read_test_records(shared, with_map(shared_map)).at(0);
  EXPECT_EQ(r.load, plain.load);
  bool stated = false;
  for (const auto& c : r.cleaning)
    stated |= contains(c, "(text in CP1250, given)");
  EXPECT_TRUE(stated);
  EXPECT_TRUE(contains(refusal(f.path(), with_map(map, "KLINGON")),
                       "encoding 'KLINGON' is not known to iconv"));
}

// A Bluehill export whose last 40 % of bytes are NUL (a crash while writing): refused with the
// line where the damage starts, never read up to it with the rest set aside as "results".
TEST(RecordEncodings, NulTailIsRefused) {
  std::string text = file_text(shared);
  const std::size_t cut = text.size() * 6 / 10;
  std::fill(text.begin() + static_cast<std::ptrdiff_t>(cut), text.end(), '\0');
  TempFile f("nul_tail.csv", text);
  const std::string m = refusal(f.path(), with_map(shared_map));
  EXPECT_TRUE(contains(m, "the file is damaged")) << m;
  EXPECT_TRUE(contains(m, "are not dropped silently")) << m;
  EXPECT_LT(m.size(), 400u) << m;
}

// A binary tail (garbage bytes after the rows): refused, not a trailer.
TEST(RecordEncodings, BinaryTailIsRefused) {
  std::string text = file_text(shared);
  text.resize(text.size() * 7 / 10);
  for (int i = 0; i < 3000; ++i)
    text += static_cast<char>((i * 2654435761u) >> 13);
  TempFile f("binary_tail.csv", text);
  const std::string m = refusal(f.path(), with_map(shared_map));
  EXPECT_TRUE(contains(m, "the file is damaged")) << m;
  EXPECT_LT(m.size(), 400u) << m;
}

// UTF-16 that lost a byte (with or without its byte-order mark): the message names the encoding
// problem instead of reading the misaligned rest as a "trailer".
TEST(RecordEncodings, Utf16WithALostByteIsRefused) {
  for (const bool bom : {true, false}) {
    SCOPED_TRACE(bom);
    std::string u = encoded(file_text(shared), "UTF-16LE");
    u.erase(u.size() / 2 + 1, 1);
    if (bom)
      u = "\xFF\xFE" + u;
    TempFile f("lost_byte.txt", u);
    const std::string m = refusal(f.path(), with_map(shared_map));
    EXPECT_TRUE(contains(m, "UTF-16LE")) << m;
    EXPECT_TRUE(contains(m, "odd number of bytes")) << m;
  }
}

// A 70 kB cell (damage inside a line): the message quotes at most ~80 characters of it, and a
// NUL or control character is written visibly instead of cutting the message.
TEST(RecordEncodings, MessagesAreCapped) {
  std::string text = file_text(shared);
  const std::size_t line5 = [&] {
    std::size_t p = 0;
    for (int k = 0; k < 5; ++k)
      p = text.find('\n', p) + 1;
    return p;
  }();
  const std::size_t comma = text.find(',', line5);
  text.insert(comma + 1, std::string(70000, 'x'));
  TempFile f("long_cell.csv", text);
  const std::string m = refusal(f.path(), with_map(shared_map));
  EXPECT_TRUE(contains(m, "long_cell.csv:6:")) << m.substr(0, 300);
  EXPECT_LT(m.size(), 400u) << m.substr(0, 300);
  EXPECT_EQ(message_excerpt(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(message_excerpt(std::string(100, 'y'), 10), std::string(10, 'y') + "...");
  // Cut at a character boundary: "ż" is two bytes.
  EXPECT_EQ(message_excerpt("abcdefghiżz", 10), "abcdefghiż...");
}
