#pragma once
// A model's state as bytes and back, bit for bit (the checkpoints that `--resume` continues
// from): values are appended in their in-memory form, so a double comes back with every bit,
// NaN included. The file is meant to be read back on the machine that wrote it (a cluster job
// resumed where it was killed): the header records the byte order and the reader refuses another.
// Every read is bounds-checked; a short or damaged file is an InputError naming it, never a crash.
#include <array>
#include <cstdint>
#include <cstring>
#include <deque>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace fiberbridge {

class BinaryWriter {
public:
  /// Starts the file with `magic` (a short text naming the kind of file) and `version`.
  BinaryWriter(const std::string& magic, std::uint32_t version);

  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>, "put() copies bytes");
    bytes_.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  void put(const std::string& s);
  template <class T>
  void put(const std::vector<T>& v) {
    put(static_cast<std::uint64_t>(v.size()));
    for (const auto& x : v)
      put(x);
  }
  template <class T>
  void put(const std::deque<T>& v) {
    put(static_cast<std::uint64_t>(v.size()));
    for (const auto& x : v)
      put(x);
  }
  template <class A, class B>
  void put(const std::pair<A, B>& p) {
    put(p.first);
    put(p.second);
  }

  /// The bytes with a trailing checksum (FNV-1a 64 of everything before it).
  std::string finish() const;

private:
  std::string bytes_;
};

class BinaryReader {
public:
  /// Checks the header (magic, version, byte order) and the checksum; `source` names the file
  /// in every error. Throws InputError when the bytes are not such a file of this version.
  BinaryReader(std::string bytes, const std::string& magic, std::uint32_t version,
               std::string source);

  template <class T>
  void get(T& v) {
    static_assert(std::is_trivially_copyable_v<T>, "get() copies bytes");
    need(sizeof(T));
    std::memcpy(&v, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
  }
  void get(std::string& s);
  template <class T>
  void get(std::vector<T>& v) {
    v.resize(count(min_size<T>()));
    for (auto& x : v)
      get(x);
  }
  template <class T>
  void get(std::deque<T>& v) {
    v.resize(count(min_size<T>()));
    for (auto& x : v)
      get(x);
  }
  template <class A, class B>
  void get(std::pair<A, B>& p) {
    get(p.first);
    get(p.second);
  }
  template <class T>
  T get() {
    T v{};
    get(v);
    return v;
  }
  /// Throws unless every byte was read (a file of another layout with the same version).
  void expect_end() const;
  const std::string& source() const { return source_; }

private:
  /// Fewest bytes one element takes in the file (a string or a pair may take fewer than its
  /// sizeof).
  template <class T>
  static constexpr std::size_t min_size() {
    return std::is_trivially_copyable_v<T> ? sizeof(T) : 1;
  }
  void need(std::size_t n) const;
  /// Reads an element count and checks that at least count * min_size bytes remain.
  std::size_t count(std::size_t min_size);
  std::string bytes_;
  std::string source_;
  std::size_t pos_ = 0, end_ = 0;
};

/// FNV-1a 64-bit hash of n bytes (the file checksum; also a compact fingerprint of long inputs).
std::uint64_t checksum64(const void* data, std::size_t n);

/// Reads a whole file as bytes; InputError naming it when it cannot be read.
std::string read_file_bytes(const std::string& path);

} // namespace fiberbridge
