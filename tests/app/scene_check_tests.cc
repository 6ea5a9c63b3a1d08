// Every section a scene will use is checked before its first item runs (issue 14 section 3): a bad
// value in the section of a LATER item fails at once, naming the key, and nothing is written (no
// output directory, no summary, no "running <item>" line). A section the run does not use is not
// an error.
#include "scene_runner.h"

#include <gtest/gtest.h>

#include <string>

using namespace fiberbridge::test;

namespace {

/// The beam-and-compare scene (PVA control law) with Run and other keys overridden.
std::string scene(const std::string& run_items, const std::string& sets) {
  return "run " + source("tests/app/scenes/compare_beam_pva.prm") + " --set 'Run=" + run_items +
         "' " + sets;
}

/// A failure before the first item: non-zero exit, the reason names `key`, no item started and
/// the scene's output directory ("out") was never created (so no summary.json either).
void expect_rejected_before_running(const std::string& name, const std::string& args,
                                    const std::string& key) {
  const auto r = run(name, args);
  EXPECT_NE(r.exit_code, 0) << args;
  EXPECT_NE(r.err.find(key), std::string::npos) << "stderr: " << r.err;
  EXPECT_EQ(r.err.find("running "), std::string::npos) << "an item ran: " << r.err;
  EXPECT_FALSE(fs::exists(work(name) / "out")) << "the run created its output directory";
}

} // namespace

TEST(SceneCheck, LawPointTypoFailsBeforeTheFirstItem) {
#ifndef FIBERBRIDGE_HAVE_BEAM
  GTEST_SKIP() << "beam module not built (FIBERBRIDGE_MODELS)";
#endif
  // extract runs first and does not use the law; beam (after it) does.
  expect_rejected_before_running(
      "check_law_typo",
      scene("extract, beam", "--set 'Data/File=" + source("data/sample_rdelta_pva_control.csv") +
                                 "' --set 'Cohesive law/Points=0.1:661, 1.0;187'"),
      "Cohesive law/Points");
}

TEST(SceneCheck, ContradictoryMpmSettingFailsBeforeTheBeamRuns) {
#if !defined(FIBERBRIDGE_HAVE_BEAM) || !defined(FIBERBRIDGE_HAVE_MPM)
  GTEST_SKIP() << "beam or MPM module not built (FIBERBRIDGE_MODELS)";
#endif
  // 20 mm cells leave less than two cells through the 17.5 mm arm: only the specimen tells.
  expect_rejected_before_running("check_mpm_cells", scene("beam, mpm", "--set 'MPM/Cell size=20'"),
                                 "MPM/Cell size");
  // The minimum ligament leaves the tip no room to grow in the 300 mm specimen with a 100 mm notch.
  expect_rejected_before_running("check_mpm_ligament",
                                 scene("beam, mpm", "--set 'MPM/Minimum ligament=199'"),
                                 "MPM/Minimum ligament");
  // Out of the range MpmParameters::validate allows (the pattern admits it).
  expect_rejected_before_running("check_mpm_plateau",
                                 scene("beam, mpm", "--set 'MPM/Plateau tolerance=0'"),
                                 "MPM/Plateau tolerance");
}

TEST(SceneCheck, BadFemValueFailsBeforeTheBeamRuns) {
#if !defined(FIBERBRIDGE_HAVE_BEAM) || !defined(FIBERBRIDGE_HAVE_FEM)
  GTEST_SKIP() << "beam or FEM module not built (FIBERBRIDGE_MODELS)";
#endif
  expect_rejected_before_running("check_fem_plateau",
                                 scene("beam, fem", "--set 'FEM/Plateau tolerance=0'"),
                                 "FEM/Plateau tolerance");
  // 25 mm elements put only 4 elements along the 100 mm notch: the engine needs 5.
  expect_rejected_before_running(
      "check_fem_mesh", scene("beam, fem", "--set 'FEM/Element size=25'"), "FEM/Element size");
  // 2 mm arms: the crack-plane layer is 2/4 mm (Minimum layers per arm), so 5 mm elements would
  // be 10 times longer than high (fem::kMaxCrackPlaneAspect is 4): only the specimen tells.
  expect_rejected_before_running(
      "check_fem_aspect",
      scene("beam, fem", "--set 'Specimen/Height=4' --set 'FEM/Element size=5'"),
      "FEM/Element size");
}

