// The durability campaign (issue 33): a synthetic campaign from known laws recovered within a
// stated tolerance, the bootstrap intervals' coverage, the ranking, determinism, the paper's own
// Table 1 as group values, bad manifests, and the laws as LS-DYNA / Abaqus take them.
#include "fiberbridge/analysis/campaign.h"
#include "fiberbridge/analysis/campaign_run.h"
#include "fiberbridge/analysis/campaign_synthetic.h"
#include "fiberbridge/analysis/cohesive_export.h"
#include "fiberbridge/analysis/degradation.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>

using namespace fiberbridge;
using namespace fiberbridge::analysis;
namespace fs = std::filesystem;

namespace {

const std::string table1 = std::string(FIBERBRIDGE_DATA_DIR) + "/reference/seed_table1.csv";

fs::path scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("fiberbridge_campaign_tests_" + name);
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

/// The synthetic campaign of the Table 1 laws written under scratch(name); its manifest's path.
std::string synthetic_manifest(const std::string& name, const SyntheticCampaignOptions& so = {}) {
  return write_synthetic_campaign(scratch(name).string(), table1_truth(read_property_table(table1)),
                                  so);
}

CampaignResult synthetic_campaign(const std::string& name, const SyntheticCampaignOptions& so,
                                  int samples, unsigned seed = 1) {
  const std::string m = synthetic_manifest(name, so);
  CampaignOptions o;
  o.bootstrap_samples = samples;
  o.seed = seed;
  return analyse_campaign(read_campaign_manifest(m), {}, o, {"DF"});
}

/// Equal, NaN equal to NaN (l_b and rho_b are NaN without crack lengths in the data).
bool same(double a, double b) {
  return a == b || (std::isnan(a) && std::isnan(b));
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

/// What the method itself may miss by (a fraction of the group's peak stress), measured with
/// the test below: the adhesives' sigma1 within 2.6 % of the peak (Eq. 6's smoothing over
/// +-k delta_c/n = +-0.1 mm rounds the peak at d1 = 0.1 mm; docs/verification.md, "Closed
/// loop"), sigma2 within 0.6 %; DF within 9.9 %: its laws are small (G_B 50-300 J/m^2 against
/// 4 J/m^2 noise) and two of them rise after d1 (sigma1 < sigma2), where the smoothing window,
/// which spans the whole first segment, pulls sigma1 towards the second.
double method_allowance(const std::string& material) {
  return material == "DF" ? 0.12 : 0.04;
}

} // namespace

// Every group's trilinear values against the law it was made from. Tolerance: the group mean of
// 5 specimens with 10 % independent scatter on sigma1 and sigma2 lies within 3 standard errors
// (3 x 10 %/sqrt(5) = 13.4 %) of the truth for all but ~0.3 % of quantities, plus what the
// method itself may miss (method_allowance, measured by the zero-scatter test below).
TEST(CampaignSynthetic, TrilinearValuesWithinToleranceOfTruth) {
  SyntheticCampaignOptions so;
  so.seed = 11;
  const auto r = synthetic_campaign("truth", so, 0);
  const auto truth = table1_truth(read_property_table(table1));
  ASSERT_EQ(r.groups.size(), truth.size());
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const auto& g = r.groups[i];
    const auto& t = truth[i].law;
    ASSERT_EQ(g.material, truth[i].material);
    ASSERT_TRUE(g.estimate.ok) << g.material << " " << g.cycles << ": " << g.estimate.failure;
    const double peak = std::max(t.s1, t.s2), m = method_allowance(g.material);
    EXPECT_NEAR(g.estimate.tri.s1, t.s1, 0.134 * t.s1 + m * peak) << g.material << g.cycles;
    EXPECT_NEAR(g.estimate.tri.s2, t.s2, 0.134 * t.s2 + m * peak) << g.material << g.cycles;
    EXPECT_NEAR(g.estimate.J1, t.j1(), 0.134 * t.j1() + m * t.area()) << g.material;
    EXPECT_NEAR(g.estimate.J2, t.j2(), 0.134 * t.j2() + m * t.area()) << g.material;
    // G_ss = J_tip + area: the area's scatter as above, J_tip's 2 % scatter over 5 specimens.
    EXPECT_NEAR(g.estimate.G_ss, 200 + t.area(), 0.134 * t.area() + 0.03 * 200) << g.material;
    EXPECT_NEAR(g.estimate.j_tip, 200, 0.03 * 200) << g.material;
    EXPECT_DOUBLE_EQ(g.estimate.delta_c, t.dc); // the manifest's delta_c_mm (seed: fixed)
  }
}

// Without specimen scatter the campaign measures the method alone: Eq. 6 and the fit on Eq. 2
// data with 4 J/m^2 noise.
TEST(CampaignSynthetic, WithoutScatterTheMethodAloneIsClose) {
  SyntheticCampaignOptions so;
  so.stress_cv = 0;
  so.seed = 5;
  const auto r = synthetic_campaign("no_scatter", so, 0);
  const auto truth = table1_truth(read_property_table(table1));
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const auto& g = r.groups[i];
    const auto& t = truth[i].law;
    ASSERT_TRUE(g.estimate.ok);
    const double peak = std::max(t.s1, t.s2);
    const double m = method_allowance(g.material) * peak;
    EXPECT_NEAR(g.estimate.tri.s1, t.s1, m) << g.material << " " << g.cycles;
    EXPECT_NEAR(g.estimate.tri.s2, t.s2, m) << g.material << " " << g.cycles;
  }
}

