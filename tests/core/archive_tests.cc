// The one archive (core/binary_archive.h, core/json_archive.h; docs/design.md section 4, "One
// archive (issue 30 item 4)"): every kind of value it writes comes back exactly (doubles bit for
// bit with NaN, infinities, -0 and subnormals; empty lists; strings holding any byte), and bytes
// that are not such an archive (cut short, damaged, of another kind or version, not an archive at
// all) are an InputError naming the source, never a crash or a wrong value.
#include "fiberbridge/core/binary_archive.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/json_archive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <deque>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using namespace fiberbridge;

namespace {

/// The bits of a double (NaN != NaN, and -0 == 0: values are compared by their bits).
std::uint64_t bits(double v) {
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

template <class T>
T round_trip(const T& v) {
  return from_archive_bytes<T>(to_archive_bytes(v, "test value"), "test value");
}

/// Doubles whose decimal form, or whose arithmetic, would lose something.
std::vector<double> awkward_doubles() {
  double payload_nan = 0;
  const std::uint64_t nan_bits = 0x7ff8000000001234ULL; // a NaN with a payload
  std::memcpy(&payload_nan, &nan_bits, sizeof payload_nan);
  return {0.1 + 0.2,
          1.0 / 3.0,
          -0.0,
          std::numeric_limits<double>::quiet_NaN(),
          -std::numeric_limits<double>::quiet_NaN(),
          payload_nan,
          std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::denorm_min(),
          std::numeric_limits<double>::max(),
          std::numeric_limits<double>::lowest(),
          412.123456789012345};
}

/// A string with every byte value, the zero byte and invalid UTF-8 included.
std::string every_byte() {
  std::string s;
  for (int c = 0; c < 256; ++c)
    s.push_back(static_cast<char>(c));
  return s + std::string("\0\xff\xfe", 3);
}

} // namespace

TEST(Archive, DoublesComeBackBitForBit) {
  for (const double v : awkward_doubles())
    EXPECT_EQ(bits(round_trip(v)), bits(v)) << v;
  const auto list = awkward_doubles();
  const auto back = round_trip(list);
  ASSERT_EQ(back.size(), list.size());
  for (std::size_t i = 0; i < list.size(); ++i)
    EXPECT_EQ(bits(back[i]), bits(list[i])) << i;
}

TEST(Archive, IntegersFlagsAndTheirLimitsComeBack) {
  EXPECT_EQ(round_trip(std::numeric_limits<std::int64_t>::min()),
            std::numeric_limits<std::int64_t>::min());
  EXPECT_EQ(round_trip(std::numeric_limits<std::uint64_t>::max()),
            std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(round_trip(-7), -7);
  EXPECT_TRUE(round_trip(true));
  EXPECT_FALSE(round_trip(false));
}

TEST(Archive, StringsHoldAnyByte) {
  EXPECT_EQ(round_trip(every_byte()), every_byte());
  EXPECT_EQ(round_trip(std::string()), "");
  const std::vector<std::string> list = {"", every_byte(), "a, b; c\n", std::string(1, '\0')};
  EXPECT_EQ(round_trip(list), list);
}

TEST(Archive, EmptyAndNestedListsComeBack) {
  EXPECT_TRUE(round_trip(std::vector<double>{}).empty());
  EXPECT_TRUE(round_trip(std::vector<std::string>{}).empty());
  EXPECT_TRUE(round_trip(std::deque<int>{}).empty());
  const std::vector<std::vector<double>> nested = {{}, {1.5}, {}, {2.5, -3.25}};
  EXPECT_EQ(round_trip(nested), nested);
  const std::vector<std::pair<std::string, std::string>> pairs = {{"Section/Key", "1, 2"},
                                                                  {"", every_byte()}};
  EXPECT_EQ(round_trip(pairs), pairs);
  const std::deque<std::pair<double, int>> dq = {{0.5, 1}, {-2.0, 3}};
  EXPECT_EQ(round_trip(dq), dq);
}

TEST(Archive, JsonKeepsItsNumbersAndNonFiniteDoubles) {
  Json j = {{"name", every_byte()},
            {"third", 1.0 / 3.0},
            {"n", -42},
            {"list", Json::array({1, "two", nullptr, true})},
            {"empty", Json::object()},
            {"nan", std::numeric_limits<double>::quiet_NaN()}};
  const Json back = round_trip(j);
  EXPECT_EQ(bits(back["third"].get<double>()), bits(1.0 / 3.0));
  EXPECT_TRUE(std::isnan(back["nan"].get<double>())) << "JSON text would have made it null";
  EXPECT_EQ(back.at("name").get<std::string>(), every_byte());
  j.erase("nan");
  Json back_rest = back;
  back_rest.erase("nan");
  EXPECT_EQ(back_rest, j);
  EXPECT_EQ(round_trip(Json()), Json());
}

TEST(Archive, SeveralValuesReadBackInTheirOrder) {
  BinaryWriter out("test file", 3);
  out.put(std::string("first"));
  out.put(2.5);
  out.put(std::vector<int>{1, 2, 3});
  out.put(true);
  BinaryReader in(out.finish(), "test file", 3, "some.bin");
  EXPECT_EQ(in.get<std::string>(), "first");
  EXPECT_EQ(in.get<double>(), 2.5);
  EXPECT_EQ(in.get<std::vector<int>>(), (std::vector<int>{1, 2, 3}));
  EXPECT_TRUE(in.get<bool>());
  EXPECT_NO_THROW(in.expect_end());
}

namespace {

/// The message of the InputError that reading `bytes` as a one-string archive throws ("" when
/// none).
std::string error_reading(std::string bytes) {
  try {
    BinaryReader in(std::move(bytes), "test file", 3, "dir/some.bin");
    in.get<std::vector<double>>();
    in.get<std::string>();
    in.expect_end();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string sample() {
  BinaryWriter out("test file", 3);
  out.put(awkward_doubles());
  out.put(every_byte());
  return out.finish();
}

} // namespace

TEST(Archive, EveryCutOfAFileIsAClearError) {
  const std::string whole = sample();
  ASSERT_EQ(error_reading(whole), "");
  for (std::size_t n = 0; n < whole.size(); ++n) {
    const std::string e = error_reading(whole.substr(0, n));
    EXPECT_EQ(e.rfind("dir/some.bin: ", 0), 0u) << "cut at " << n << ": " << e;
  }
}

TEST(Archive, ADamagedByteIsCaughtByTheChecksum) {
  std::string bytes = sample();
  bytes[bytes.size() / 2] ^= 0x10;
  EXPECT_NE(error_reading(bytes).find("(checksum mismatch)"), std::string::npos);
}

TEST(Archive, ForeignBytesAreNamedAsSuch) {
  // Not an archive: a CSV, a CBOR document (a resume record of before issue 30), nothing.
  const std::vector<std::uint8_t> cbor = Json::to_cbor(Json{{"format", "x"}, {"version", 1}});
  for (const std::string& foreign :
       {std::string("time_s,load_N\n0,1\n2,3\n"), std::string(cbor.begin(), cbor.end()),
        std::string(), std::string(100, '\xff')}) {
    const std::string e = error_reading(foreign);
    EXPECT_EQ(e.rfind("dir/some.bin: ", 0), 0u) << e;
    EXPECT_NE(e.find("expected a test file file of format version 3"), std::string::npos) << e;
  }
  // An archive of another kind, and one of another version.
  BinaryWriter other("other file", 3);
  other.put(1.0);
  EXPECT_NE(error_reading(other.finish()).find("not a checkpoint of this kind"), std::string::npos);
  BinaryWriter older("test file", 2);
  older.put(1.0);
  EXPECT_NE(error_reading(older.finish()).find("written by another version of fiberbridge"),
            std::string::npos);
}

TEST(Archive, ALayoutThatDoesNotMatchIsAClearError) {
  // A list longer than the file, a flag that is neither 0 nor 1, bytes left over: an archive
  // of the right kind and version whose content was written by other code.
  BinaryWriter long_list("test file", 3);
  long_list.put(std::uint64_t(1) << 60);
  EXPECT_NE(error_reading(long_list.finish()).find("longer than the rest of the file"),
            std::string::npos);

  BinaryWriter flag("test file", 3);
  flag.put(std::uint8_t(2));
  BinaryReader in(flag.finish(), "test file", 3, "flag.bin");
  EXPECT_THROW(in.get<bool>(), InputError);

  BinaryWriter extra("test file", 3);
  extra.put(std::vector<double>{});
  extra.put(std::string("s"));
  extra.put(1.0);
  EXPECT_NE(error_reading(extra.finish()).find("bytes left over"), std::string::npos);

  // A JSON block whose bytes are not CBOR.
  BinaryWriter json("test file", 3);
  json.put(std::string("\xff\xff", 2));
  BinaryReader jin(json.finish(), "test file", 3, "json.bin");
  try {
    jin.get<Json>();
    ADD_FAILURE() << "a JSON block of bad CBOR was read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("json.bin: ", 0), 0u) << e.what();
  }
}
