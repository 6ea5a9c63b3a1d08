// Scene-level tests of the fiberbridge executable: commands on bundled data produce the outputs
// docs/design.md section 5 names, and every kind of bad input ends with a one-line reason, a
// non-zero exit and no summary.json.
#include "fiberbridge/core/summary.h"
#include "scene_runner.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

using namespace fiberbridge::test;

TEST(BadInput, MissingColumn) {
  expect_clean_failure("missing_column", "extract " + data("missing_column.csv") + " --out out",
                       "missing required column 'R_J_m2'");
}

TEST(BadInput, NaNValue) {
  expect_clean_failure("nan", "extract " + data("nan_value.csv") + " --out out", "nan_value.csv:4");
}

TEST(BadInput, NonMonotoneOpening) {
  expect_clean_failure("nonmonotone", "extract " + data("nonmonotone.csv") + " --out out",
                       "nonmonotone.csv:5");
}

TEST(BadInput, NoSteadyState) {
  expect_clean_failure("no_steady", "extract " + data("no_steady_state.csv") + " --out out",
                       "no steady state");
}

TEST(BadInput, DeltaCOutsideData) {
  expect_clean_failure("dc_outside",
                       "extract " + source("data/sample_rdelta_pva_control.csv") +
                           " --delta-c 50 --out out",
                       "lies outside the data");
}

TEST(BadInput, NegativeLawPoint) {
  expect_clean_failure("law_negative", "run " + data("law_negative.prm"), "negative traction");
}

TEST(BadInput, UnorderedLawPoints) {
  expect_clean_failure("law_unordered", "run " + data("law_unordered.prm"), "increase");
}

TEST(BadInput, UnknownSceneKey) {
  expect_clean_failure("unknown_key", "run " + data("unknown_key.prm"), "Smoothing halfwidth");
}