// Coverage of the 95 % intervals over repeated campaigns (other seeds of the data and of the
// bootstrap): 6 campaigns x 20 groups x 6 quantities. Measured over 20 campaigns
// (docs/verification.md, "Durability campaign"): 0.945 with the default student t interval,
// 0.89 expanded percentile, 0.82 percentile (a percentile interval cannot reach beyond the range
// of 5 specimens). The binomial standard error of 720 trials at 0.945 is 0.0085: the bounds
// (0.90, 0.985) are 5 of them either side, so the test fails for intervals that are too narrow
// (the percentile ones would) or vacuous, not by chance.
TEST(CampaignSynthetic, IntervalCoverageOverRepeatedCampaigns) {
  int hit = 0, all = 0;
  const auto truth = table1_truth(read_property_table(table1));
  for (int c = 0; c < 6; ++c) {
    SyntheticCampaignOptions so;
    so.seed = 100 + c;
    const auto r = synthetic_campaign("coverage", so, 200, 7 + c);
    for (std::size_t i = 0; i < r.groups.size(); ++i) {
      const auto& g = r.groups[i];
      const auto& t = truth[i].law;
      const std::vector<std::pair<GroupQuantity, double>> checks{
          {GroupQuantity::sigma1, t.s1 / 1e3},   {GroupQuantity::sigma2, t.s2 / 1e3},
          {GroupQuantity::J1, t.j1()},           {GroupQuantity::J2, t.j2()},
          {GroupQuantity::G_ss, 200 + t.area()}, {GroupQuantity::J_tip, 200.0}};
      for (const auto& [q, v] : checks) {
        const auto& ci = g.ci[static_cast<std::size_t>(q)];
        ++all;
        hit += ci.lo <= v && v <= ci.hi ? 1 : 0;
      }
    }
  }
  const double coverage = static_cast<double>(hit) / all;
  std::cout << "coverage of the 95 % intervals: " << hit << "/" << all << " = " << coverage << "\n";
  EXPECT_GT(coverage, 0.90);
  EXPECT_LT(coverage, 0.985);
}

// The ranking: with 3 % specimen scatter the campaign must give the paper's order and be sure of
// it; at the bundled 10 % the order is recovered in 19 of 20 campaigns (docs/verification.md).
TEST(CampaignSynthetic, RankingRecovered) {
  SyntheticCampaignOptions so;
  so.stress_cv = 0.03;
  so.seed = 3;
  const auto r = synthetic_campaign("ranking", so, 200);
  std::vector<std::string> order;
  for (const auto& m : r.ranking.ranks)
    order.push_back(m.material);
  EXPECT_EQ(order, (std::vector<std::string>{"PF", "EPI", "PRF", "PVA"}));
  EXPECT_EQ(r.ranking.reference, std::vector<std::string>{"DF"});
  for (const auto& p : r.ranking.pairs)
    EXPECT_GT(p.p_first_ahead, 0.8) << p.first << " ahead of " << p.second;
}

// Deterministic given the seed; a group's intervals do not depend on the other groups (its seed
// mixes only the campaign's seed and its own key), so the groups could run anywhere.
TEST(CampaignBootstrap, DeterministicAndIndependentOfOtherGroups) {
  SyntheticCampaignOptions so;
  so.replicates = 4;
  const auto truth = table1_truth(read_property_table(table1));
  const std::string m = write_synthetic_campaign(scratch("determinism").string(), truth, so);
  CampaignOptions o;
  o.bootstrap_samples = 50;
  const auto manifest = read_campaign_manifest(m);
  const auto a = analyse_campaign(manifest, {}, o, {"DF"});
  const auto b = analyse_campaign(manifest, {}, o, {"DF"});
  CampaignManifest only_pf = manifest;
  only_pf.rows.erase(std::remove_if(only_pf.rows.begin(), only_pf.rows.end(),
                                    [](const CampaignRow& r) { return r.material != "PF"; }),
                     only_pf.rows.end());
  const auto c = analyse_campaign(only_pf, {}, o, {});
  for (std::size_t i = 0; i < a.groups.size(); ++i)
    for (std::size_t k = 0; k < n_group_quantities; ++k) {
      EXPECT_TRUE(same(a.groups[i].ci[k].lo, b.groups[i].ci[k].lo));
      EXPECT_TRUE(same(a.groups[i].ci[k].hi, b.groups[i].ci[k].hi));
    }
  for (const auto& g : c.groups) {
    const auto it = std::find_if(a.groups.begin(), a.groups.end(), [&](const CampaignGroup& x) {
      return x.material == g.material && x.cycles == g.cycles;
    });
    ASSERT_NE(it, a.groups.end());
    for (std::size_t k = 0; k < n_group_quantities; ++k)
      EXPECT_TRUE(same(it->ci[k].lo, g.ci[k].lo));
  }
  o.seed = 2;
  const auto d = analyse_campaign(manifest, {}, o, {"DF"});
  EXPECT_NE(a.groups[0].ci[1].lo, d.groups[0].ci[1].lo) << "the seed must matter";
}

