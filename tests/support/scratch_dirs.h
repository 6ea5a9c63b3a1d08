#pragma once
// Test outputs that go when the test passes. The scene and DIC tests write whole virtual tests
// (frames, VTU, CSV): about 0.8 GB over the suite, enough to fill a CI machine's disk before the
// fuzz build starts (CI of 2026-12-07 stopped with "No space left on device"). A passing test's
// directories are removed when it ends; a failing test keeps them for the reader, and
// FIBERBRIDGE_KEEP_TEST_OUTPUT=1 keeps every one.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

namespace fiberbridge::test {

class ScratchDirs : public ::testing::EmptyTestEventListener {
public:
  /// `dir` is removed when the running test ends, if it passed.
  static void remove_when_passed(const std::filesystem::path& dir) {
    ScratchDirs& me = instance();
    std::lock_guard<std::mutex> lock(me.mutex_);
    me.dirs_.push_back(dir);
  }

  void OnTestEnd(const ::testing::TestInfo& info) override {
    std::vector<std::filesystem::path> dirs;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      dirs.swap(dirs_);
    }
    const char* keep = std::getenv("FIBERBRIDGE_KEEP_TEST_OUTPUT");
    if (!info.result()->Passed() || (keep && std::string(keep) == "1"))
      return;
    for (const auto& d : dirs) {
      std::error_code ec; // a directory already gone, or never made, is not the test's failure
      std::filesystem::remove_all(d, ec);
    }
  }

private:
  /// The one listener of this test executable, appended to gtest's on first use. gtest owns
  /// and deletes it; appending while a test runs is safe (listeners are called by index).
  static ScratchDirs& instance() {
    static ScratchDirs* me = [] {
      auto* l = new ScratchDirs;
      ::testing::UnitTest::GetInstance()->listeners().Append(l);
      return l;
    }();
    return *me;
  }

  std::mutex mutex_;
  std::vector<std::filesystem::path> dirs_;
};

} // namespace fiberbridge::test
