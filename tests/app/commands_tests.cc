// The command line in process (app/cli/commands.h): main.cc only starts MPI, so the commands are
// library code and are tested here without spawning the executable (app_tests.cc spawns it).
// The Test section's struct (app/scene/test_section.h) is read here too: reduce and identify share
// it.
#include "fiberbridge/app/cli/commands.h"
#include "fiberbridge/app/scene/section.h"
#include "fiberbridge/app/scene/test_section.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <tuple>

using namespace fiberbridge;

namespace {

std::string fresh_dir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("fb_commands_" + name);
  std::filesystem::remove_all(d);
  return d.string();
}

} // namespace

TEST(CommandLine, UnknownCommandAndNoCommandFail) {
  EXPECT_EQ(app::run_command_line({"frobnicate"}, 0), 2);
  EXPECT_EQ(app::run_command_line({}, 0), 1); // usage printed, but nothing was done
  EXPECT_EQ(app::run_command_line({"--help"}, 0), 0);
}

// Linear softening, sigma_c 500 kPa, delta_c 1 mm, J_tip 100: Eq. 2 ends at
// J_tip + sigma_c delta_c / 2 = 350 J/m^2, a number of the law alone (no discretization: the
// forward curve is the law's exact integral, so 1e-9 is round-off).
TEST(CommandLine, ForwardInProcessWritesTheLawsCurve) {
  const std::string out = fresh_dir("forward");
  ASSERT_EQ(app::run_command_line({"forward", "--type", "linear", "--peak-stress", "500",
                                   "--delta-c", "1", "--j-tip", "100", "--out", out},
                                  0),
            0);
  const auto R = CsvTable::read(out + "/rdelta_forward.csv").numeric("R_J_m2");
  ASSERT_FALSE(R.empty());
  EXPECT_NEAR(R.front(), 100, 1e-9);
  EXPECT_NEAR(R.back(), 350, 1e-9);
  // A bad option value is one failed command (exit 1), not an exception out of the library.
  EXPECT_EQ(
      app::run_command_line({"forward", "--type", "linear", "--delta-c", "1", "--out", out}, 0), 1);
}

TEST(TestSectionStruct, FilesAreTrimmedAndAMissingRecordIsNamed) {
  dealii::ParameterHandler prm;
  app::declare_section<app::TestSection>(prm, "Test");
  prm.enter_subsection("Test");
  prm.set("Files", " a.csv ,, b.csv,");
  prm.set("Crack back tolerance", "0.5");
  prm.leave_subsection();
  const auto t = app::parse_section<app::TestSection>(prm, "Test");
  ASSERT_EQ(t.files.size(), 2u);
  EXPECT_EQ(t.files[0], "a.csv");
  EXPECT_EQ(t.files[1], "b.csv");
  EXPECT_DOUBLE_EQ(t.crack_back_tolerance, 0.5e-3);
  const std::string scene = fresh_dir("test_section") + ".prm";
  try {
    t.resolved_files(scene);
    FAIL() << "a missing record was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Test/Files: record 'a.csv' not found"), std::string::npos)
        << e.what();
  }
}

// One word, as --crack-length (analysis::set_crack_length): `equivalent` reduces against the
// equivalent crack and still reads the readings (they give a0 and are shown beside).
TEST(TestSectionStruct, CrackLengthSourceReachesTheReader) {
  for (const auto& [text, source, equivalent] :
       {std::tuple{"auto", analysis::CrackLengthSource::automatic, false},
        std::tuple{"measured", analysis::CrackLengthSource::measured, false},
        std::tuple{"equivalent", analysis::CrackLengthSource::automatic, true}}) {
    dealii::ParameterHandler prm;
    app::declare_section<app::TestSection>(prm, "Test");
    prm.enter_subsection("Test");
    prm.set("Crack length", text);
    prm.leave_subsection();
    const auto t = app::parse_section<app::TestSection>(prm, "Test");
    const auto o = t.chain_options("scene.prm", specimen::Specimen::unknown(), {});
    EXPECT_EQ(o.read.crack_length, source) << text;
    EXPECT_EQ(o.reduce.use_equivalent_crack, equivalent) << text;
    EXPECT_EQ(t.read_options("scene.prm").crack_length, source) << text;
  }
}
