// The chain study as a scene (issue 39 item 1; prm/study_chain.prm): virtual tests through the
// measuring chain as a user runs it. Two kinds of test:
// - ChainStudy.*: the instrument itself (tables, refusals as rows, no crash). Pass today.
// - ChainStudyTargets.*: issue 39's targets on Table 1 laws at the paper's 1 Hz (G_ss 2 %, J_tip
//   10 % or 20 J/m^2, delta_c 10 %, sigma1 and sigma2 12 % or 15 kPa, no refusal of a record that
//   reaches steady state). They failed on the estimators of 2026-12-05 (J_tip +42 %, 19 of 20
//   Table 1 laws refused: docs/verification.md, "The chain on virtual tests") and pass with the
//   data-chosen direct-energy windows (issue 39 item 2). Do not loosen them; the tolerances are
//   the issue's.
#include "scene_runner.h"

#include <cmath>

namespace fiberbridge::test {
namespace {

/// The study on `cases` into a fresh work directory; its summary. `more`: further --set options.
Json run_chain_study(const std::string& name, const std::string& cases,
                     const std::string& more = "") {
  const auto r = run(name, "run '" + source("prm/study_chain.prm") +
                               "' --set 'Output directory=out' --set 'Chain study/Table 1=" +
                               source("data/reference/seed_table1.csv") +
                               "' --set 'Chain study/Cases=" + cases + "'" + more);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return read_json(work(name) / "out" / "summary.json");
}

double get(const Json& c, const char* key) {
  return c.contains(key) && c[key].is_number() ? c[key].get<double>() : std::nan("");
}

#ifdef FIBERBRIDGE_HAVE_FEM
TEST(ChainStudy, RefusalIsARowNotACrash) {
  // The long zone (delta_c 9 mm on the seed's 300 mm beam) may or may not reach steady state:
  // either way the study finishes with one row per case and says why a case was refused.
  const Json s = run_chain_study("chain_study_rows", "long_zone");
  ASSERT_TRUE(s.contains("chain_study"));
  const Json& b = s["chain_study"];
  EXPECT_EQ(b["n_cases"].get<int>(), 1);
  EXPECT_TRUE(fs::exists(work("chain_study_rows") / "out" / "chain_recovery.csv"));
  for (const auto& c : b["cases"]) {
    const std::string outcome = c["outcome"].get<std::string>();
    EXPECT_TRUE(outcome == "recovered" || outcome == "refused") << c.dump();
    if (outcome != "recovered")
      EXPECT_FALSE(c["reason"].get<std::string>().empty()) << c.dump();
  }
}

/// Issue 39's targets on one case.
void expect_targets(const Json& c) {
  const std::string name = c["case"].get<std::string>();
  ASSERT_EQ(c["outcome"].get<std::string>(), "recovered")
      << name << " reaches steady state in the FEM but was refused: " << c["reason"];
  const double j = get(c, "J_tip_J_m2"), jt = get(c, "J_tip_true_J_m2");
  EXPECT_LE(std::abs(get(c, "G_ss_err_rel")), 0.02) << name << " G_ss";
  EXPECT_TRUE(std::abs(j - jt) <= 0.10 * jt || std::abs(j - jt) <= 20)
      << name << " J_tip " << j << " against " << jt;
  EXPECT_LE(std::abs(get(c, "delta_c_err_rel")), 0.10) << name << " delta_c";
  for (const char* k : {"sigma1", "sigma2"}) {
    const double v = get(c, (std::string(k) + "_kPa").c_str());
    const double t = get(c, (std::string(k) + "_true_kPa").c_str());
    EXPECT_TRUE(std::abs(v - t) <= 0.12 * t || std::abs(v - t) <= 15)
        << name << " " << k << " " << v << " kPa against " << t;
  }
}

// identify on the same virtual test (Chain study/Identify; issue 39: "measure it, no target"):
// `dic, identify` fits the record dic wrote (the run's identify block names it), and its row is in
// chain_identify.csv. Bounds from the measured base case (docs/verification.md, "identify on the
// virtual tests"): G_ss -1.5 % (3 %: the beam forward model's 1-2 % on these arms), sigma at the
// paper's d1 = 0.1 mm +2.8 % and d2 = 1 mm +2.2 % (12 %, the chain's own target).
TEST(ChainStudy, IdentifyRunsOnTheSameVirtualTest) {
  const auto r = run("chain_study_identify",
                     "run '" + source("prm/study_chain.prm") +
                         "' --set 'Output directory=out' --set 'Chain study/Table 1=" +
                         source("data/reference/seed_table1.csv") +
                         "' --set 'Chain study/Cases=base' --set 'Chain study/Identify=true'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path out = work("chain_study_identify") / "out";
  EXPECT_TRUE(fs::exists(out / "chain_identify.csv"));
  const Json id = read_json(out / "cases" / "base" / "identify" / "summary.json")["identify"];
  ASSERT_EQ(id["records"].size(), 1u);
  EXPECT_EQ(id["records"][0]["record"].get<std::string>(), "dic_record") << id["records"].dump();
  const Json c = read_json(out / "summary.json")["chain_study_identify"]["cases"][0];
  ASSERT_EQ(c["outcome"].get<std::string>(), "identified") << c.dump();
  EXPECT_LE(std::abs(get(c, "G_ss_err_rel")), 0.03) << c.dump();
  EXPECT_LE(std::abs(get(c, "sigma1_err_rel")), 0.12) << c.dump();
  EXPECT_LE(std::abs(get(c, "sigma2_err_rel")), 0.12) << c.dump();
}

TEST(ChainStudyTargets, Table1LawsAtOneHertz) {
  // The PVA control law (the base), two of the 16-cycle laws the issue saw refused, and the
  // Table 1 law whose J_tip the windowed slopes put at +10.0 % (R at initiation fitted to D,
  // docs/design.md: +1.6 %).
  const Json s = run_chain_study("chain_study_targets", "base, EPI_c16, PF_c16, PF_c24");
  ASSERT_TRUE(s.contains("chain_study"));
  for (const auto& c : s["chain_study"]["cases"])
    expect_targets(c);
}
// J_tip on a law no Table 1 group has: a steep, short rise (1.2 MPa at 0.05 mm, 0.3 MPa at
// 0.5 mm, delta_c 3 mm, J_tip 150 J/m^2). The one-sided windows at the first readings read J_tip
// +26 % here; R at initiation fitted to D itself gives -3.6 % (docs/verification.md, "R at
// initiation"). Bound: issue 39's J_tip target, 10 % or 20 J/m^2. (sigma1 and sigma2 are at the
// paper's fixed d1 = 0.1 and d2 = 1 mm, which this law's kinks are not: no bound on them.)
TEST(ChainStudyTargets, JtipOfASteepShortLaw) {
  const Json s = run_chain_study("chain_study_steep_law", "base",
                                 " --set 'Cohesive law/Points=0.05:1200, 0.5:300'"
                                 " --set 'Cohesive law/Delta c=3' --set 'Cohesive law/J tip=150'");
  ASSERT_TRUE(s.contains("chain_study"));
  const Json& c = s["chain_study"]["cases"][0];
  ASSERT_EQ(c["outcome"].get<std::string>(), "recovered") << c.dump();
  const double j = get(c, "J_tip_J_m2"), jt = get(c, "J_tip_true_J_m2");
  EXPECT_EQ(jt, 150);
  EXPECT_TRUE(std::abs(j - jt) <= 0.10 * jt || std::abs(j - jt) <= 20)
      << "J_tip " << j << " against " << jt;
  EXPECT_LE(std::abs(get(c, "G_ss_err_rel")), 0.02) << c.dump();
}
// The fit corrected by simulation (Fit/Model correction, on by default where the fit's data are
// the scene's own records). On the PRF control law the seed's fit has sigma1 +10.2 %: seed Eq. 2's
// recoverable energy is not the dissipation rate the record holds while the zone develops, and the
// records' windows add to it (docs/verification.md, "Where sigma1's bias comes from"). Measured
// after the correction: sigma1 +3.7 %, sigma2 -0.1 %, delta_c -1.6 % (uncorrected +10.2, -2.6,
// +2.5 %); with the simulated records reduced with the records' windows (session 32) +1.0,
// +1.1 and -1.6 %. Bounds: sigma1 6 % (the measured 3.7 % with the run-to-run spread of the chain's
// automatic choices, and under the uncorrected 10 %), sigma2 and delta_c 2.5 % (under their
// uncorrected errors); the uncorrected sigma1 at least 7 %, so that the test says the bias it
// corrects is there.
TEST(ChainStudyTargets, CorrectionRemovesTheSeedFitsBias) {
  const Json s = run_chain_study("chain_study_correction", "PRF_c0");
  ASSERT_TRUE(s.contains("chain_study"));
  const Json& c = s["chain_study"]["cases"][0];
  ASSERT_EQ(c["outcome"].get<std::string>(), "recovered") << c.dump();
  ASSERT_EQ(c["correction"].get<std::string>(), "converged") << c.dump();
  const double t1 = get(c, "sigma1_true_kPa");
  EXPECT_GE(get(c, "sigma1_uncorrected_kPa") / t1 - 1, 0.07) << c.dump();
  EXPECT_LE(std::abs(get(c, "sigma1_err_rel")), 0.06) << c.dump();
  EXPECT_LE(std::abs(get(c, "sigma2_err_rel")), 0.025) << c.dump();
  EXPECT_LE(std::abs(get(c, "delta_c_err_rel")), 0.025) << c.dump();
  expect_targets(c);
}

// Fit/Model correction = fem: the FEM simulates the records instead of the beam. On the PRF
// control virtual test (measured 2026-12-07, with the simulated records reduced with the
// measured windows) the two give the corrected law's G_ss within 0.1 %, delta_c within 0.6 % and
// sigma2 within 0.2 % of each other. 2 % holds the forward models' agreement and fails a FEM
// whose simulated records end early (before the FEM reported the notch-root opening past
// delta_c, its records stopped at delta_c and the correction refused: "no steady state in the
// records simulated"). sigma1 is not compared: it follows J_tip through the bridging area, and
// the FEM's J_tip runs 1-5 % low against the beam's at 2 mm elements (docs/verification.md,
// "The specimen's far end in the chain"), which moves sigma1 by about 2 %.
TEST(ChainStudy, FemAsTheCorrectionsForwardModel) {
  const std::string name = "chain_study_fem_correction";
  run_chain_study(name, "PRF_c0");
  const std::string scene =
      (work(name) / "out" / "cases" / "PRF_c0" / "fem" / "virtual_test" / "dic_scene.prm").string();
  Json by[2];
  int k = 0;
  for (const std::string model : {"beam", "fem"}) {
    const std::string out = (work(name) / ("by_" + model)).string();
    // The work directory of `run` is wiped per name: each run its own.
    const auto r = run(name + "_" + model, "run '" + scene +
                                               "' --set 'Run=dic, reduce, extract, fit' --set "
                                               "'Output directory=" +
                                               out + "' --set 'Fit/Model correction=" + model +
                                               "' --set 'FEM/Element size=2'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    by[k++] = read_json(fs::path(out) / "summary.json");
  }
  for (const auto& s : by)
    ASSERT_TRUE(s["fit_correction"]["converged"].get<bool>()) << s["fit_correction"].dump();
  EXPECT_EQ(by[1]["fit_correction"]["forward_model"].get<std::string>(), "fem");
  const Json &beam = by[0]["trilinear_corrected"], &fem = by[1]["trilinear_corrected"];
  for (const char* key : {"G_ss_J_m2", "delta_c_mm", "sigma2_kPa"})
    EXPECT_NEAR(get(fem, key) / get(beam, key), 1.0, 0.02) << key;
}

// The specimen's far end (Fit/Model correction = auto). On PVA at 8-24 cycles the zone is
// 130-140 mm long when the notch root moves, 60-70 mm before the virtual specimen's end: R
// falls from there on (the tip runs ahead of the work done), and extract's plateau reads G_ss
// 2.6-5.2 % low (measured 2026-12-07; the record holds no steady state to read). extract flags
// the fall (end_effect), auto then corrects with the FEM, which holds the far end, and the
// corrected law's G_ss (J_tip + J1 + J2) is within 0.8 % (issue 39's target: 2 %). The plateau
// is required to be at least 2 % low, so that the test says the effect it corrects is there.
TEST(ChainStudyTargets, SpecimensFarEndCorrectedByTheFem) {
  const std::string name = "chain_study_far_end";
  const Json s = run_chain_study(name, "PVA_c8, PVA_c24");
  ASSERT_TRUE(s.contains("chain_study"));
  ASSERT_EQ(s["chain_study"]["cases"].size(), 2u);
  for (const auto& c : s["chain_study"]["cases"]) {
    const std::string id = c["case"].get<std::string>();
    ASSERT_EQ(c["correction"].get<std::string>(), "converged") << c.dump();
    const Json chain = read_json(work(name) / "out" / "cases" / id / "chain" / "summary.json");
    EXPECT_TRUE(chain["extract"]["end_effect"].get<bool>()) << id;
    EXPECT_EQ(chain["fit_correction"]["forward_model"].get<std::string>(), "fem") << id;
    EXPECT_LE(get(c, "G_ss_uncorrected_J_m2") / get(c, "G_ss_true_J_m2") - 1, -0.02) << c.dump();
    expect_targets(c);
  }
}
#else
TEST(ChainStudy, SkippedWithoutTheFem) {
  GTEST_SKIP() << "the FEM is not built";
}

TEST(FitCorrection, FemForwardModelNeedsTheFem) {
  expect_clean_failure("fit_correction_fem_without_fem",
                       "run '" + source("tests/app/scenes/reduce_delta_root.prm") +
                           "' --set 'Output directory=out' --set 'Fit/Model correction=fem'",
                       "Fit/Model correction = fem needs a build with the FEM");
}
#endif

} // namespace
} // namespace fiberbridge::test