// The paper's Table 1 given as group values: the campaign's degradation and ranking are the
// `rank` command's (degradation.h) on the printed table, and reproduce the printed slopes and R^2.
TEST(CampaignTable1, SeedValuesReproduceThePapersSlopesAndRanking) {
  const auto table = read_property_table(table1);
  std::vector<CampaignGroup> groups;
  for (const auto& mat : {"PVA", "EPI", "PRF", "PF", "DF"})
    for (std::size_t c = 0; c < table.cycles.size(); ++c) {
      CampaignGroup g;
      g.material = mat;
      g.cycles = table.cycles[c];
      g.estimate.ok = g.estimate.has_law = true;
      g.estimate.tri = {0.1e-3, table.find(mat, "sigma1")->values[c] * 1e3, 1e-3,
                        table.find(mat, "sigma2")->values[c] * 1e3, seed_delta_c_mm(mat) * 1e-3};
      g.estimate.J1 = table.find(mat, "J1")->values[c];
      g.estimate.J2 = table.find(mat, "J2")->values[c];
      g.estimate.l_b = table.find(mat, "lb")->values[c] * 1e-3;
      groups.push_back(g);
    }
  const auto deg = campaign_degradation(groups, 0.95);
  const auto printed = analyse_degradation(table);
  int compared = 0;
  for (const auto& p : printed) {
    const auto it = std::find_if(deg.begin(), deg.end(), [&](const CampaignDegradation& d) {
      return d.material == p.material && d.property == p.property;
    });
    ASSERT_NE(it, deg.end()) << p.material << " " << p.property;
    ASSERT_TRUE(it->has_slope);
    // Same numbers through the same regression: equal to rounding of the unit conversions.
    EXPECT_NEAR(it->paper.fit.slope, p.fit.slope, 1e-9 * (1 + std::abs(p.fit.slope)));
    EXPECT_NEAR(it->paper.fit.r2, p.fit.r2, 1e-9);
    EXPECT_EQ(it->paper.significant, p.significant);
    // The printed slope and R^2 (rounded or truncated, degradation.h) of the four adhesives;
    // DF's printed rows are known not to follow from its printed values (docs/design.md
    // section 1, "Degradation and ranking": the 16-cycle row is inconsistent).
    if (p.has_printed && p.material != "DF") {
      EXPECT_TRUE(p.matches_printed) << p.material << " " << p.property;
      ++compared;
    }
    EXPECT_TRUE(std::isnan(it->p_value)) << "no bootstrap, no p";
  }
  EXPECT_EQ(compared, 16); // sigma1, J1, sigma2, J2 of the four adhesives
  const auto ranking = campaign_ranking(groups, {"DF"});
  std::vector<std::string> order;
  for (const auto& m : ranking.ranks)
    order.push_back(m.material);
  EXPECT_EQ(order, (std::vector<std::string>{"PF", "EPI", "PRF", "PVA"}));
  EXPECT_EQ(ranking.reference, std::vector<std::string>{"DF"});
}

