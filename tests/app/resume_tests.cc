// `fiberbridge run --resume` at the level of units of work (issue 15 item 3): a study and an
// identify scene are killed once some of their units (study runs, identify fits) are finished;
// the resumed run restores those from the records in resume/, runs only the others, and its
// tables equal an uninterrupted run's (all but the wall-time columns, which measure the runs).
// A record made with other parameters is refused, naming the key that changed.
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/summary.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Starts the executable with `args`, stdout to /dev/null and stderr to `err`; returns the pid.
pid_t start(std::vector<std::string> args, const fs::path& err) {
  args.insert(args.begin(), FIBERBRIDGE_BIN);
  std::vector<char*> argv;
  for (auto& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen(err.c_str(), "w", stderr);
    execv(FIBERBRIDGE_BIN, argv.data());
    _exit(127);
  }
  return pid;
}

int exit_code(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::size_t records_in(const fs::path& dir) {
  std::size_t n = 0;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir / "resume", ec))
    n += e.path().extension() == ".rec";
  return n;
}

/// Starts a run and kills it (SIGKILL) as soon as `at_least` records of finished units exist;
/// returns how many there were then.
std::size_t kill_after_records(const std::vector<std::string>& args, const fs::path& dir,
                               std::size_t at_least) {
  const pid_t pid = start(args, dir.parent_path() / (dir.filename().string() + "_killed.txt"));
  int status = 0;
  while (records_in(dir) < at_least && waitpid(pid, &status, WNOHANG) == 0)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return records_in(dir);
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1))
    ++n;
  return n;
}

/// The CSV `file` of two directories, column by column as text, except the wall-time columns.
void expect_same_table(const fs::path& a, const fs::path& b, const std::string& file) {
  const auto ta = fiberbridge::CsvTable::read((a / file).string());
  const auto tb = fiberbridge::CsvTable::read((b / file).string());
  ASSERT_EQ(ta.header(), tb.header()) << file;
  ASSERT_EQ(ta.n_rows(), tb.n_rows()) << file;
  for (const auto& col : ta.header())
    if (col.find("wall_time") == std::string::npos && col != "cpu_s")
      EXPECT_EQ(ta.text(col), tb.text(col)) << file << ", column " << col;
}

} // namespace

