#pragma once
// The one archive of fiberbridge (docs/design.md section 4, "One archive (issue 30 item 4)"):
// every value that crosses between MPI ranks (a task's result) or is kept for `--resume` (a
// finished unit, a model's checkpoint) is written and read here, bit for bit: a double comes back
// with every bit, NaN included. A file is meant to be read back on the machine that wrote it (a
// cluster job resumed where it was killed): the header records the byte order and the reader
// refuses another. Every read is bounds-checked; a short, damaged or foreign file is an InputError
// naming it, never a crash.
//
// What can be written: numbers (copied as they are in memory), bool (one byte, checked on
// reading), strings (any bytes), std::vector / std::deque / std::pair of those, any other
// trivially copyable struct (its bytes), and every type T with a BinaryCodec<T> specialization:
// its save and load side by side, the one way that T is written and read (as boost::serialization's
// save/load pairs or deal.II's serialize members). A type with neither does not compile.
#include <array>
#include <cstdint>
#include <cstring>
#include <deque>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace fiberbridge {

class BinaryWriter;
class BinaryReader;

/// Specialize for a type that is not trivially copyable (or whose bytes alone are not a safe
/// record: an enum, a struct with a bool):
///   template <> struct BinaryCodec<T> {
///     static void save(BinaryWriter& out, const T& v);
///     static void load(BinaryReader& in, T& v);
///   };
/// `save` writes at least one byte (the reader's bound on a list length assumes so); `load` checks
/// what it reads and throws InputError (naming in.source()) when it cannot be a T.
template <class T, class Enable = void>
struct BinaryCodec {};

namespace archive_detail {
template <class T, class = void>
struct has_codec : std::false_type {};
template <class T>
struct has_codec<T, std::void_t<decltype(&BinaryCodec<T>::save), decltype(&BinaryCodec<T>::load)>>
    : std::true_type {};
/// Written as their bytes: numbers and plain structs (not bool, enums, pointers, or a type with
/// a codec).
template <class T>
constexpr bool as_bytes = std::is_trivially_copyable_v<T> && !std::is_same_v<T, bool> &&
                          !std::is_enum_v<T> && !std::is_pointer_v<T> && !has_codec<T>::value;
} // namespace archive_detail

class BinaryWriter {
public:
  /// Starts the file with `magic` (a short text naming the kind of file) and `version`.
  BinaryWriter(const std::string& magic, std::uint32_t version);

  template <class T>
  void put(const T& v) {
    if constexpr (archive_detail::has_codec<T>::value) {
      BinaryCodec<T>::save(*this, v);
    } else {
      static_assert(archive_detail::as_bytes<T>,
                    "no BinaryCodec<T> for this type (core/binary_archive.h)");
      bytes_.append(reinterpret_cast<const char*>(&v), sizeof(T));
    }
  }
  void put(bool b) { put(static_cast<std::uint8_t>(b ? 1 : 0)); }
  void put(const std::string& s);
  void put(const char* s) { put(std::string(s)); }
  template <class T>
  void put(const std::vector<T>& v) {
    put(static_cast<std::uint64_t>(v.size()));
    if constexpr (archive_detail::as_bytes<T>)
      bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
    else
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
    if constexpr (archive_detail::has_codec<T>::value) {
      BinaryCodec<T>::load(*this, v);
    } else {
      static_assert(archive_detail::as_bytes<T>,
                    "no BinaryCodec<T> for this type (core/binary_archive.h)");
      need(sizeof(T));
      std::memcpy(&v, bytes_.data() + pos_, sizeof(T));
      pos_ += sizeof(T);
    }
  }
  void get(bool& b);
  void get(std::string& s);
  template <class T>
  void get(std::vector<T>& v) {
    v.resize(count(min_size<T>()));
    if constexpr (archive_detail::as_bytes<T>) {
      need(v.size() * sizeof(T)); // count() checked that this cannot overflow
      if (!v.empty())
        std::memcpy(static_cast<void*>(v.data()), bytes_.data() + pos_, v.size() * sizeof(T));
      pos_ += v.size() * sizeof(T);
    } else {
      for (auto& x : v)
        get(x);
    }
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
  /// Fewest bytes one element takes in the file (a string, a pair or a type with a codec may
  /// take fewer than its sizeof, but never none).
  template <class T>
  static constexpr std::size_t min_size() {
    return archive_detail::as_bytes<T> ? sizeof(T) : 1;
  }
  void need(std::size_t n) const;
  /// Reads an element count and checks that at least count * min_size bytes remain.
  std::size_t count(std::size_t min_size);
  std::string bytes_;
  std::string source_;
  std::size_t pos_ = 0, end_ = 0;
};

/// A value as the bytes of a one-value archive (a task's result crossing between MPI ranks,
/// task_distributor.h), and back. `kind` names what the bytes hold in every error.
template <class T>
std::string to_archive_bytes(const T& v, const std::string& kind, std::uint32_t version = 1) {
  BinaryWriter out(kind, version);
  out.put(v);
  return out.finish();
}
template <class T>
T from_archive_bytes(std::string bytes, const std::string& kind, std::uint32_t version = 1,
                     const std::string& source = "") {
  BinaryReader in(std::move(bytes), kind, version, source.empty() ? kind : source);
  T v{};
  in.get(v);
  in.expect_end();
  return v;
}

/// FNV-1a 64-bit hash of n bytes (the file checksum; also a compact fingerprint of long inputs).
std::uint64_t checksum64(const void* data, std::size_t n);

/// Reads a whole file as bytes; InputError naming it when it cannot be read.
std::string read_file_bytes(const std::string& path);

} // namespace fiberbridge