namespace {

/// Two synthetic PVA c0 records in `d` (PVA_c0_s1.csv, PVA_c0_s2.csv) for manifests to list.
void write_two_pva_records(const fs::path& d) {
  const auto truth = table1_truth(read_property_table(table1));
  SyntheticCampaignOptions so;
  so.replicates = 2;
  write_synthetic_campaign(d.string(), {truth[0]}, so);
}

/// A check that the manifest `text`, written to d/m.csv, is refused with a message holding `what`.
auto manifest_error_check(const fs::path& d) {
  return [d](const std::string& text, const std::string& what) {
    write(d / "m.csv", text);
    try {
      read_campaign_manifest((d / "m.csv").string());
      ADD_FAILURE() << "no error for: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
}

} // namespace

// Bad manifests: every error names manifest:line.
TEST(CampaignManifest, BadManifestsNameTheLine) {
  const fs::path d = scratch("bad");
  write_two_pva_records(d);
  const auto expect_error = manifest_error_check(d);
  const std::string head = "file,material,cycles,specimen\n";
  expect_error(head + "PVA_c0_s1.csv,PVA,0,a\nmissing.csv,PVA,0,b\n", "m.csv:3");
  expect_error(head + "PVA_c0_s1.csv,PVA,0,a\nPVA_c0_s2.csv,PVA,0,a\n", "listed twice");
  expect_error(head + "PVA_c0_s1.csv,PVA,0,a\nPVA_c0_s1.csv,PVA,0,b\n", "m.csv:3: file");
  expect_error(head + "PVA_c0_s1.csv,PVA,-8,a\n", "m.csv:2: cycles");
  expect_error("file,material,cycles\nPVA_c0_s1.csv,PVA,0\n", "'specimen' is missing");
  expect_error(head, "no data rows");
  expect_error("file,material,cycles,specimen,delta_c_mm\nPVA_c0_s1.csv,PVA,0,a,-1\n",
               "m.csv:2: column delta_c_mm");
  // The geometry columns: positive, a0 inside the length; read in mm.
  expect_error("file,material,cycles,specimen,a0_mm\nPVA_c0_s1.csv,PVA,0,a,x\n",
               "m.csv:2: column a0_mm");
  expect_error("file,material,cycles,specimen,a0_mm,length_mm\nPVA_c0_s1.csv,PVA,0,a,150,120\n",
               "m.csv:2: a0_mm must be shorter than length_mm");
  write(d / "m.csv", "file,material,cycles,specimen,width_mm,arm_thickness_mm,a0_mm,length_mm\n"
                     "PVA_c0_s1.csv,PVA,0,a,25,2.7,40,\n");
  const auto m = read_campaign_manifest((d / "m.csv").string());
  EXPECT_DOUBLE_EQ(m.rows[0].width, 25e-3);
  EXPECT_DOUBLE_EQ(m.rows[0].arm_thickness, 2.7e-3);
  EXPECT_DOUBLE_EQ(m.rows[0].initial_crack, 40e-3);
  EXPECT_TRUE(std::isnan(m.rows[0].length)); // empty cell: the scene's Specimen
}

// A group of one specimen has no interval (said so), a material with two cycle counts no slope
// (said so), and neither is an error.
TEST(CampaignManifest, OneSpecimenAndTwoCycleCountsAreNotes) {
  const fs::path d = scratch("notes");
  auto truth = table1_truth(read_property_table(table1));
  truth.resize(2); // PVA at 0 and 8 cycles
  SyntheticCampaignOptions so;
  so.replicates = 3;
  write_synthetic_campaign(d.string(), truth, so);
  write(d / "m.csv", "file,material,cycles,specimen,delta_c_mm\nPVA_c0_s1.csv,PVA,0,a,6\n"
                     "PVA_c8_s1.csv,PVA,8,a,6\nPVA_c8_s2.csv,PVA,8,b,6\nPVA_c8_s3.csv,PVA,8,c,6\n");
  CampaignOptions o;
  o.bootstrap_samples = 50;
  const auto r = analyse_campaign(read_campaign_manifest((d / "m.csv").string()), {}, o, {});
  ASSERT_EQ(r.groups.size(), 2u);
  EXPECT_TRUE(r.groups[0].estimate.ok);
  EXPECT_FALSE(r.groups[0].has_interval());
  EXPECT_TRUE(std::isnan(r.groups[0].ci[1].lo));
  bool said = false;
  for (const auto& n : r.groups[0].notes)
    said = said || n.find("one specimen, no interval") != std::string::npos;
  EXPECT_TRUE(said);
  EXPECT_TRUE(r.groups[1].has_interval());
  ASSERT_FALSE(r.degradation.empty());
  for (const auto& dd : r.degradation) {
    EXPECT_FALSE(dd.has_slope);
    EXPECT_NE(dd.note.find("needs at least 3"), std::string::npos) << dd.note;
  }
  EXPECT_TRUE(r.ranking.ranks.empty());
  EXPECT_EQ(r.ranking.not_ranked, std::vector<std::string>{"PVA"});
}

// One group, one kind of input: an R(delta) table beside a raw record is an error naming both
// lines. The raw record is one of the shared real records (data/dcb_records, MIT licence).
TEST(CampaignManifest, MixedInputsInOneGroupAreAnError) {
  const fs::path d = scratch("mixed");
  const auto truth = table1_truth(read_property_table(table1));
  SyntheticCampaignOptions so;
  so.replicates = 1;
  write_synthetic_campaign(d.string(), {truth[0]}, so);
  const std::string record =
      std::string(FIBERBRIDGE_DATA_DIR) + "/dcb_records/DCB-01_Toughness.csv";
  write(d / "m.csv",
        "file,material,cycles,specimen\nPVA_c0_s1.csv,PVA,0,a\n" + record + ",PVA,0,b\n");
  RawRecordOptions raw;
  raw.read.columns = RecordColumnMap::parse(
      "time_s: Time, opening_mm: Disp, load_N: Force, a_mm: CrackExt", "test");
  raw.specimen.width = 25e-3;
  raw.specimen.height = 2 * 2.7e-3; // both arms
  try {
    analyse_campaign(read_campaign_manifest((d / "m.csv").string()), raw, {}, {});
    ADD_FAILURE() << "mixed inputs accepted";
  } catch (const InputError& e) {
    const std::string w = e.what();
    EXPECT_NE(w.find("m.csv:3"), std::string::npos) << w;
    EXPECT_NE(w.find("m.csv:2"), std::string::npos) << w;
    EXPECT_NE(w.find("one kind of input"), std::string::npos) << w;
  }
}

// LS-DYNA: the normalised curve and T, GIC give back delta_c (LS-DYNA's ultimate separation is
// GIC / (T x area of the curve)) and the law's area and peak; exact up to rounding.
TEST(CohesiveExport, LsDynaCurveKeepsAreaPeakAndDeltaC) {
  const auto law = trilinear_polyline(0.1e-3, 661e3, 1e-3, 187e3, 6e-3);
  const auto c = lsdyna_normalised_curve(law);
  EXPECT_NEAR(c.ultimate_separation(), 6e-3, 1e-15);
  EXPECT_NEAR(c.GIC, law.area(), 1e-9);
  EXPECT_DOUBLE_EQ(c.T, 661e3);
  EXPECT_DOUBLE_EQ(*std::max_element(c.t_over_T.begin(), c.t_over_T.end()), 1.0);
  const std::string card = lsdyna_mat_cohesive_general(law, 7, 1007, "PVA control");
  EXPECT_NE(card.find("*MAT_COHESIVE_GENERAL"), std::string::npos);
  // T = 0.661 MPa, GIC = area in N/mm (0.8822 N/mm for this law).
  EXPECT_NE(card.find("1.0,0.661,0.661,0.0"), std::string::npos) << card;
  EXPECT_NE(card.find("7,1.0e-9,0,1,0,1007,"), std::string::npos) << card;
  EXPECT_NE(card.find(",0.88215,0.88215\n"), std::string::npos) << card;
}

// Abaqus: the traction the tabular damage gives (linear D between rows, as Abaqus interpolates)
// keeps the law's area and peak to 0.1 % with 200 rows per segment; D rises from 0 to 1.
TEST(CohesiveExport, AbaqusTableKeepsAreaAndPeak) {
  for (const auto& law : {trilinear_polyline(0.1e-3, 661e3, 1e-3, 187e3, 6e-3),
                          trilinear_polyline(0.1e-3, 7e3, 1e-3, 34e3, 3.5e-3)}) {
    const auto t = abaqus_damage_table(law, 200);
    EXPECT_EQ(t.D.front(), 0.0);
    EXPECT_EQ(t.D.back(), 1.0);
    for (std::size_t i = 1; i < t.D.size(); ++i)
      EXPECT_GE(t.D[i], t.D[i - 1]);
    double area = 0, peak = 0, prev = 0;
    const int n = 200000;
    const double dc = law.delta.back();
    for (int i = 1; i <= n; ++i) {
      const double d = dc * i / n, s = t.traction(d);
      area += 0.5 * (s + prev) * dc / n;
      peak = std::max(peak, s);
      prev = s;
    }
    EXPECT_NEAR(area, law.area(), 1e-3 * law.area());
    EXPECT_NEAR(peak, law.peak(), 1e-3 * law.peak());
    const std::string inp = abaqus_cohesive_material(law, "X");
    EXPECT_NE(inp.find("*DAMAGE EVOLUTION, TYPE=DISPLACEMENT, SOFTENING=TABULAR"),
              std::string::npos);
    EXPECT_NE(inp.find("*ELASTIC, TYPE=TRACTION"), std::string::npos);
  }
}

// l_b (crack growth to the peak-stress opening d1, seed section 3.4) where the R(delta) files
// carry crack lengths, and the rho_b range from it: a group whose files have a_mm = 100 + 67
// delta_mm gives l_b = 6.7 mm (the seed's PVA control) whatever the specimen.
TEST(CampaignGroup, ZoneLengthFromCrackLengthsAndTheDensityRange) {
  const fs::path d = scratch("lb");
  const auto truth = table1_truth(read_property_table(table1));
  SyntheticCampaignOptions so;
  so.replicates = 3;
  const std::string m = write_synthetic_campaign(d.string(), {truth[0]}, so);
  // Add a crack-length column to every file (same rows, a linear in delta).
  for (int k = 1; k <= 3; ++k) {
    const fs::path f = d / ("PVA_c0_s" + std::to_string(k) + ".csv");
    std::ifstream in(f);
    std::string line, out;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#')
        out += line + "\n";
      else if (line.rfind("replicate", 0) == 0)
        out += line + ",a_mm\n";
      else {
        const double delta_mm = std::stod(line.substr(line.find(',', line.find(',') + 1) + 1));
        out += line + "," + std::to_string(100 + 67 * delta_mm) + "\n";
      }
    }
    in.close();
    write(f, out);
  }
  CampaignOptions o;
  o.bootstrap_samples = 20;
  const auto r = analyse_campaign(read_campaign_manifest(m), {}, o, {});
  ASSERT_EQ(r.groups.size(), 1u);
  const auto& g = r.groups[0];
  ASSERT_TRUE(g.estimate.ok) << g.estimate.failure;
  // Linear interpolation of a linear column: exact to the printed digits (std::to_string, 1e-6).
  EXPECT_NEAR(g.estimate.l_b, 6.7e-3, 1e-8);
  EXPECT_NEAR(r.specimens[0].l_b, 6.7e-3, 1e-8);
  ASSERT_TRUE(std::isfinite(g.estimate.rho_low));
  EXPECT_LT(g.estimate.rho_low, g.estimate.rho_high);
  // The range is the model's at the fitted sigma1 and the group's l_b (bridging_model.h), for
  // the tracheid (Bridging section defaults) and the seed's bundle at 50 J/m^2.
  const auto rho = [&](const BridgingFiber& f) {
    return bridged_density(g.estimate.tri.s1, 0.1e-3, g.estimate.l_b, f,
                           BridgingMechanism::governing, false);
  };
  const double a1 = rho(seed_tracheid_fiber()), a2 = rho(seed_bundle_fiber(50));
  EXPECT_DOUBLE_EQ(g.estimate.rho_low, std::min(a1, a2));
  EXPECT_DOUBLE_EQ(g.estimate.rho_high, std::max(a1, a2));
  EXPECT_TRUE(std::isfinite(g.ci[static_cast<std::size_t>(GroupQuantity::rho_high)].hi));
}

// A raw record that measured delta_root becomes the specimen's R(delta_root) (reduce's direct
// energy, to_rdelta); one without stays R(a) only. The shared record DCB-01 (data/dcb_records)
// with a made-up delta_root column (a fifth of the opening: only the plumbing is tested here).
TEST(CampaignSpecimen, RawRecordWithDeltaRootGivesRDelta) {
  const fs::path d = scratch("raw");
  const std::string record =
      std::string(FIBERBRIDGE_DATA_DIR) + "/dcb_records/DCB-01_Toughness.csv";
  std::ifstream in(record);
  std::string line, out;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    if (line.rfind("Time", 0) == 0)
      out += line + ",Root\n";
    else {
      const auto c1 = line.find(','), c2 = line.find(',', c1 + 1);
      out += line + "," + std::to_string(0.2 * std::stod(line.substr(c1 + 1, c2 - c1 - 1))) + "\n";
    }
  }
  write(d / "with_root.csv", out);
  write(d / "m.csv", "file,material,cycles,specimen\nwith_root.csv,X,0,a\n" + record + ",Y,0,b\n");
  RawRecordOptions raw;
  raw.read.columns = RecordColumnMap::parse(
      "time_s: Time, opening_mm: Disp, load_N: Force, a_mm: CrackExt, delta_root_mm: Root", "t");
  raw.specimen.width = 25e-3;
  raw.specimen.height = 2 * 2.7e-3; // both arms
  const auto manifest = read_campaign_manifest((d / "m.csv").string());
  const auto a = load_campaign_specimen(manifest.rows[0], raw);
  EXPECT_EQ(a.input, SpecimenInput::raw_record);
  EXPECT_TRUE(a.has_rdelta);
  EXPECT_GT(a.curve.delta.size(), 5u);
  EXPECT_EQ(a.curve.a.size(), a.curve.delta.size());
  raw.read.columns =
      RecordColumnMap::parse("time_s: Time, opening_mm: Disp, load_N: Force, a_mm: CrackExt", "t");
  const auto b = load_campaign_specimen(manifest.rows[1], raw);
  EXPECT_FALSE(b.has_rdelta);
  EXPECT_TRUE(std::isfinite(b.plateau));
  EXPECT_TRUE(std::isfinite(b.initiation));
}

