// The Beam and MPM sections as a scene gives them (issue 14 section 3, one parameter convention):
// a setting shared with another section has that section's name; the old name stays accepted with
// a note in the run's notes, and both names given with different values is an error naming both
// (core/renamed_key.h, the mechanism of FEM/Steady-state window).
#include "fiberbridge/app/items/item_beam.h"
#include "fiberbridge/app/items/item_mpm.h"
#include "fiberbridge/app/items/items.h"
#include "fiberbridge/app/scene/models.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <string>

using namespace fiberbridge;
using units::mm;

namespace {

/// What `body` throws, "" if nothing; an error that is not an InputError fails the test.
template <class F>
std::string input_error(F&& body) {
  try {
    body();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool has_note(const std::vector<std::string>& notes, const std::string& text) {
  for (const auto& n : notes)
    if (n.find(text) != std::string::npos)
      return true;
  return false;
}

} // namespace

#ifdef FIBERBRIDGE_HAVE_BEAM
namespace {
beam::BeamParameters beam_section(const std::string& sets) {
  dealii::ParameterHandler prm;
  app::find_model("beam")->declare(prm);
  prm.parse_input_from_string("subsection Beam\n" + sets + "end\n");
  return app::read_beam_section(prm);
}
} // namespace

// Beam/Newton iterations is now Beam/Maximum Newton iterations, the FEM's name.
TEST(SceneSections, BeamMaximumNewtonIterationsIsTheFemsName) {
  EXPECT_EQ(beam_section("").max_newton_iterations, beam::BeamParameters().max_newton_iterations);
  const auto p = beam_section("set Maximum Newton iterations = 12\n");
  EXPECT_EQ(p.max_newton_iterations, 12);
  EXPECT_TRUE(p.deprecation_notes.empty());
}

TEST(SceneSections, BeamOldNewtonIterationsKeyIsMappedWithANote) {
  const auto p = beam_section("set Newton iterations = 12\n");
  EXPECT_EQ(p.max_newton_iterations, 12);
  ASSERT_EQ(p.deprecation_notes.size(), 1u);
  EXPECT_TRUE(has_note(p.deprecation_notes,
                       "Beam/Newton iterations is deprecated: use Beam/Maximum Newton iterations"));
  // The same value under both names is what the scene meant: accepted, still with the note.
  const auto same =
      beam_section("set Newton iterations = 12\nset Maximum Newton iterations = 12\n");
  EXPECT_EQ(same.max_newton_iterations, 12);
  EXPECT_EQ(same.deprecation_notes.size(), 1u);
  // Its range is the one the key always had.
  EXPECT_NE(input_error([] {
              beam_section("set Newton iterations = 2.5\n");
            }).find("Beam/Newton iterations: expected a whole number"),
            std::string::npos);
}

TEST(SceneSections, BeamBothNewtonIterationNamesDisagreeIsAnError) {
  const std::string e = input_error(
      [] { beam_section("set Maximum Newton iterations = 30\nset Newton iterations = 12\n"); });
  EXPECT_NE(e.find("Beam/Maximum Newton iterations = 30"), std::string::npos) << e;
  EXPECT_NE(e.find("Beam/Newton iterations = 12"), std::string::npos) << e;
}
#endif

#ifdef FIBERBRIDGE_HAVE_MPM
namespace {
mpm::MpmParameters mpm_section(const std::string& sets) {
  dealii::ParameterHandler prm;
  app::find_model("mpm")->declare(prm);
  prm.parse_input_from_string("subsection MPM\nset Cell size = 2.5\n" + sets + "end\n");
  return app::read_mpm_section(prm);
}
} // namespace

// MPM/Tip advance is in mm as the Beam's, rounded to whole cells (at least one); 0, the default,
// is one cell whatever the cell size, as the old Growth step's default was.
TEST(SceneSections, MpmTipAdvanceInMmIsRoundedToWholeCells) {
  EXPECT_EQ(mpm_section("").growth_step_cells, 1);
  EXPECT_EQ(mpm_section("set Tip advance = 5\n").growth_step_cells, 2);
  EXPECT_EQ(mpm_section("set Tip advance = 6\n").growth_step_cells, 2);
  EXPECT_EQ(mpm_section("set Tip advance = 0.5\n").growth_step_cells, 1);
  EXPECT_TRUE(mpm_section("set Tip advance = 5\n").deprecation_notes.empty());
  EXPECT_NE(input_error([] { mpm_section("set Tip advance = 12\n"); }).find("MPM/Tip advance"),
            std::string::npos);
}

TEST(SceneSections, MpmOldGrowthStepKeyIsMappedWithANote) {
  const auto p = mpm_section("set Growth step = 2\n");
  EXPECT_EQ(p.growth_step_cells, 2);
  ASSERT_EQ(p.deprecation_notes.size(), 1u);
  EXPECT_TRUE(has_note(p.deprecation_notes, "MPM/Growth step is deprecated: use MPM/Tip advance"));
  // 5 mm are the same two cells.
  EXPECT_EQ(mpm_section("set Growth step = 2\nset Tip advance = 5\n").growth_step_cells, 2);
  EXPECT_NE(input_error([] {
              mpm_section("set Growth step = 5\n");
            }).find("MPM/Growth step: expected a whole number of cells in [1, 4]"),
            std::string::npos);
}

TEST(SceneSections, MpmBothTipAdvanceNamesDisagreeIsAnError) {
  const std::string e =
      input_error([] { mpm_section("set Tip advance = 2.5\nset Growth step = 2\n"); });
  EXPECT_NE(e.find("MPM/Tip advance = 2.5"), std::string::npos) << e;
  EXPECT_NE(e.find("MPM/Growth step = 2"), std::string::npos) << e;
}

// MPM/End ligament is now MPM/Minimum ligament, the Beam's name (mm, 0 = the specimen height).
TEST(SceneSections, MpmMinimumLigamentIsTheBeamsName) {
  const auto p = mpm_section("set Minimum ligament = 40\n");
  EXPECT_DOUBLE_EQ(p.end_ligament, 40 * mm);
  EXPECT_TRUE(p.deprecation_notes.empty());
  const auto old = mpm_section("set End ligament = 40\n");
  EXPECT_DOUBLE_EQ(old.end_ligament, 40 * mm);
  ASSERT_EQ(old.deprecation_notes.size(), 1u);
  EXPECT_TRUE(
      has_note(old.deprecation_notes, "MPM/End ligament is deprecated: use MPM/Minimum ligament"));
  const std::string e =
      input_error([] { mpm_section("set Minimum ligament = 40\nset End ligament = 50\n"); });
  EXPECT_NE(e.find("MPM/Minimum ligament = 40"), std::string::npos) << e;
  EXPECT_NE(e.find("MPM/End ligament = 50"), std::string::npos) << e;
}
#endif
