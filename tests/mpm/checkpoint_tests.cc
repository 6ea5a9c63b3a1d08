// Checkpoints of the DCB model (mpm/checkpoint.h): a run interrupted at an advance and resumed
// from its last checkpoint gives the uninterrupted run's R curve and VTU files to the last bit
// (the state is saved bit for bit and the thread team is deterministic, so no tolerance); a
// checkpoint of other inputs or a damaged one is refused with the reason.
#include "fiberbridge/core/error.h"
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/mpm/checkpoint.h"
#include "fiberbridge/mpm/dcb.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

using namespace fiberbridge;
using namespace fiberbridge::mpm;
namespace fs = std::filesystem;

namespace {

// The small specimen of dcb_tests.cc (4 cells through each 10 mm arm), stopped after 20 mm of
// growth: 7 advances of a linear-softening zone, about 5 s.
specimen::Specimen small_specimen() {
  specimen::Specimen s;
  s.length = 0.120;
  s.height = 0.020;
  s.initial_crack = 0.040;
  s.width = 0.035;
  return s;
}

MpmParameters short_run() {
  MpmParameters p;
  p.cell_size = 2.5e-3;
  p.loading_periods = 8;
  p.end_ligament = 0.060;
  p.vtu_every_advances = 2;
  p.checkpoint_interval = 0;
  return p;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A fresh directory for one test.
fs::path fresh_dir(const std::string& name) {
  const fs::path d =
      fs::temp_directory_path() / ("fb_mpm_checkpoint_" + std::to_string(getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

/// What a crash looks like to the model: an exception out of the progress callback.
struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted by the test") {}
};

} // namespace

TEST(MpmCheckpoint, ResumedRunMatchesTheUninterruptedOneBitForBit) {
  const specimen::Specimen s = small_specimen();
  const specimen::Material m;
  const auto law = law::make_linear_softening(1e6, 0.2e-3);
  const fs::path ref_dir = fresh_dir("reference"), dir = fresh_dir("interrupted");

  DcbModel reference(s, m, law, 200, short_run(), ref_dir.string());
  const result::SimulationResult r1 = reference.run();
  ASSERT_GE(r1.rcurve.size(), 6u);

  // Checkpoints every 20 ms (many per second of this run); the run is stopped at the fourth
  // advance, after the second VTU, and resumes from whichever checkpoint came last.
  MpmParameters p = short_run();
  p.checkpoint_interval = 0.02;
  int advances = 0;
  DcbModel interrupted(s, m, law, 200, p, dir.string(), [&](const std::string&) {
    if (++advances == 4)
      throw Interrupted();
  });
  EXPECT_THROW(interrupted.run(), Interrupted);
  ASSERT_TRUE(fs::exists(checkpoint_path(dir.string())));

  p.resume = true;
  std::vector<std::string> lines;
  DcbModel resumed(s, m, law, 200, p, dir.string(),
                   [&](const std::string& l) { lines.push_back(l); });
  const result::SimulationResult r2 = resumed.run();
  ASSERT_FALSE(lines.empty());
  EXPECT_NE(lines.front().find("resumed from the checkpoint"), std::string::npos) << lines.front();

  EXPECT_EQ(resumed.solver().steps(), reference.solver().steps());
  ASSERT_EQ(r2.rcurve.size(), r1.rcurve.size());
  for (std::size_t i = 0; i < r1.rcurve.size(); ++i)
    EXPECT_EQ(std::memcmp(&r1.rcurve[i], &r2.rcurve[i], sizeof(result::RCurvePoint)), 0)
        << "R-curve row " << i << ": a " << r1.rcurve[i].a << " / " << r2.rcurve[i].a << ", R_J "
        << r1.rcurve[i].R_J << " / " << r2.rcurve[i].R_J;
  EXPECT_EQ(std::memcmp(&r1.G_ss, &r2.G_ss, sizeof(double)), 0) << r1.G_ss << " / " << r2.G_ss;
  EXPECT_EQ(resumed.solver().external_work(), reference.solver().external_work());
  EXPECT_EQ(resumed.solver().numerical_loss(), reference.solver().numerical_loss());
  EXPECT_EQ(resumed.crack().traction_work(), reference.crack().traction_work());
  EXPECT_EQ(resumed.stop_reason(), reference.stop_reason());
  // The particle files and the collection that lists them (the resumed run continues the list
  // the checkpoint carried).
  int vtu_files = 0;
  for (const auto& e : fs::directory_iterator(ref_dir))
    if (e.path().extension() == ".vtu" || e.path().extension() == ".pvd") {
      ++vtu_files;
      EXPECT_EQ(slurp(dir / e.path().filename()), slurp(e.path())) << e.path().filename();
    }
  EXPECT_GE(vtu_files, 4);
  fs::remove_all(ref_dir.parent_path());
}

TEST(MpmCheckpoint, RefusesACheckpointOfOtherInputsOrADamagedOne) {
  const specimen::Specimen s = small_specimen();
  const specimen::Material m;
  const auto law = law::make_linear_softening(1e6, 0.2e-3);
  const fs::path dir = fresh_dir("refuse");
  MpmParameters p = short_run();
  {
    DcbModel model(s, m, law, 200, p, dir.string());
    for (int i = 0; i < 100; ++i)
      ASSERT_TRUE(model.step(true));
    model.write_checkpoint();
  }
  const std::string file = checkpoint_path(dir.string());
  ASSERT_TRUE(fs::exists(file));
  p.resume = true;
  auto message = [&](const law::TractionLaw& l, const MpmParameters& q, double j_tip = 200) {
    DcbModel model(s, m, l, j_tip, q, dir.string());
    try {
      model.resume_from_checkpoint();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // The same inputs resume (another thread count changes nothing and is not an input).
  MpmParameters threads = p;
  threads.threads = 1;
  {
    DcbModel same(s, m, law, 200, threads, dir.string());
    EXPECT_TRUE(same.resume_from_checkpoint());
    EXPECT_EQ(same.solver().steps(), 100);
  }
  MpmParameters slower = p;
  slower.loading_periods = 16;
  EXPECT_NE(message(law, slower).find("MPM/Loading periods"), std::string::npos)
      << message(law, slower);
  const auto stronger = law::make_linear_softening(1.1e6, 0.2e-3);
  EXPECT_NE(message(stronger, p).find("Cohesive law"), std::string::npos) << message(stronger, p);
  EXPECT_NE(message(law, p, 250).find("Cohesive law/J tip"), std::string::npos);

  // A flipped byte and a cut file: named, with what is wrong.
  const std::string good = slurp(file);
  std::string bad = good;
  bad[bad.size() / 2] ^= 0x10;
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bad;
  EXPECT_NE(message(law, p).find("damaged"), std::string::npos) << message(law, p);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << good.substr(0, good.size() / 3);
  EXPECT_NE(message(law, p).find(file), std::string::npos) << message(law, p);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << "not a checkpoint";
  EXPECT_NE(message(law, p).find(file), std::string::npos) << message(law, p);

  // A run without resume removes a checkpoint it finds (a later --resume must not pick up
  // another run's state); with resume and no checkpoint it starts afresh.
  std::ofstream(file, std::ios::binary | std::ios::trunc) << good;
  MpmParameters fresh = short_run();
  fresh.max_steps = 20; // stops at once
  DcbModel model(s, m, law, 200, fresh, dir.string());
  model.run();
  EXPECT_NE(model.stop_reason().find("step limit"), std::string::npos);
  EXPECT_FALSE(fs::exists(file));
  fs::remove_all(dir.parent_path());
}