// Issue 42's campaign findings. Materials whose names become the same file names ("PF 1" and
// "PF_1", "X/Y" and "X:Y"), a name too long for a file name, and a cycle count the degradation
// fit cannot take are refused with the manifest's line before anything runs.
TEST(CampaignManifest, CollidingMaterialNamesLongNamesAndHugeCyclesAreRefused) {
  const fs::path d = scratch("collide");
  write_two_pva_records(d);
  const auto expect_error = manifest_error_check(d);
  const std::string head = "file,material,cycles,specimen\n";
  expect_error(head + "PVA_c0_s1.csv,PF 1,0,a\nPVA_c0_s2.csv,PF_1,0,b\n",
               "m.csv:3: material 'PF_1' and 'PF 1'");
  expect_error(head + "PVA_c0_s1.csv,X/Y,0,a\nPVA_c0_s2.csv,X:Y,0,b\n", "same file names");
  expect_error(head + "PVA_c0_s1.csv," + std::string(300, 'M') + ",0,a\n",
               "m.csv:2: material name of 300 characters");
  expect_error(head + "PVA_c0_s1.csv,PVA,1e300,a\n", "m.csv:2: cycles");
  // The same material on several lines is one name, not a collision.
  write(d / "m.csv", head + "PVA_c0_s1.csv,PF 1,0,a\nPVA_c0_s2.csv,PF 1,0,b\n");
  EXPECT_EQ(read_campaign_manifest((d / "m.csv").string()).rows.size(), 2u);
}