#ifdef FIBERBRIDGE_HAVE_BEAM
TEST(Resume, ADamagedForeignOrOlderRecordIsAClearError) {
  // A record is one archive (core/binary_archive.h; docs/design.md section 4, "One archive"):
  // restored exactly when intact; cut short, replaced by another file, or left by a version of
  // before issue 30 (a CBOR <unit>.cbor), it stops --resume with one line naming it, never a
  // crash and never a silently re-run or half-read unit.
  const fs::path base = fs::path(FIBERBRIDGE_WORK_DIR) / "resume_records";
  fs::remove_all(base);
  fs::create_directories(base);
  const fs::path dir = base / "out";
  const std::vector<std::string> args = {
      "run",   std::string(FIBERBRIDGE_SOURCE_DIR) + "/prm/default.prm",
      "--set", "Run=beam",
      "--set", "Output directory=" + dir.string()};
  auto resume = args;
  resume.push_back("--resume");
  ASSERT_EQ(exit_code(start(args, base / "first.txt")), 0) << slurp(base / "first.txt");
  const fs::path record = dir / "resume" / "item_beam.rec";
  ASSERT_TRUE(fs::exists(record));
  const std::string intact = slurp(record);
  auto beam_block = [&] {
    std::ifstream in(dir / "summary.json");
    return fiberbridge::Json::parse(in).at("beam");
  };
  const auto reference = beam_block();

  ASSERT_EQ(exit_code(start(resume, base / "restored.txt")), 0) << slurp(base / "restored.txt");
  EXPECT_EQ(count(slurp(base / "restored.txt"), "item_beam restored from"), 1u)
      << slurp(base / "restored.txt");
  EXPECT_EQ(beam_block(), reference) << "the restored summary block differs from the run's";

  auto refused = [&](const std::string& what, const std::string& expect) {
    const fs::path err = base / (what + ".txt");
    const int code = exit_code(start(resume, err));
    EXPECT_TRUE(code > 0 && code < 128) << what << ": exit " << code << "\n" << slurp(err);
    const std::string text = slurp(err);
    EXPECT_NE(text.find(expect), std::string::npos) << what << ":\n" << text;
    EXPECT_NE(text.find("run without --resume to start afresh"), std::string::npos) << what << ":\n"
                                                                                    << text;
    EXPECT_EQ(text.find("restored from"), std::string::npos) << what << ":\n" << text;
  };
  for (const std::size_t cut :
       {std::size_t(0), std::size_t(7), intact.size() / 2, intact.size() - 1}) {
    std::ofstream(record, std::ios::binary | std::ios::trunc) << intact.substr(0, cut);
    refused("cut_at_" + std::to_string(cut), record.string() + ": ");
  }
  std::ofstream(record, std::ios::binary | std::ios::trunc) << "time_s,load_N\n0,1\n";
  refused("foreign", record.string() + ": not a checkpoint of this kind");
  fs::remove(record);
  const auto cbor = fiberbridge::Json::to_cbor(
      {{"format", "fiberbridge finished unit"}, {"version", 1}, {"unit", "item_beam"}});
  std::ofstream(dir / "resume" / "item_beam.cbor", std::ios::binary)
      .write(reinterpret_cast<const char*>(cbor.data()), std::streamsize(cbor.size()));
  refused("before_issue_30", "item_beam.cbor: a record written by an earlier version");

  // Without --resume the run starts afresh and keeps a new record.
  ASSERT_EQ(exit_code(start(args, base / "afresh.txt")), 0) << slurp(base / "afresh.txt");
  EXPECT_TRUE(fs::exists(record));
  EXPECT_FALSE(fs::exists(dir / "resume" / "item_beam.cbor"));
}

TEST(Resume, StudyKilledAfterSomeRunsRestoresThemAndRunsTheRest) {
  const fs::path base = fs::path(FIBERBRIDGE_WORK_DIR) / "resume_study";
  fs::remove_all(base);
  fs::create_directories(base);
  // The beam study: 4 ladder levels and the 8 stability cases the beam runs (12 units, seconds).
  auto args = [&](const std::string& out) {
    return std::vector<std::string>{
        "run",   std::string(FIBERBRIDGE_SOURCE_DIR) + "/prm/study_beam.prm",
        "--set", "Output directory=" + (base / out).string(),
        "--set", "Study/Beam ladder=Number of elements = 50, 100, 200, 400"};
  };
  ASSERT_EQ(exit_code(start(args("reference"), base / "reference.txt")), 0)
      << slurp(base / "reference.txt");
  const fs::path dir = base / "resumed";
  const std::size_t units = records_in(base / "reference");
  ASSERT_EQ(units, 12u);
  const std::size_t kept = kill_after_records(args("resumed"), dir, 3);
  ASSERT_GE(kept, 3u);
  ASSERT_LT(kept, units) << "the run finished before the kill; nothing left to resume";
  EXPECT_TRUE(fs::exists(dir / "RUN_INCOMPLETE.txt"));

  auto resume = args("resumed");
  resume.push_back("--resume");
  ASSERT_EQ(exit_code(start(resume, base / "resumed.txt")), 0) << slurp(base / "resumed.txt");
  const std::string err = slurp(base / "resumed.txt");
  // Every kept unit restored, every other one run (the study names each run it starts).
  EXPECT_EQ(count(err, "restored from"), kept) << err;
  EXPECT_EQ(count(err, "study: "), units - kept) << err;
  EXPECT_FALSE(fs::exists(dir / "RUN_INCOMPLETE.txt"));
  for (const char* f : {"study_error_vs_time.csv", "study_beam.csv", "stability.csv"})
    expect_same_table(base / "reference", dir, f);

  // Another scene into the same directory: the record names the key that changed.
  auto changed = resume;
  changed.insert(changed.end(), {"--set", "Cohesive law/Peak stress=4100"});
  ASSERT_NE(exit_code(start(changed, base / "changed.txt")), 0);
  EXPECT_NE(slurp(base / "changed.txt").find("Cohesive law/Peak stress was '4000', now '4100'"),
            std::string::npos)
      << slurp(base / "changed.txt");
  // (That a run without --resume removes the records first: OutputOnKill.MpmSceneKilledAnd...)
}

