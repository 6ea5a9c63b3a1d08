#include "fiberbridge/core/binary_archive.h"

#include "fiberbridge/core/error.h"

#include <fstream>
#include <sstream>

namespace fiberbridge {

namespace {

constexpr std::uint32_t byte_order_mark = 0x01020304;

} // namespace

std::uint64_t checksum64(const void* data, std::size_t n) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::uint64_t h = 1469598103934665603ULL;
  for (std::size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 1099511628211ULL;
  }
  return h;
}

BinaryWriter::BinaryWriter(const std::string& magic, std::uint32_t version) {
  put(magic);
  put(version);
  put(byte_order_mark);
  put(static_cast<std::uint32_t>(sizeof(double)));
}

void BinaryWriter::put(const std::string& s) {
  put(static_cast<std::uint64_t>(s.size()));
  bytes_ += s;
}

std::string BinaryWriter::finish() const {
  std::string out = bytes_;
  const std::uint64_t h = checksum64(out.data(), out.size());
  out.append(reinterpret_cast<const char*>(&h), sizeof h);
  return out;
}

BinaryReader::BinaryReader(std::string bytes, const std::string& magic, std::uint32_t version,
                           std::string source)
    : bytes_(std::move(bytes)), source_(std::move(source)) {
  const std::string what =
      " (expected a " + magic + " file of format version " + std::to_string(version) + ")";
  std::uint64_t h = 0;
  if (bytes_.size() < sizeof h)
    throw InputError(source_ + ": empty or truncated" + what);
  end_ = bytes_.size() - sizeof h;
  std::memcpy(&h, bytes_.data() + end_, sizeof h);
  // The magic first: a file of another kind is named as such, not as damaged.
  std::uint64_t n = 0;
  if (end_ < sizeof n)
    throw InputError(source_ + ": truncated" + what);
  std::memcpy(&n, bytes_.data(), sizeof n);
  if (n != magic.size() || end_ < sizeof n + n || bytes_.compare(sizeof n, n, magic) != 0)
    throw InputError(source_ + ": not a checkpoint of this kind" + what);
  if (checksum64(bytes_.data(), end_) != h)
    throw InputError(source_ + ": damaged or cut short (checksum mismatch)" + what);
  pos_ = sizeof n + n;
  const auto v = get<std::uint32_t>();
  if (v != version)
    throw InputError(source_ + ": written by another version of fiberbridge (format version " +
                     std::to_string(v) + ")" + what);
  if (get<std::uint32_t>() != byte_order_mark ||
      get<std::uint32_t>() != static_cast<std::uint32_t>(sizeof(double)))
    throw InputError(source_ + ": written on a machine with another byte order" + what);
}

void BinaryReader::need(std::size_t n) const {
  if (n > end_ - pos_)
    throw InputError(source_ + ": ends early (byte " + std::to_string(pos_) + " of " +
                     std::to_string(end_) + "): the file does not match this version's layout");
}

std::size_t BinaryReader::count(std::size_t min_size) {
  const auto n = get<std::uint64_t>();
  if (min_size > 0 && n > (end_ - pos_) / min_size)
    throw InputError(source_ + ": a list of " + std::to_string(n) +
                     " entries is longer than the rest of the file");
  return static_cast<std::size_t>(n);
}

void BinaryReader::get(bool& b) {
  const auto byte = get<std::uint8_t>();
  if (byte > 1)
    throw InputError(source_ + ": byte " + std::to_string(pos_ - 1) + " holds " +
                     std::to_string(byte) +
                     " where a true/false flag was expected: the file does not match this "
                     "version's layout");
  b = byte == 1;
}

void BinaryReader::get(std::string& s) {
  const std::size_t n = count(1);
  need(n);
  s.assign(bytes_, pos_, n);
  pos_ += n;
}

void BinaryReader::expect_end() const {
  if (pos_ != end_)
    throw InputError(source_ + ": " + std::to_string(end_ - pos_) +
                     " bytes left over after the state: the file does not match this version's "
                     "layout");
}

std::string read_file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path + ": cannot open for reading");
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad())
    throw InputError(path + ": read failed");
  return s.str();
}

} // namespace fiberbridge