// A campaign where no group can be estimated (delta_c_mm written in micrometres) is a failed
// run, not an empty Table 1 with exit 0.
TEST(CampaignRun, NoGroupEstimatedIsAnError) {
  const fs::path d = scratch("none");
  const auto truth = table1_truth(read_property_table(table1));
  SyntheticCampaignOptions so;
  so.replicates = 3;
  write_synthetic_campaign(d.string(), {truth[0]}, so);
  write(d / "m.csv", "file,material,cycles,specimen,delta_c_mm\nPVA_c0_s1.csv,PVA,0,a,6000\n"
                     "PVA_c0_s2.csv,PVA,0,b,6000\nPVA_c0_s3.csv,PVA,0,c,6000\n");
  CampaignOptions o;
  o.bootstrap_samples = 0;
  try {
    analyse_campaign(read_campaign_manifest((d / "m.csv").string()), {}, o, {});
    ADD_FAILURE() << "a campaign without any estimate passed";
  } catch (const ComputationError& e) {
    EXPECT_NE(std::string(e.what()).find("no group of the campaign could be estimated"),
              std::string::npos)
        << e.what();
  }
}

// One bad R cell (1e6 J/m^2) in one of the group's specimens: the group's note names that
// specimen, its manifest line, its file and the cell's line.
TEST(CampaignGroup, OneBadCellNamesTheSpecimenFileAndLine) {
  const fs::path d = scratch("bad_cell");
  const auto truth = table1_truth(read_property_table(table1));
  SyntheticCampaignOptions so;
  so.replicates = 6;
  const std::string m = write_synthetic_campaign(d.string(), {truth[0]}, so);
  // Spoil one R cell of the third specimen's file, as a typo would (the file as written).
  const fs::path f = d / "PVA_c0_s3.csv";
  std::ifstream in(f);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);)
    lines.push_back(l);
  in.close();
  auto cells = [](const std::string& l) {
    std::vector<std::string> c;
    std::size_t b = 0;
    for (std::size_t e; (e = l.find(',', b)) != std::string::npos; b = e + 1)
      c.push_back(l.substr(b, e - b));
    c.push_back(l.substr(b));
    return c;
  };
  std::size_t r_col = std::string::npos, spoiled_line = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].empty() || lines[i][0] == '#')
      continue;
    auto c = cells(lines[i]);
    if (r_col == std::string::npos) {
      r_col = std::find(c.begin(), c.end(), "R_J_m2") - c.begin();
      ASSERT_LT(r_col, c.size()) << lines[i];
      continue;
    }
    if (i < lines.size() / 2)
      continue;
    c[r_col] = "1000000";
    std::string joined;
    for (std::size_t k = 0; k < c.size(); ++k)
      joined += (k ? "," : "") + c[k];
    lines[i] = joined;
    spoiled_line = i + 1;
    break;
  }
  ASSERT_GT(spoiled_line, 0u);
  std::ofstream out(f);
  for (const auto& l : lines)
    out << l << "\n";
  out.close();
  CampaignOptions o;
  o.bootstrap_samples = 0;
  const auto manifest = read_campaign_manifest(m);
  std::vector<CampaignSpecimen> specimens;
  for (const auto& row : manifest.rows) {
    specimens.push_back(load_campaign_specimen(row, {}));
    assess_campaign_specimen(specimens.back(), o);
  }
  auto groups = make_campaign_groups(specimens);
  ASSERT_EQ(groups.size(), 1u);
  analyse_campaign_group(groups[0], specimens, o);
  ASSERT_FALSE(groups[0].estimate.ok); // as the fuzzer found: the group is gone
  std::string notes;
  for (const auto& n : groups[0].notes)
    notes += n + "\n";
  EXPECT_NE(notes.find("without specimen 's3'"), std::string::npos) << notes;
  EXPECT_NE(notes.find("PVA_c0_s3.csv:" + std::to_string(spoiled_line)), std::string::npos)
      << notes;
}

// Every file of a group carries one stem (issue 40 item 6: it was spelled in four places).
TEST(CampaignFiles, GroupFileStemIsTheMaterialAsAFileNamePartAndTheCycles) {
  EXPECT_EQ(analysis::group_file_stem("PVA control", 0), "PVA_control_c0");
  EXPECT_EQ(analysis::group_file_stem("PRF/wet", 12.5), "PRF_wet_c12.5");
  EXPECT_EQ(analysis::group_file_stem("EPI", 100000), "EPI_c1e+05") << "cycles as fmt prints them";
}

