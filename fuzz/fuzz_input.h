#pragma once
// Shared by the libFuzzer targets: the fuzz input as a string or as a file (the readers under test
// take file paths), and the rule every target checks. A reader of user input may only end in
// success or in fiberbridge::InputError / ComputationError (a one-line reason for the user); any
// other exception escapes LLVMFuzzerTestOneInput, which libFuzzer reports as a crash, and ASan and
// UBSan abort on memory errors and undefined behaviour.
#include "fiberbridge/core/error.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fiberbridge::fuzz {

inline std::string as_text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// Writes the input to a file private to this process (one per target and process, reused by
/// every run) and returns its path.
inline const std::string& as_file(const std::string& text, const char* suffix) {
  static const std::string path =
      std::string(std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp") + "/fiberbridge_fuzz_" +
      std::to_string(::getpid()) + suffix;
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  return path;
}

/// Runs `body`; the user-facing errors are the expected outcome of bad input.
template <class Body>
void expect_success_or_input_error(Body&& body) {
  try {
    body();
  } catch (const InputError&) {
  } catch (const ComputationError&) {
  }
}

} // namespace fiberbridge::fuzz
