// Output that is never half-true (issue 15): an MPM scene (coarse cells, short loading) is killed
// with SIGTERM or SIGKILL at random moments of its run, into a directory that already holds a
// complete result. After every kill the directory must either hold a complete result (summary.json,
// no incomplete marker, every table identical to an uninterrupted run's) or say that it is
// incomplete (RUN_INCOMPLETE.txt, no summary.json); no file may be truncated under its real name.
// A rerun into the same directory must then give the uninterrupted run's tables again.
#include "fiberbridge/core/csv.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

const char* marker = "RUN_INCOMPLETE.txt"; // app/analysis_steps.h incomplete_marker

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Starts `fiberbridge run` on the coarse MPM scene into `out`; returns the child's pid.
pid_t start_scene(const fs::path& out) {
  const std::string bin = FIBERBRIDGE_BIN;
  const std::string scene = std::string(FIBERBRIDGE_SOURCE_DIR) + "/prm/mpm_linear_softening.prm";
  const std::string set_out = "Output directory=" + out.string();
  const pid_t pid = fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    execl(bin.c_str(), bin.c_str(), "run", scene.c_str(), "--set", set_out.c_str(), "--set",
          "MPM/Cell size=5", "--set", "MPM/Loading periods=8", static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

int wait_for(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

/// The tables of a complete run, by file name.
std::vector<std::pair<std::string, std::string>> tables(const fs::path& dir) {
  std::vector<std::pair<std::string, std::string>> t;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".csv")
      t.emplace_back(e.path().filename().string(), slurp(e.path()));
  std::sort(t.begin(), t.end());
  return t;
}

/// The invariant after a kill at any moment (see the file comment); `what` names the trial.
void expect_complete_or_marked(const fs::path& dir,
                               const std::vector<std::pair<std::string, std::string>>& reference,
                               const std::string& what) {
  const bool summary = fs::exists(dir / "summary.json");
  const bool incomplete = fs::exists(dir / marker);
  EXPECT_NE(summary, incomplete) << what << ": summary.json " << summary << ", " << marker << " "
                                 << incomplete;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (e.path().extension() == ".csv") {
      // Every table under its real name is complete: it parses and ends with its last row.
      const std::string text = slurp(e.path());
      EXPECT_TRUE(!text.empty() && text.back() == '\n') << what << ": " << name << " truncated";
      EXPECT_NO_THROW(fiberbridge::CsvTable::read(e.path().string())) << what << ": " << name;
    }
    if (summary)
      EXPECT_NE(e.path().extension(), ".partial")
          << what << ": temporary file " << name << " beside summary.json";
  }
  if (summary)
    EXPECT_EQ(tables(dir), reference) << what << ": summary.json beside tables of another run";
}

} // namespace

#ifdef FIBERBRIDGE_HAVE_MPM
TEST(OutputOnKill, MpmSceneKilledAtRandomMomentsLeavesCompleteOrMarkedOutput) {
  const fs::path dir = fs::path(FIBERBRIDGE_WORK_DIR) / "output_on_kill";
  fs::remove_all(dir);
  // The uninterrupted run: the reference tables and the run time the kill moments are drawn from.
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_EQ(wait_for(start_scene(dir)), 0);
  const double run_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(fs::exists(dir / "summary.json"));
  ASSERT_FALSE(fs::exists(dir / marker));
  const auto reference = tables(dir);
  ASSERT_FALSE(reference.empty());

  const unsigned seed = std::random_device{}();
  std::mt19937 rng(seed);
  // Moments from just after the start to just past the end (5 % to 105 % of the run time), so
  // kills land in start-up, the MPM loop, the writing of the tables and plots, and after the end.
  std::uniform_real_distribution<double> moment(0.05 * run_s, 1.05 * run_s);
  int trial = 0;
  for (int sig : {SIGTERM, SIGKILL, SIGTERM, SIGKILL, SIGTERM, SIGKILL}) {
    const double at = moment(rng);
    const pid_t pid = start_scene(dir);
    std::this_thread::sleep_for(std::chrono::duration<double>(at));
    kill(pid, sig);
    const int status = wait_for(pid);
    const std::string what = "trial " + std::to_string(++trial) + " (seed " + std::to_string(seed) +
                             ", " + (sig == SIGTERM ? "SIGTERM" : "SIGKILL") + " at " +
                             std::to_string(at) + " s of " + std::to_string(run_s) + " s, " +
                             (WIFSIGNALED(status) ? "killed" : "had finished") + ")";
    expect_complete_or_marked(dir, reference, what);
  }
  // A rerun into the directory a killed run left behind completes and matches the reference.
  ASSERT_EQ(wait_for(start_scene(dir)), 0);
  EXPECT_TRUE(fs::exists(dir / "summary.json"));
  EXPECT_FALSE(fs::exists(dir / marker));
  EXPECT_EQ(tables(dir), reference);
}
#endif