// The group's law corrected by simulation (CampaignOptions::correct_law; the app's is the beam,
// docs/design.md "The fit corrected by simulation"): the shift it finds moves the point estimate
// and every bootstrap sample alike, so the interval moves with it, and J1, J2 follow the shifted
// law; the Eq. 6 law's band does not move. A group of R(delta) tables has no record to simulate
// and is never corrected. Exact to round-off: every sample is shifted by the same amount, so a
// Student-t interval's centre moves by it and its half-width not at all.
TEST(CampaignCorrection, TheShiftMovesTheEstimateAndEveryBootstrapSample) {
  const std::string m = synthetic_manifest("correction");
  CampaignOptions o;
  o.bootstrap_samples = 50;
  const CampaignResult plain = analyse_campaign(read_campaign_manifest(m), {}, o, {"DF"});
  int calls = 0;
  CampaignOptions oc = o;
  // The shift alone: without the chain's accuracy, which widens a group of records' intervals
  // (CampaignAccuracy below).
  oc.chain_u_G_ss = oc.chain_u_J_tip = 0;
  oc.correct_law = [&calls](const std::vector<const CampaignSpecimen*>&,
                            const law::TrilinearParameters& law, double j_tip) {
    ++calls;
    LawCorrection c;
    c.converged = true;
    c.law = law;
    c.law.s1 += 10 * units::kPa;
    c.law.s2 -= 5 * units::kPa;
    c.j_tip = j_tip + 3;
    c.simulations = 2;
    return c;
  };
  // R(delta) tables: not corrected.
  CampaignGroup tables = make_campaign_groups(plain.specimens).front();
  analyse_campaign_group(tables, plain.specimens, oc);
  EXPECT_EQ(calls, 0);
  EXPECT_FALSE(tables.correction.applied);
  // The same specimens as if they came from records.
  auto specimens = plain.specimens;
  for (auto& s : specimens)
    s.record = std::make_shared<const TestRecord>();
  CampaignGroup g = make_campaign_groups(specimens).front();
  analyse_campaign_group(g, specimens, oc);
  const CampaignGroup& p = plain.groups.front();
  ASSERT_EQ(calls, 1);
  ASSERT_TRUE(g.correction.applied);
  EXPECT_NEAR(g.estimate.tri.s1 - p.estimate.tri.s1, 10 * units::kPa, 1e-6);
  EXPECT_NEAR(g.estimate.tri.s2 - p.estimate.tri.s2, -5 * units::kPa, 1e-6);
  EXPECT_NEAR(g.estimate.j_tip - p.estimate.j_tip, 3, 1e-9);
  EXPECT_NEAR(g.estimate.J1, g.estimate.tri.j1(), 1e-9);
  EXPECT_NEAR(g.estimate.J2, g.estimate.tri.j2(), 1e-9);
  EXPECT_EQ(g.estimate.G_ss, p.estimate.G_ss);
  const auto s1 = static_cast<std::size_t>(GroupQuantity::sigma1);
  EXPECT_NEAR(g.ci[s1].lo - p.ci[s1].lo, 10, 1e-6); // kPa
  EXPECT_NEAR(g.ci[s1].hi - p.ci[s1].hi, 10, 1e-6);
  EXPECT_EQ(g.law_lo, p.law_lo);
  EXPECT_EQ(g.law_hi, p.law_hi);
  EXPECT_TRUE(std::any_of(g.notes.begin(), g.notes.end(), [](const std::string& n) {
    return n.find("law corrected by simulation") != std::string::npos;
  }));
  // A correction that did not converge leaves the group as the chain gave it, with its notes.
  oc.correct_law = [](const std::vector<const CampaignSpecimen*>&, const law::TrilinearParameters&,
                      double) {
    LawCorrection c;
    c.notes = {"not corrected: no fixed point"};
    return c;
  };
  CampaignGroup n = make_campaign_groups(specimens).front();
  analyse_campaign_group(n, specimens, oc);
  EXPECT_FALSE(n.correction.applied);
  EXPECT_EQ(n.estimate.tri.s1, p.estimate.tri.s1);
  EXPECT_TRUE(std::any_of(n.notes.begin(), n.notes.end(), [](const std::string& x) {
    return x.find("no fixed point") != std::string::npos;
  }));
}