TEST(SceneCheck, LaterItemsOwnSectionsAreCheckedFirst) {
#ifndef FIBERBRIDGE_HAVE_BEAM
  GTEST_SKIP() << "beam module not built (FIBERBRIDGE_MODELS)";
#endif
  // A study ladder key that the Beam section does not have, checked level by level.
  expect_rejected_before_running(
      "check_study_ladder",
      scene("beam, study", "--set 'Study/Ladder models=beam' --set 'Study/Beam ladder=Number of "
                           "elementz = 50, 100'"),
      "Study/Beam ladder");
  // A ladder level whose value the Beam section rejects (validate, not the pattern).
  expect_rejected_before_running(
      "check_study_level",
      scene("beam, study",
            "--set 'Study/Ladder models=beam' --set 'Study/Beam ladder=Plateau tolerance = 0.01, "
            "0'"),
      "Beam/Plateau tolerance");
  expect_rejected_before_running("check_study_case",
                                 scene("beam, study",
                                       "--set 'Study/Stability models=beam' --set 'Study/Stability "
                                       "cases=snap_bak'"),
                                 "Study/Stability cases");
  expect_rejected_before_running(
      "check_study_model",
      scene("beam, study", "--set 'Study/Ladder models=bean' --set 'Study/Beam ladder=Number of "
                           "elements = 50'"),
      "Study/Ladder models");
  // The rank table and the beam's own keys.
  expect_rejected_before_running("check_rank_table",
                                 scene("beam, rank", "--set 'Rank/Table file=no_such_table.csv'"),
                                 "Rank/Table file");
  expect_rejected_before_running("check_beam_ligament",
                                 scene("beam", "--set 'Beam/Minimum ligament=250'"),
                                 "Beam/Minimum ligament");
}

TEST(SceneCheck, CompareWithoutASimulationFailsAtOnce) {
  expect_rejected_before_running(
      "check_compare_alone",
      scene("extract, compare",
            "--set 'Data/File=" + source("data/sample_rdelta_pva_control.csv") + "'"),
      "'compare' needs at least one simulation");
}

TEST(SceneCheck, AnUnusedSectionIsNotAnError) {
#if !defined(FIBERBRIDGE_HAVE_MPM)
  GTEST_SKIP() << "MPM module not built (FIBERBRIDGE_MODELS): the scene sets an MPM key";
#endif
  // fit hands its law to the simulations: the Cohesive law section is not used, so a law the
  // section could not build does not stop the run.
  const std::string args =
      scene("fit", "--set 'Data/File=" + source("data/sample_rdelta_pva_control.csv") +
                       "' --set 'Cohesive law/Points=0.1:661, 1.0;187' --set 'MPM/Cell size=20'");
  const auto r = run("check_unused", args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(work("check_unused") / "out" / "summary.json"));
}

// A renamed key given under both names with different values (issue 14 section 3): the scene is
// refused before the first item, naming both keys (core/renamed_key.h).
TEST(SceneCheck, RenamedKeyGivenTwiceFailsBeforeTheFirstItem) {
#if !defined(FIBERBRIDGE_HAVE_BEAM) || !defined(FIBERBRIDGE_HAVE_MPM)
  GTEST_SKIP() << "beam or MPM module not built (FIBERBRIDGE_MODELS)";
#endif
  expect_rejected_before_running(
      "check_renamed_beam",
      scene("beam", "--set 'Beam/Maximum Newton iterations=30' --set 'Beam/Newton iterations=20'"),
      "Beam/Maximum Newton iterations = 30 and Beam/Newton iterations = 20");
  expect_rejected_before_running(
      "check_renamed_mpm",
      scene("beam, mpm", "--set 'MPM/Tip advance=5' --set 'MPM/Growth step=1'"),
      "MPM/Tip advance = 5 and MPM/Growth step = 1");
}

TEST(SceneCheck, BadIdentifyForwardModelFailsBeforeTheFirstItem) {
#if !defined(FIBERBRIDGE_HAVE_BEAM) || !defined(FIBERBRIDGE_HAVE_FEM)
  // identify needs the beam; prm/test_records.prm has a FEM section, which a build without the
  // FEM refuses as an unknown subsection before any key is checked.
  GTEST_SKIP() << "beam or FEM module not built (FIBERBRIDGE_MODELS)";
#endif
  // Identify/Forward model takes the models that offer identify a forward run (beam, fem): a
  // typo names the key before reduce (the first item) runs. The MPM is a model but not offered.
  for (const char* bad : {"femm", "mpm"})
    expect_rejected_before_running(std::string("check_identify_forward_") + bad,
                                   "run " + source("prm/test_records.prm") +
                                       " --set 'Run=reduce, identify' --set " +
                                       "'Identify/Forward model=" + bad + "'",
                                   "Identify/Forward model");
}