TEST(Resume, IdentifyKilledAfterTheJointFitRestoresIt) {
  const fs::path base = fs::path(FIBERBRIDGE_WORK_DIR) / "resume_identify";
  fs::remove_all(base);
  fs::create_directories(base);
  // Two shared records (the specimen and material of prm/test_records.prm), the joint fit and
  // one fit per record, few evaluations on a coarse forward model: seconds per fit (the fits'
  // quality is not what this test is about).
  const std::string records = std::string(FIBERBRIDGE_SOURCE_DIR) + "/data/dcb_records/";
  std::ofstream(base / "scene.prm")
      << "set Run = identify\n"
         "subsection Specimen\n  set Width = 25\n  set Height = 5.4\n  set Length = 123\nend\n"
         "subsection Test\n  set Files = "
      << records << "DCB-05_Toughness.csv, " << records
      << "DCB-01_Toughness.csv\n"
         "  set Columns = time_s: Time, opening_mm: Disp, load_N: Force, a_mm: CrackExt\nend\n"
         "subsection Material\n  set E_L = 19300\n  set E_T = 6110\n  set G_LT = 2288\n"
         "  set nu_LT = 0.3\nend\n"
         "subsection Identify\n  set Per record = true\n  set Starts = 1\n"
         "  set Max evaluations = 10\n  set Tolerance = 1e-2\n  set Number of elements = 40\n"
         "  set Tip advance = 2\nend\n";
  auto args = [&](const std::string& out) {
    return std::vector<std::string>{"run", (base / "scene.prm").string(), "--set",
                                    "Output directory=" + (base / out).string()};
  };
  ASSERT_EQ(exit_code(start(args("reference"), base / "reference.txt")), 0)
      << slurp(base / "reference.txt");
  ASSERT_EQ(records_in(base / "reference"), 3u); // the joint fit and two per-record fits
  const fs::path dir = base / "resumed";
  const std::size_t kept = kill_after_records(args("resumed"), dir, 1);
  ASSERT_GE(kept, 1u);
  ASSERT_LT(kept, 3u) << "the run finished before the kill; nothing left to resume";
  auto resume = args("resumed");
  resume.push_back("--resume");
  ASSERT_EQ(exit_code(start(resume, base / "resumed.txt")), 0) << slurp(base / "resumed.txt");
  const std::string err = slurp(base / "resumed.txt");
  EXPECT_EQ(count(err, "restored from"), kept) << err;
  EXPECT_NE(err.find("identify_joint restored from"), std::string::npos) << err;
  for (const char* f :
       {"identify_fit.csv", "identify_law.csv", "identify_fit_0.csv", "identify_fit_1.csv"})
    expect_same_table(base / "reference", dir, f);
  // The summary's identify block, per-record fits included, but for the timings.
  auto block = [](const fs::path& d) {
    std::ifstream in(d / "summary.json");
    auto j = fiberbridge::Json::parse(in).at("identify");
    j.erase("wall_time_s");
    j.erase("forward_time_s");
    for (auto& r : j.at("per_record")) {
      r.erase("wall_time_s");
      r.erase("forward_time_s");
    }
    return j;
  };
  EXPECT_EQ(block(dir), block(base / "reference"));
}
#endif