// The chain's accuracy on records (CampaignOptions::chain_u_G_ss, chain_u_J_tip) widens the
// intervals of a group of records in quadrature, by u_G G_ss, u_J J_tip and, for the law's
// stresses and energies, by the fraction u(G_B)/G_B of the bridging area; the other quantities,
// the point estimates, and groups of R(delta) tables are as before.
TEST(CampaignAccuracy, ChainAccuracyWidensTheIntervalsOfRecordsInQuadrature) {
  const std::string m = synthetic_manifest("accuracy");
  CampaignOptions none;
  none.bootstrap_samples = 200;
  none.chain_u_G_ss = none.chain_u_J_tip = 0;
  CampaignOptions with = none;
  with.chain_u_G_ss = 0.02;
  with.chain_u_J_tip = 0.03;
  const auto plain = analyse_campaign(read_campaign_manifest(m), {}, none, {"DF"});
  auto records = plain.specimens;
  for (auto& s : records)
    s.record = std::make_shared<const TestRecord>();
  for (std::size_t gi : {std::size_t{0}, plain.groups.size() - 1}) { // PVA c0 and DF c24
    const CampaignGroup& p = plain.groups[gi];
    CampaignGroup tables = make_campaign_groups(plain.specimens)[gi];
    CampaignGroup g = make_campaign_groups(records)[gi];
    ASSERT_EQ(g.material, p.material);
    ASSERT_EQ(g.cycles, p.cycles);
    analyse_campaign_group(tables, plain.specimens, with);
    analyse_campaign_group(g, records, with);
    const double G = g.estimate.G_ss, J = g.estimate.j_tip;
    ASSERT_GT(G - J, 0);
    const double f = std::hypot(0.02 * G, 0.03 * J) / (G - J), z = 1.959963984540054;
    for (std::size_t k = 0; k < n_group_quantities; ++k) {
      const auto q = static_cast<GroupQuantity>(k);
      const double v = quantity_value(g.estimate, q);
      EXPECT_TRUE(same(v, quantity_value(p.estimate, q))) << quantity_key(q);
      // R(delta) tables: the replicates alone.
      EXPECT_TRUE(same(tables.ci[k].lo, p.ci[k].lo) && same(tables.ci[k].hi, p.ci[k].hi))
          << quantity_key(q);
      double h = 0;
      if (q == GroupQuantity::G_ss)
        h = z * 0.02 * v;
      else if (q == GroupQuantity::J_tip)
        h = z * 0.03 * v;
      else if (q == GroupQuantity::sigma1 || q == GroupQuantity::sigma2 || q == GroupQuantity::J1 ||
               q == GroupQuantity::J2)
        h = z * f * v;
      if (!std::isfinite(v) || !std::isfinite(p.ci[k].hi)) // l_b, rho_b: no crack lengths here
        continue;
      EXPECT_NEAR(chain_accuracy_half_width(g, records, with, q), h, 1e-9 * (1 + v))
          << quantity_key(q);
      // Each side: the replicates' half-width and the chain's in quadrature (1e-9 relative: the
      // same bootstrap samples, only the sums' rounding differs).
      EXPECT_NEAR(g.ci[k].hi - v, std::hypot(p.ci[k].hi - v, h), 1e-9 * (1 + v)) << quantity_key(q);
      if (p.ci[k].lo > 0 && v - std::hypot(v - p.ci[k].lo, h) > 0)
        EXPECT_NEAR(v - g.ci[k].lo, std::hypot(v - p.ci[k].lo, h), 1e-9 * (1 + v))
            << quantity_key(q);
    }
    // The law's band: the same fraction of the law at each opening.
    ASSERT_EQ(g.law_hi.size(), p.law_hi.size());
    for (std::size_t i = 0; i < g.law_hi.size(); ++i)
      if (std::isfinite(p.law_hi[i]) && p.law_lo[i] > 0) {   // not held at 0: symmetric
        const double at = 0.5 * (p.law_hi[i] + p.law_lo[i]); // student t: symmetric about it
        EXPECT_NEAR(g.law_hi[i] - at, std::hypot(p.law_hi[i] - at, z * f * std::abs(at)),
                    1e-6 * (1 + std::abs(at)));
      }
    EXPECT_TRUE(std::any_of(g.notes.begin(), g.notes.end(), [](const std::string& n) {
      return n.find("the chain's accuracy on records") != std::string::npos;
    }));
  }
  // J_tip given (the rows' j_tip_J_m2) is not measured by the chain: no J_tip term, and G_B's
  // uncertainty is G_ss's alone.
  auto given = records;
  for (auto& s : given)
    s.row.j_tip = 200;
  CampaignGroup gg = make_campaign_groups(given).front();
  analyse_campaign_group(gg, given, with);
  ASSERT_TRUE(gg.estimate.ok && gg.estimate.has_law);
  EXPECT_EQ(gg.estimate.j_tip, 200);
  EXPECT_EQ(chain_accuracy_half_width(gg, given, with, GroupQuantity::J_tip), 0);
  const double G = gg.estimate.G_ss, s1 = quantity_value(gg.estimate, GroupQuantity::sigma1);
  EXPECT_NEAR(chain_accuracy_half_width(gg, given, with, GroupQuantity::sigma1),
              1.959963984540054 * 0.02 * G / (G - 200) * s1, 1e-9 * s1);
}

// A group whose averaged R(delta) falls at its end (the zone meets the specimens' far end) says
// so beside its G_ss: the plateau it is read from is cut short, and a campaign's groups are
// corrected by the beam, which does not hold that end (docs/verification.md, session 32). The
// synthetic PVA control group, each specimen's R lowered by 60 J/m^2 per mm over the last 15 %
// of its opening (72 J/m^2 over the last 1.2 mm of 8 mm, against a plateau band of 2 % of G_B,
// about 18 J/m^2); the same group untouched has no such note.
TEST(CampaignGroup, FallingEndOfTheGroupsCurveIsNoted) {
  const auto truth = table1_truth(read_property_table(table1));
  SyntheticCampaignOptions so;
  so.replicates = 4;
  for (const bool falling : {false, true}) {
    const std::string m = write_synthetic_campaign(
        scratch(falling ? "falling_end" : "flat_end").string(), {truth[0]}, so);
    CampaignOptions o;
    o.bootstrap_samples = 0;
    std::vector<CampaignSpecimen> specimens;
    for (const auto& row : read_campaign_manifest(m).rows) {
      specimens.push_back(load_campaign_specimen(row, {}));
      auto& c = specimens.back().curve;
      const double from = 0.85 * c.delta.back();
      if (falling)
        for (std::size_t i = 0; i < c.delta.size(); ++i)
          if (c.delta[i] > from)
            c.R[i] -= 60 * (c.delta[i] - from) / units::mm;
      assess_campaign_specimen(specimens.back(), o);
    }
    auto groups = make_campaign_groups(specimens);
    ASSERT_EQ(groups.size(), 1u);
    analyse_campaign_group(groups[0], specimens, o);
    ASSERT_TRUE(groups[0].estimate.ok) << groups[0].estimate.failure;
    EXPECT_EQ(groups[0].estimate.steady.end_effect, falling);
    std::string notes;
    for (const auto& n : groups[0].notes)
      notes += n + "\n";
    EXPECT_EQ(notes.find("far end") != std::string::npos, falling) << notes;
  }
}