TEST(BadInput, UnknownSceneSectionNamesLineAndSection) {
  // deal.II's own text (function signature, violated condition) must not be what the user reads.
  expect_clean_failure("unknown_section", "run " + data("unknown_section.prm"), "Line <3> of file");
  const auto r = run("unknown_section", "run " + data("unknown_section.prm"));
  EXPECT_NE(r.err.find("no such subsection to be entered: Beamm"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("ParameterHandler::"), std::string::npos) << r.err;
}

TEST(BadInput, UnknownCommandAndOption) {
  EXPECT_NE(run("unknown_cmd", "frobnicate").exit_code, 0);
  EXPECT_NE(run("unknown_opt", "extract x.csv --no-such-option").exit_code, 0);
}

TEST(Commands, ExtractOnBundledSampleGivesTheDesignOutputs) {
  const auto r = run("extract_sample",
                     "extract " + source("data/sample_rdelta_pva_control.csv") + " --out out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto out = work("extract_sample") / "out";
  for (const char* f : {"cohesive_law_eq5.csv", "cohesive_law_dRdd.csv", "trilinear_fit.csv",
                        "rdelta_averaged.csv", "summary.json"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  // A finished run removes the marker a killed one leaves (issue 15, output_kill_tests.cc).
  EXPECT_FALSE(fs::exists(out / "RUN_INCOMPLETE.txt"));
  const auto j = read_json(out / "summary.json");
  for (const char* k : {"J_tip_J_m2", "G_ss_J_m2", "delta_c_mm", "peak_sigma_eq5_kPa",
                        "peak_sigma_dRdd_kPa", "trilinear"})
    EXPECT_TRUE(j.contains(k)) << k;
  // The sample is synthetic data of the PVA control law (J_tip 200, G_ss 200 + 882.15) with
  // 15 J/m^2 noise over 6 replicates: after averaging, the plateau mean is good to a few J/m^2;
  // 2 % covers it with margin.
  EXPECT_NEAR(j["G_ss_J_m2"].get<double>(), 1082.15, 0.02 * 1082.15);
  EXPECT_NEAR(j["J_tip_J_m2"].get<double>(), 200, 0.05 * 200);
  // The new method finds a peak well above the old one (paper: "nearly a factor of 2").
  EXPECT_GT(j["peak_sigma_eq5_kPa"].get<double>(), 1.4 * j["peak_sigma_dRdd_kPa"].get<double>());
  const auto& t = j["trilinear"];
  EXPECT_NEAR(t["J1_J_m2"].get<double>() + t["J2_J_m2"].get<double>(),
              j["G_ss_J_m2"].get<double>() - j["J_tip_J_m2"].get<double>(), 1e-6 * 1000);
}

TEST(Commands, RankReproducesThePapersOrder) {
  const auto r =
      run("rank_seed", "rank " + source("data/reference/seed_table1.csv") + " --out out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(work("rank_seed") / "out" / "RUN_INCOMPLETE.txt"));
  const auto j = read_json(work("rank_seed") / "out" / "summary.json");
  std::vector<std::string> adhesives;
  for (const auto& m : j["ranking"])
    if (m != "DF")
      adhesives.push_back(m.get<std::string>());
  EXPECT_EQ(adhesives, (std::vector<std::string>{"PF", "EPI", "PRF", "PVA"}));
  // The DF 16-cycle row of Table 1 is inconsistent (J1 printed 347, ~26 expected).
  bool flagged = false;
  for (const auto& c : j["rank"]["consistency"])
    flagged = flagged || (c["material"] == "DF" && c["cycles"].get<double>() == 16);
  EXPECT_TRUE(flagged);
}

TEST(Commands, ForwardLinearSofteningIsAnalytic) {
  const auto r = run("forward_linear", "forward --type linear --peak-stress 500 --delta-c 3 "
                                       "--j-tip 200 --out out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(work("forward_linear") / "out" / "rdelta_forward.csv");
  std::string line;
  int rows = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'd')
      continue;
    double d, s, R, J;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf", &d, &s, &R, &J), 4);
    // R = J_tip + s_c delta/2 below delta_c (500 kPa * mm / 2 = 250 J/m^2 per mm); printed with
    // 10 significant digits, so 1e-6 J/m^2 is round-off.
    const double exact = d < 3 ? 200 + 250 * d : 200 + 750;
    EXPECT_NEAR(R, exact, 1e-6);
    ++rows;
  }
  EXPECT_GT(rows, 100);
}

TEST(Scenes, DefaultSceneRuns) {
#if !defined(FIBERBRIDGE_HAVE_FEM) || !defined(FIBERBRIDGE_HAVE_MPM)
  GTEST_SKIP() << "the default scene runs the FEM and the MPM; not built (FIBERBRIDGE_MODELS)";
#endif
  const auto r =
      run("default_scene", "run " + source("prm/default.prm") +
                               " --set \"Output directory=out\" --set \"MPM/Threads=1\"");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = read_json(work("default_scene") / "out" / "summary.json");
  EXPECT_TRUE(j.contains("trilinear"));
}

namespace {
std::string scene(const std::string& f) {
  return std::string(FIBERBRIDGE_TEST_DATA) + "/../scenes/" + f;
}

/// Rows of a CSV as maps column -> text (comments skipped).
std::vector<std::map<std::string, std::string>> read_rows(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#')
      continue;
    std::vector<std::string> cells;
    std::stringstream ls(line);
    std::string c;
    while (std::getline(ls, c, ','))
      cells.push_back(c);
    if (header.empty()) {
      header = cells;
      continue;
    }
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i)
      row[header[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}
} // namespace

TEST(Scenes, StudyLadderErrorDecreasesAndStabilityIsDiagnosed) {
  const auto r = run("study_small", "run " + scene("study_beam_small.prm"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = read_rows(work("study_small") / "out" / "study_error_vs_time.csv");
  ASSERT_EQ(rows.size(), 3u);
  for (const char* col :
       {"model", "level", "n_dofs_or_particles", "wall_time_s", "rdelta_rel_error"})
    EXPECT_TRUE(rows[0].count(col)) << col;
  // Refinement must reduce the R_J error against the exact linear-softening R curve (the beam is
  // second order: about 4x per halving; demand at least 2x so the test is about convergence, not
  // the constant).
  for (std::size_t i = 1; i < rows.size(); ++i)
    EXPECT_LT(std::stod(rows[i].at("rdelta_rel_error")),
              0.5 * std::stod(rows[i - 1].at("rdelta_rel_error")));
  const auto stab = read_rows(work("study_small") / "out" / "stability.csv");
  ASSERT_EQ(stab.size(), 2u);
  for (const auto& s : stab) {
    EXPECT_NE(s.at("outcome"), "failure") << s.at("case");
    EXPECT_NE(s.at("outcome"), "suspect") << s.at("case");
  }
  // The 50 mm ligament cannot hold the PVA zone: the run must end with that diagnosis.
  EXPECT_EQ(stab[1].at("case"), "zone_longer_than_ligament");
  EXPECT_EQ(stab[1].at("outcome"), "diagnosed stop");
  EXPECT_NE(stab[1].at("diagnosis").find("ligament"), std::string::npos);
}

TEST(Scenes, CompareClosedLoopShowsTheOldMethodsError) {
  const auto r = run("compare_beam", "run " + scene("compare_beam_pva.prm"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = read_json(work("compare_beam") / "out" / "summary.json");
  ASSERT_TRUE(j.contains("compare"));
  double eq6 = 0, drdd = 0, eq6_control = 0;
  for (const auto& row : j["compare"]["closed_loop"]) {
    if (row["R_source"] == "R_energy" && row["method"] == "eq6")
      eq6 = row["curve_rel_l2"];
    if (row["R_source"] == "R_energy" && row["method"] == "dRdd")
      drdd = row["curve_rel_l2"];
    if (row["R_source"] == "R_eq2" && row["method"] == "eq6")
      eq6_control = row["curve_rel_l2"];
  }
  // The old method misses the PVA law by ~40 % (L2; its peak is ~1.85x low), Eq. 6 from the
  // simulated energy R curve by ~6 % (measured 6.3 %: grid resolution of the 0.1 mm peak, 5.4 %
  // in the Eq. 2 control, plus the non-self-similar zone growth). Bounds with margin: 10 % / 30 %.
  EXPECT_LT(eq6, 0.10);
  EXPECT_GT(drdd, 0.30);
  EXPECT_LT(eq6_control, 0.10);
  const auto rows = read_rows(work("compare_beam") / "out" / "rcurve_beam.csv");
  ASSERT_GT(rows.size(), 100u);
  for (const char* col : {"a_mm", "delta_root_mm", "R_energy_J_m2", "R_J_J_m2", "R_eq2_J_m2",
                          "J_ff_J_m2", "load_N", "load_point_opening_mm"})
    EXPECT_TRUE(rows[0].count(col)) << col;
}

TEST(Scenes, BeamAgreesWithFemOnLinearSoftening) {
#ifndef FIBERBRIDGE_HAVE_FEM
  GTEST_SKIP() << "FEM module not built (FIBERBRIDGE_MODELS)";
#endif
  const auto r = run("beam_vs_fem", "run " + scene("beam_vs_fem_linear.prm"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = read_json(work("beam_vs_fem") / "out" / "summary.json");
  // Both must follow Eq. 2 through the J they measure: FEM 1 mm elements 5.5e-4, beam 8.7e-5
  // measured; 2e-3 bounds the FEM's discretization error at this resolution (study_fem ladder).
  EXPECT_LT(j["beam"]["rdelta_rel_error_vs_eq2"].get<double>(), 2e-3);
  EXPECT_LT(j["fem"]["rdelta_rel_error_vs_eq2"].get<double>(), 2e-3);
  for (const auto& d : j["compare"]["pairwise"]) {
    // Plateaus: both at J_tip + area (measured -0.54 % apart: the beam's discrete tip advance);
    // 1 % allows for that.
    EXPECT_LT(std::abs(d["plateau_rel_diff"].get<double>()), 0.01);
    // Peak load: CBT-calibrated beam vs 2D orthotropic FEM, measured 3.1 %; corrected beam theory
    // itself is good to ~2 % against fine FE (docs/design.md section 3, "Reference formulas"),
    // so 5 %.
    EXPECT_LT(std::abs(d["peak_load_rel_diff"].get<double>()), 0.05);
    // R_J as a function of delta_root is specimen-independent (Eq. 2): measured 0.15 %.
    if (d["quantity"] == "R_J(delta_root)")
      EXPECT_LT(d["rel_l2_developing"].get<double>(), 0.005);
  }
}

TEST(Scenes, ThinArmBeamSaysWhenSmallRotationsAreNotEnough) {
  // The thin composite at J_tip 3786 J/m^2 opens 0.3 of its crack length: the small-rotation
  // load is 1.15 % low (docs/verification.md, finite rotations), past the 1 % bound, so the
  // notes must say so and point at Beam/Kinematics; with finite kinematics they must not.
  const std::string base = "run " + source("prm/lefm_thin_composite.prm") +
                           " --set Run=beam --set 'Output directory=out' --set 'Cohesive law/J "
                           "tip=3786' --set 'Beam/Kinematics=";
  auto said = [&](const std::string& name, const std::string& kinematics) {
    const auto r = run(name, base + kinematics + "'");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const auto j = read_json(work(name) / "out" / "summary.json");
    for (const auto& n : j["beam"]["notes"])
      if (n.get<std::string>().find("Beam/Kinematics = finite") != std::string::npos)
        return true;
    return false;
  };
  EXPECT_TRUE(said("thin_small", "small"));
  EXPECT_FALSE(said("thin_finite", "finite"));
  expect_clean_failure("thin_bad_kinematics", base + "large'", "Kinematics");
}

// The bundled Gmsh specimens (issue 13 item 7): each scene names ../mesh/dcb_specimen.geo, found
// from any working directory against the scene's folder, and runs LEFM with R_J at J_tip (the
// physics is checked in tests/fem/specimen_mesh_tests.cc; 3e-3 is that file's bound). A missing
// mesh fails before anything runs, naming the key.
TEST(Scenes, GmshSpecimenScenesRun) {
#ifndef FIBERBRIDGE_HAVE_FEM
  GTEST_SKIP() << "FEM module not built (FIBERBRIDGE_MODELS)";
#endif
  for (const std::string name : {"fem_tapered_composite", "fem_end_blocks_composite"}) {
    const auto r = run(name, "run " + source("prm/" + name + ".prm") +
                                 " --set 'Output directory=out' --set 'FEM/Output every=0'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = read_json(work(name) / "out" / "summary.json");
    EXPECT_TRUE(j["fem"]["reached_steady_state"].get<bool>()) << name;
    EXPECT_NEAR(j["fem"]["G_ss_J_m2"].get<double>() / 500, 1, 3e-3) << name;
  }
  expect_clean_failure("gmsh_missing",
                       "run " + source("prm/fem_tapered_composite.prm") +
                           " --set Run=beam,fem --set 'FEM/Mesh file=no_such.geo'",
                       "FEM/Mesh file");
}

// A resumed run must not restore the FEM record of another specimen: the mesh file's content is
// part of the record's fingerprint, so an edited .geo under the same name is refused by key.
TEST(Scenes, ResumeRefusesAnEditedSpecimenMesh) {
#ifndef FIBERBRIDGE_HAVE_FEM
  GTEST_SKIP() << "FEM module not built (FIBERBRIDGE_MODELS)";
#endif
  fs::remove_all(work("gmsh_resume"));
  fs::create_directories(work("gmsh_resume"));
  const fs::path geo = work("gmsh_resume") / "specimen.geo";
  fs::copy_file(source("mesh/dcb_specimen.geo"), geo);
  const std::string args = "run " + source("prm/fem_tapered_composite.prm") +
                           " --set 'FEM/Output every=0' --set 'FEM/Mesh file=" + geo.string() +
                           "' --set 'Output directory=" + (work("gmsh_resume") / "out").string() +
                           "'";
  ASSERT_EQ(run("gmsh_resume_run", args).exit_code, 0);
  EXPECT_EQ(run("gmsh_resume_same", args + " --resume").exit_code, 0);
  std::ofstream(geo, std::ios::app) << "// an edit\n";
  const auto r = run("gmsh_resume_edited", args + " --resume");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("FEM/Mesh file content"), std::string::npos) << r.err;
}

// An old key name still runs and the run's notes in summary.json say what replaced it (issue 14
// section 3; the beam's notes are new with Beam/Newton iterations, so its path is checked whole).
TEST(Scenes, OldBeamKeyRunsWithADeprecationNote) {
  const auto r = run("beam_old_key", "run " + source("tests/app/scenes/compare_beam_pva.prm") +
                                         " --set Run=beam --set 'Beam/Newton iterations=40'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = read_json(work("beam_old_key") / "out" / "summary.json");
  unsigned noted = 0;
  for (const auto& n : j["beam"]["notes"])
    noted += n.get<std::string>().find("Beam/Newton iterations is deprecated: use Beam/Maximum "
                                       "Newton iterations") != std::string::npos;
  EXPECT_EQ(noted, 1u);
}

// reduce (issue 12): raw DCB records in, R(a) out; every record that cannot be used gives one
// line naming file:line, exit 1 and no summary.json.
namespace {
const std::string record_map =
    " --columns 'time_s: Time (s), opening_mm: Extension (mm), load_N: Load (N), a_mm: Crack "
    "length (mm)'";
std::string record(const std::string& f) {
  return data("records/" + f);
}
void expect_bad_record(const std::string& file, const std::string& expect) {
  const std::string name = "reduce_" + file.substr(0, file.find('.'));
  expect_clean_failure(name,
                       "reduce " + record(file) + " --width 25 --arm-thickness 2.7" + record_map +
                           " --out out",
                       expect);
  EXPECT_EQ(run(name, "reduce " + record(file) + " --width 25 --arm-thickness 2.7" + record_map +
                          " --out out")
                .exit_code,
            1);
}
} // namespace

TEST(BadInput, RecordDecreasingTime) {
  expect_bad_record("decreasing_time.csv", "decreasing_time.csv:7: time_s = 3 is earlier than 4");
}
TEST(BadInput, RecordCrackLengthGoingBack) {
  expect_bad_record("crack_back.csv", "crack_back.csv:22: a_mm = 33 is 3 mm shorter");
}
TEST(BadInput, RecordMissingColumn) {
  // The map names a crack column the file does not have: an error naming it and the headers
  // found (a record without any crack column is read against the equivalent crack, issue 31).
  expect_bad_record("missing_column.csv", "missing_column.csv:1: no column 'Crack length (mm)' "
                                          "for a_mm (headers found: #1 'Time (s)'");
}
TEST(BadInput, RecordNotANumber) {
  // A cell that is not a number is refused at its line; a NaN cell is a dropout (below).
  const fs::path dir = work("reduce_abc_opening_input"); // run() empties its own directory
  fs::create_directories(dir);
  std::ifstream in(record("nan_opening.csv"));
  std::ofstream out(dir / "abc_opening.csv");
  for (std::string line; std::getline(in, line);)
    out << (line.rfind("6,nan,", 0) == 0 ? "6,abc," + line.substr(6) : line) << "\n";
  out.close();
  expect_clean_failure("reduce_abc_opening",
                       "reduce " + (dir / "abc_opening.csv").string() +
                           " --width 25 --arm-thickness 2.7" + record_map + " --out out",
                       "abc_opening.csv:8: column 'Extension (mm)' holds 'abc', expected a number");
}
TEST(AppReduce, NanOpeningRowIsADropoutNamedInTheCleaning) {
  // A NaN load or opening is a channel dropout (issue 31 item 2): the row is dropped and the
  // cleaning report says so with its line; the record still reduces.
  const auto r =
      run("reduce_nan_opening", "reduce " + record("nan_opening.csv") +
                                    " --width 25 --arm-thickness 2.7" + record_map + " --out out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = read_json(work("reduce_nan_opening") / "out" / "summary.json");
  bool named = false;
  for (const auto& c : j["reduce"]["records"][0]["cleaning"])
    named =
        named || (c.get<std::string>().find("1 row(s) with an empty or NaN") != std::string::npos &&
                  c.get<std::string>().find("line 8") != std::string::npos);
  EXPECT_TRUE(named) << j["reduce"]["records"][0]["cleaning"].dump();
}
TEST(BadInput, RecordNoCrackGrowth) {
  expect_bad_record("no_growth.csv", "no_growth.csv:13: record 'no_growth': the crack length "
                                     "stays at 30 mm");
}
TEST(BadInput, RecordWithoutWidthOrArmThickness) {
  expect_clean_failure("reduce_no_width",
                       "reduce " + record("good.csv") + " --arm-thickness 2.7" + record_map +
                           " --out out",
                       "the specimen width is missing");
  expect_clean_failure("reduce_no_arm",
                       "reduce " + record("good.csv") + " --width 25" + record_map + " --out out",
                       "the arm thickness is missing");
}

TEST(AppReduce, SharedRecordsScene) {
#ifndef FIBERBRIDGE_HAVE_FEM
  // prm/test_records.prm has an FEM section (its fem check), which a build without the FEM does
  // not declare.
  GTEST_SKIP()
      << "FEM module not built (FIBERBRIDGE_MODELS): prm/test_records.prm has an FEM section";
#endif
  // The bundled scene on the four shared records, reduce only: the outputs issue 12 lists. (The
  // identify and FEM items of the scene take minutes; AppIdentify tests them on one record.)
  const auto r = run("reduce_scene", "run " + source("prm/test_records.prm") +
                                         " --set 'Output directory=out' --set Run=reduce");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path out = work("reduce_scene") / "out";
  for (const char* f : {"rcurve_test.csv", "rcurve_test_mean.csv", "summary.json"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  EXPECT_FALSE(fs::exists(out / "RUN_INCOMPLETE.txt"));
  std::ifstream csv(out / "rcurve_test.csv");
  std::string line;
  while (std::getline(csv, line) && line[0] == '#') {
  }
  EXPECT_EQ(line, "record,a_mm,da_mm,R_energy_J_m2,R_energy_lo_J_m2,R_energy_hi_J_m2,R_MBT_J_m2,"
                  "R_CC_J_m2,R_MCC_J_m2,equivalent_crack,a_eq_mm,R_CBBM_J_m2,R_energy_eq_J_m2,"
                  "R_energy_eq_lo_J_m2,R_energy_eq_hi_J_m2,R_energy_readings_J_m2");
  const Json s = read_json(out / "summary.json");
  const Json& b = s.at("reduce");
  ASSERT_EQ(b.at("records").size(), 4u);
  for (const auto& rec : b.at("records")) {
    EXPECT_GT(rec.at("MBT_Delta_mm").get<double>(), 0.0);
    EXPECT_FALSE(rec.at("cleaning").empty());
    for (const char* m : {"energy", "MBT", "CC", "MCC"})
      EXPECT_GT(rec.at(m).at("plateau_J_m2").get<double>(),
                rec.at(m).at("initiation_J_m2").get<double>())
          << rec.at("name") << " " << m << ": the R curve rises (bridging)";
  }
  EXPECT_EQ(b.at("mean").at("n_records").get<int>(), 4);
}

#ifdef FIBERBRIDGE_HAVE_BEAM
// identify (issue 12): the law from one shared record through the scene; bad Identify settings.
TEST(AppIdentify, OneSharedRecordScene) {
#ifndef FIBERBRIDGE_HAVE_FEM
  GTEST_SKIP()
      << "FEM module not built (FIBERBRIDGE_MODELS): prm/test_records.prm has an FEM section";
#endif
  const auto r = run("identify_scene", "run " + source("prm/test_records.prm") +
                                           " --set 'Output directory=out' --set 'Run=identify'"
                                           " --set 'Identify/Per record=false'"
                                           " --set 'Test/Files=" +
                                           source("data/dcb_records/DCB-05_Toughness.csv") + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path out = work("identify_scene") / "out";
  for (const char* f : {"identify_fit.csv", "identify_law.csv", "summary.json"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const Json b = read_json(out / "summary.json").at("identify");
  for (const char* k : {"d1_mm", "sigma1_kPa", "d2_mm", "sigma2_kPa", "delta_c_mm"})
    EXPECT_GT(b.at("trilinear").at(k).get<double>(), 0.0) << k;
  for (const char* k :
       {"J_tip_J_m2", "G_ss_J_m2", "load_rms_rel", "crack_rms_mm", "evaluations", "wall_time_s"})
    EXPECT_TRUE(b.contains(k)) << k;
  // G_ss = J_tip + the law's area, as the block states it.
  const auto& t = b.at("trilinear");
  const double area = 0.5 * (t.at("sigma1_kPa").get<double>() * t.at("d2_mm").get<double>() +
                             t.at("sigma2_kPa").get<double>() *
                                 (t.at("delta_c_mm").get<double>() - t.at("d1_mm").get<double>()));
  EXPECT_NEAR(b.at("G_ss_J_m2").get<double>(), b.at("J_tip_J_m2").get<double>() + area, 1e-6);
  // DCB-05 alone: 1.35 % measured (docs/verification.md); 4 % as in tests/identify.
  EXPECT_LT(b.at("load_rms_rel").get<double>(), 0.04);
}

TEST(AppIdentify, BadSettingsNameTheKey) {
#ifndef FIBERBRIDGE_HAVE_FEM
  // prm/test_records.prm has an FEM section (its fem check), which a build without the FEM does
  // not declare.
  GTEST_SKIP()
      << "FEM module not built (FIBERBRIDGE_MODELS): prm/test_records.prm has an FEM section";
#endif
  const std::string scene = "run " + source("prm/test_records.prm") +
                            " --set 'Output directory=out' --set 'Run=identify' ";
  expect_clean_failure("identify_bad_dc", scene + "--set 'Identify/Delta c max=0.1'",
                       "Identify/Delta c range");
  expect_clean_failure("identify_bad_crack", scene + "--set 'Identify/Crack scatter=0'",
                       "Identify/Crack scatter");
  expect_clean_failure("identify_bad_algorithm", scene + "--set 'Identify/Algorithm=newton'",
                       "Identify/Algorithm");
  expect_clean_failure("identify_no_records", scene + "--set 'Test/Files='", "Test/Files");
}
#endif

#ifdef FIBERBRIDGE_HAVE_BEAM
// Issue 12 part 3: with delta_root measured, the scene runs the three routes on the same record
// and writes them side by side (law_routes.csv, summary block law_routes, law_routes.png).
TEST(AppReduce, ThreeRoutesScene) {
  const auto r =
      run("three_routes", "run " + source("tests/app/scenes/three_routes_delta_root.prm") +
                              " --set 'Output directory=out'"
                              // The outputs, not the identification's accuracy
                              // (tests/identify checks that): a short search
                              // (the full one took 10 min on the loaded machine).
                              " --set 'Identify/Starts=1'"
                              " --set 'Identify/Max evaluations=40'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path out = work("three_routes") / "out";
  ASSERT_TRUE(fs::exists(out / "law_routes.csv"));
  std::ifstream csv(out / "law_routes.csv");
  std::string line;
  while (std::getline(csv, line) && line[0] == '#') {
  }
  EXPECT_EQ(line, "delta_mm,sigma_eq5_kPa,sigma_dRdd_kPa,sigma_identified_kPa");
  const Json s = read_json(out / "summary.json");
  const Json& b = s.at("law_routes");
  for (const char* route : {"eq5", "dRdd", "identified"})
    EXPECT_GT(b.at(route).at("peak_sigma_kPa").get<double>(), 0.0) << route;
  // Eq. 5/6 and dR/ddelta integrate the same slopes: their areas agree (both R(delta_c) -
  // J_tip up to the trapezoid rule on one grid; 2 % covers the S_n = 0 end interval).
  EXPECT_NEAR(b.at("dRdd").at("area_ratio").get<double>(), 1.0, 0.02);
  // The old route's peak lies below Eq. 5/6's (seed Eq. 4: about half on a flat law).
  EXPECT_LT(b.at("dRdd").at("peak_ratio").get<double>(), 1.0);
}
#endif

// R against the CBBM equivalent crack from the command line (issue 31 items 3-4): the bundled
// beam-written record (J_tip 250, G_ss 997.8 J/m^2) with --crack-length equivalent. Measured: the
// CBBM plateau 1012 J/m^2 (+1.5 %: F/N applied to a geometrically linear model's record, and the
// curve still rising at 123 mm), G_CBBM at 5 %/max 251.5 J/m^2 (+0.6 % on J_tip: the crack starts
// at the tip's toughness, the zone still short). Bounds 3 % on both: the measured errors plus the
// 1-2 % that the direct-energy band gives this record (DeltaRootFeedsExtractAndFit).
TEST(AppReduce, EquivalentCrackFromTheCommandLine) {
  const auto r =
      run("reduce_equivalent", "reduce " + record("beam_delta_root.csv") +
                                   " --width 25 --arm-thickness 2.7 --shear-modulus 2290 "
                                   "--transverse-modulus 6110 --crack-length equivalent --out out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path out = work("reduce_equivalent") / "out";
  EXPECT_TRUE(fs::exists(out / "initiation_test.csv"));
  const Json rec = read_json(out / "summary.json").at("reduce").at("records").at(0);
  EXPECT_EQ(rec.at("crack").get<std::string>(), "equivalent");
  EXPECT_NEAR(rec.at("CBBM").at("plateau_J_m2").get<double>(), 997.8, 0.03 * 997.8);
  EXPECT_NEAR(rec.at("initiation").at("5%/max").at("G_CBBM_J_m2").get<double>(), 250, 0.03 * 250);
  EXPECT_TRUE(rec.at("initiation").at("5%/max").at("G_MBT_J_m2").is_null());
  EXPECT_EQ(run("reduce_equivalent_bad", "reduce " + record("beam_delta_root.csv") +
                                             " --width 25 --arm-thickness 2.7 --crack-length "
                                             "guessed --out out")
                .exit_code,
            1);
}

TEST(AppReduce, DeltaRootFeedsExtractAndFit) {
  // G_ss from R(delta_root) of the reduced record against the beam run that wrote it (997.8
  // J/m^2): measured 1014.5 (+1.7 %); 3 % allows for the direct-energy band (+-1-2 % here,
  // docs/verification.md "Test records"). J_tip is not checked: the first smoothing window is
  // one-sided and lifts R at initiation (328 against 250 J/m^2).
  const auto r = run("reduce_root", "run " + source("tests/app/scenes/reduce_delta_root.prm") +
                                        " --set 'Output directory=out'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path out = work("reduce_root") / "out";
  EXPECT_TRUE(fs::exists(out / "rdelta_test.csv"));
  const Json s = read_json(out / "summary.json");
  EXPECT_NEAR(s.at("G_ss_J_m2").get<double>(), 997.8, 0.03 * 997.8);
  EXPECT_TRUE(s.at("reduce").at("records").at(0).at("delta_root_measured").get<bool>());
  EXPECT_TRUE(s.contains("trilinear"));
  std::ifstream csv(out / "rcurve_test.csv");
  std::string line;
  while (std::getline(csv, line) && line[0] == '#') {
  }
  EXPECT_NE(line.find("delta_root_mm,R_delta_J_m2"), std::string::npos) << line;
}

#ifdef FIBERBRIDGE_HAVE_BEAM
namespace {
/// The data rows of a CSV (comment lines dropped), as text.
std::vector<std::string> data_lines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#')
      lines.push_back(line);
  return lines;
}
} // namespace

// Issue 30: a study after identify runs the identified law on the identified specimen (the
// record's a0) and modulus (the calibrated E_L), as the scene's own beam does; the summary names
// the law's and the specimen's source.
TEST(AppStudy, LadderUsesTheIdentifiedSpecimenAndModulus) {
  const auto r =
      run("identify_study", "run " + source("tests/app/scenes/identify_study_small.prm"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path out = work("identify_study") / "out";
  const Json s = read_json(out / "summary.json");
  EXPECT_EQ(s.at("beam").at("law_source"), "identify");
  EXPECT_EQ(s.at("study").at("law_source"), "identify");
  EXPECT_EQ(s.at("study").at("specimen_source"), "identify");
  // The handed-on specimen differs from the sections (a0 70 mm, E_L 15 GPa quoted), so a level
  // on the sections could not reproduce the scene's beam run.
  const Json& rec = s.at("identify").at("records").at(0);
  const double a0_mm = rec.at("a0_mm").get<double>();
  ASSERT_GT(std::abs(a0_mm - 70.0), 10.0);
  ASSERT_GT(std::abs(rec.at("E_L_effective_GPa").get<double>() - 15.0), 1.0);
  // The one level has the Beam section's own settings: the same run, row for row.
  const auto scene_rows = data_lines(out / "rcurve_beam.csv");
  const auto level_rows = data_lines(out / "study" / "beam_level0" / "rcurve_beam.csv");
  ASSERT_GT(scene_rows.size(), 2u);
  EXPECT_EQ(level_rows, scene_rows);
  // Its R curve starts at the identified a0 (the CSV's a_mm, first data row after the header).
  const double a_first = std::stod(level_rows.at(1).substr(0, level_rows.at(1).find(',')));
  // 1e-6 mm: the CSV's 10 significant digits of a length of tens of mm.
  EXPECT_NEAR(a_first, a0_mm, 1e-6);
}
#endif
