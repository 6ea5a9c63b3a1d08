#pragma once
// Running the fiberbridge executable from a scene test (app_tests.cc, scene_check_tests.cc): each
// run in a fresh work directory, stderr captured, and the check that a failure is clean.
#include "fiberbridge/core/summary.h"
#include "support/scratch_dirs.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace fiberbridge::test {

namespace fs = std::filesystem;
using fiberbridge::Json;

struct RunResult {
  int exit_code;
  std::string err;
};

/// The work directory `name`; it goes when the test passes (support/scratch_dirs.h).
inline fs::path work(const std::string& name) {
  const fs::path dir = fs::path(FIBERBRIDGE_WORK_DIR) / name;
  ScratchDirs::remove_when_passed(dir);
  return dir;
}

/// Runs the executable in a fresh work directory `work(name)`; stderr captured.
inline RunResult run(const std::string& name, const std::string& args) {
  const fs::path dir = work(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string err_file = (dir / "stderr.txt").string();
  const std::string cmd = "cd '" + dir.string() + "' && '" + FIBERBRIDGE_BIN + "' " + args +
                          " > stdout.txt 2> '" + err_file + "'";
  const int rc = std::system(cmd.c_str());
  std::ifstream in(err_file);
  std::stringstream s;
  s << in.rdbuf();
  return {WEXITSTATUS(rc), s.str()};
}

inline Json read_json(const fs::path& p) {
  std::ifstream in(p);
  return Json::parse(in);
}

inline std::string data(const std::string& f) {
  return std::string(FIBERBRIDGE_TEST_DATA) + "/" + f;
}
inline std::string source(const std::string& f) {
  return std::string(FIBERBRIDGE_SOURCE_DIR) + "/" + f;
}

/// A failure must say why in one line naming `expect`, exit non-zero and leave no summary.
inline void expect_clean_failure(const std::string& name, const std::string& args,
                                 const std::string& expect) {
  const auto r = run(name, args);
  EXPECT_NE(r.exit_code, 0) << args;
  EXPECT_NE(r.err.find(expect), std::string::npos) << "stderr: " << r.err;
  // The reason is on the last line; warnings or progress may come before it.
  EXPECT_FALSE(r.err.empty());
  for (const auto& entry : fs::recursive_directory_iterator(work(name)))
    EXPECT_NE(entry.path().filename(), "summary.json") << "failed run left " << entry.path();
}

} // namespace fiberbridge::test
