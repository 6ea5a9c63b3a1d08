// Degradation statistics, ranking and row consistency against the seed's Table 1 (seed section
// 3.3; docs/design.md section 1 "Degradation and ranking").
#include "fiberbridge/analysis/degradation.h"
#include "fiberbridge/core/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>

using namespace fiberbridge;
using namespace fiberbridge::analysis;

namespace {

const std::string table1 = std::string(FIBERBRIDGE_DATA_DIR) + "/reference/seed_table1.csv";

const DegradationRow& row_of(const std::vector<DegradationRow>& rows, const std::string& m,
                             const std::string& p) {
  for (const auto& r : rows)
    if (r.material == m && r.property == p)
      return r;
  throw std::runtime_error("no row " + m + " " + p);
}

/// Expects parse_property_table(text) to throw InputError whose message contains every piece.
void expect_input_error(const std::string& text, const std::vector<std::string>& pieces) {
  try {
    parse_property_table(text, "bad.csv");
    ADD_FAILURE() << "no InputError for:\n" << text;
  } catch (const InputError& e) {
    for (const auto& p : pieces)
      EXPECT_NE(std::string(e.what()).find(p), std::string::npos)
          << "message '" << e.what() << "' lacks '" << p << "'";
  }
}

} // namespace

TEST(Regression, KnownAnswerPvaSigma1) {
  // Table 1, PVA sigma1 at 0/8/16/24 cycles: 661, 491, 302, 257 kPa. By hand: mean x = 12,
  // Sxx = 320, mean y = 427.75, Sxy = -12*661 - 4*491 + 4*302 + 12*257 = -5604, so slope =
  // -17.5125, intercept = 427.75 + 12*17.5125 = 637.9; Syy = 103374.75, R^2 = 5604^2/(320 Syy),
  // SSR = Syy - Sxy^2/Sxx = 5234.7, SE = sqrt(SSR/2/320).
  const auto fit = linear_regression({0, 8, 16, 24}, {661, 491, 302, 257});
  // Sums of a few exact binary integers: only the final divisions round (1e-12 is generous).
  EXPECT_NEAR(fit.slope, -17.5125, 1e-12);
  EXPECT_NEAR(fit.intercept, 637.9, 1e-11);
  EXPECT_NEAR(fit.r2, 5604.0 * 5604.0 / (320 * 103374.75), 1e-14);
  EXPECT_NEAR(fit.slope_std_error, std::sqrt(5234.7 / 2 / 320), 1e-12);
  EXPECT_EQ(fit.n, 4);
}

TEST(Regression, ExactLineAndDegenerateInput) {
  const auto exact = linear_regression({1, 2, 3, 5}, {3, 5, 7, 11}); // y = 1 + 2x
  EXPECT_NEAR(exact.slope, 2, 1e-14);
  EXPECT_NEAR(exact.intercept, 1, 1e-14);
  EXPECT_NEAR(exact.r2, 1, 1e-14);
  EXPECT_NEAR(exact.slope_std_error, 0, 1e-14);
  const auto two = linear_regression({0, 1}, {1, 3});
  EXPECT_NEAR(two.slope, 2, 1e-14);
  EXPECT_TRUE(std::isnan(two.slope_std_error)); // no residual degrees of freedom
  const auto flat = linear_regression({0, 8, 16}, {5, 5, 5});
  EXPECT_EQ(flat.slope, 0);
  EXPECT_EQ(flat.r2, 0);
  EXPECT_THROW(linear_regression({0, 1, 2}, {1, 2}), InputError);
  EXPECT_THROW(linear_regression({3, 3, 3}, {1, 2, 3}), InputError);
  EXPECT_THROW(linear_regression({0}, {1}), InputError);
  EXPECT_THROW(linear_regression({0, 1, NAN}, {1, 2, 3}), InputError);
}

TEST(PropertyTable, ReadsSeedTable1) {
  const auto t = read_property_table(table1);
  EXPECT_EQ(t.cycles, (std::vector<double>{0, 8, 16, 24}));
  EXPECT_EQ(t.rows.size(), 30u); // 5 materials x (sigma1, J1, sigma2, J2, lb, rho_b)
  const PropertyRow* s1 = t.find("PVA", "sigma1");
  ASSERT_NE(s1, nullptr);
  EXPECT_EQ(s1->line, 8u); // 7 lines of comments and header before it
  EXPECT_EQ(s1->values, (std::vector<double>{661, 491, 302, 257}));
  EXPECT_TRUE(s1->has_printed);
  EXPECT_DOUBLE_EQ(s1->printed_slope, -17.5);
  EXPECT_DOUBLE_EQ(s1->printed_slope_half_unit, 0.05);
  EXPECT_DOUBLE_EQ(s1->printed_r2_half_unit, 0.005);
  const PropertyRow* lb = t.find("PVA", "lb");
  ASSERT_NE(lb, nullptr);
  EXPECT_FALSE(lb->has_printed);
  EXPECT_DOUBLE_EQ(lb->half_units[0], 0.05);
  const PropertyRow* rho = t.find("DF", "rho_b");
  ASSERT_NE(rho, nullptr);
  EXPECT_EQ(rho->range_text, "2-6,0.3-1,4-10,8-24");
  EXPECT_EQ(rho->ranges[1], std::make_pair(0.3, 1.0));
  EXPECT_TRUE(std::isnan(rho->values[0]));
  EXPECT_EQ(t.find("PF", "none"), nullptr);
}

TEST(PropertyTable, BadInputNamesFileLineAndExpectation) {
  const std::string head = "material,property,c0,c8,c16,slope,r2\n";
  expect_input_error(head + "PVA,sigma1,661,49x1,302,-1,0.9\n",
                     {"bad.csv:2", "c8", "49x1", "expected a number"});
  expect_input_error(head + "PVA,rho_b,40-,24-66,17-49,,\n", {"bad.csv:2", "c0", "40-"});
  expect_input_error(head + "PVA,rho_b,111-40,24-66,17-49,,\n", {"bad.csv:2", "low <= high"});
  expect_input_error(head + "PVA,rho_b,40-111,24,17-49,,\n", {"bad.csv:2", "mixes"});
  expect_input_error(head + "PVA,sigma1,661,491,302,-1,\n", {"bad.csv:2", "both or neither"});
  expect_input_error(head + "PVA,sigma1,661,491,302,-1,1.3\n", {"bad.csv:2", "r2", "[0, 1]"});
  expect_input_error(head + "PVA,sigma1,1,2,3,,\n# note\nPVA,sigma1,4,5,6,,\n",
                     {"bad.csv:4", "second row", "line 2"});
  expect_input_error("material,property,c0,c8,slope,r2\nPVA,sigma1,1,2,,\n",
                     {"bad.csv", "2 cycle columns", "at least 3"});
  expect_input_error("material,property,c0,c8,C16\nPVA,sigma1,1,2,3\n",
                     {"bad.csv", "unknown column 'C16'"});
  expect_input_error("property,c0,c8,c16\nsigma1,1,2,3\n", {"missing column 'material'"});
  expect_input_error("material,property,c0,c8,c08\nA,s,1,2,3\n", {"same cycle count 8"});
  expect_input_error("material,property,c0,c8,c16,slope\nA,s,1,2,3,1\n", {"without 'r2'"});
  // A too-short row is caught by the CSV reader, with its line.
  expect_input_error(head + "PVA,sigma1,661,491\n", {"bad.csv:2", "expected 7"});
  EXPECT_THROW(read_property_table("/nonexistent/table.csv"), InputError);
}

TEST(Degradation, EveryPrintedSlopeAndR2IsReproducedExceptTheDf16Misprints) {
  // Acceptance (analyse_degradation): the recomputed value must round or truncate to the printed
  // digits (slope printed to 0.1 or 0.01 /cycle, R^2 to 0.01), widened by the first-order effect
  // of the +-0.5 rounding of the printed inputs (<= 0.05/cycle on a slope over 0..24 cycles).
  // Checked by hand: 18 of the 20 rows reproduce; DF J1 (6.08 vs. 2.2, R^2 0.16 vs. 0.55) and
  // DF sigma2 (+0.83 vs. -1.0, R^2 0.01 vs. 0.68) do not, because of their 16-cycle cells.
  const auto rows = analyse_degradation(read_property_table(table1));
  EXPECT_EQ(rows.size(), 25u); // 20 trilinear rows + 5 l_b rows; rho_b ranges are skipped
  std::set<std::string> mismatched;
  int with_printed = 0;
  for (const auto& r : rows) {
    if (!r.has_printed)
      continue;
    ++with_printed;
    if (!r.matches_printed)
      mismatched.insert(r.material + " " + r.property);
  }
  EXPECT_EQ(with_printed, 20);
  EXPECT_EQ(mismatched, (std::set<std::string>{"DF J1", "DF sigma2"}));

  // The anchor of docs/design.md section 1: PVA sigma1 -17.5/cycle, R^2 0.949 (printed 0.94, i.e.
  // truncated).
  const auto& pva = row_of(rows, "PVA", "sigma1");
  EXPECT_NEAR(pva.fit.slope, -17.5125, 1e-12);
  EXPECT_NEAR(pva.fit.r2, 0.94936, 5e-6); // hand value 31404816/33079920 to 5 digits
  EXPECT_GT(pva.fit.r2, 0.945);           // would print 0.95 if rounded: the table truncated
}

TEST(Degradation, Df16CorrectedCellsReproduceThePrintedDfStatistics) {
  // Diagnosis of the two mismatches: the printed J2 = 26 at 16 cycles implies sigma2 = 2 J2/dc
  // = 14.9 kPa (not 166), and then J1 = (69*1.0 - 14.9*0.1)/2 = 33.8 J/m^2 (not 347). With
  // those two cells the printed DF J1 (2.2, 0.55) and sigma2 (-1.0, 0.68) statistics reproduce
  // under the same acceptance rule. (The decimal-point reading 34.7 and 16.6 also reproduces.)
  auto t = read_property_table(table1);
  auto fix = [&](const std::string& p, double v, double half_unit) {
    for (auto& r : t.rows)
      if (r.material == "DF" && r.property == p) {
        r.values[2] = v;
        r.half_units[2] = half_unit;
      }
  };
  const double s2 = 2 * 26 / 3.5;
  fix("sigma2", s2, 0.5 * 2 / 3.5); // propagated from J2's own rounding (+-0.5 J/m^2)
  fix("J1", 0.5 * (69 - 0.1 * s2), 0.5);
  const auto rows = analyse_degradation(t);
  for (const auto& r : rows)
    if (r.has_printed)
      EXPECT_TRUE(r.matches_printed) << r.material << " " << r.property;
  EXPECT_NEAR(row_of(rows, "DF", "J1").fit.slope, 2.159, 1e-3);
  EXPECT_NEAR(row_of(rows, "DF", "sigma2").fit.slope, -1.064, 1e-3);
}

TEST(Degradation, SignificantRowsAreThePapersBold) {
  // Bold in Table 1: all four PVA properties; sigma2 and J2 of EPI and PRF; nothing for PF, DF.
  const auto rows = analyse_degradation(read_property_table(table1));
  std::set<std::string> significant;
  for (const auto& r : rows)
    if (r.significant)
      significant.insert(r.material + " " + r.property);
  EXPECT_EQ(significant, (std::set<std::string>{"PVA sigma1", "PVA J1", "PVA sigma2", "PVA J2",
                                                "EPI sigma2", "EPI J2", "PRF sigma2", "PRF J2"}));
  // DF J2 is the closest miss: slope -1.76/cycle but R^2 0.690 < 0.8.
  EXPECT_LT(row_of(rows, "DF", "J2").fit.r2, 0.8);
  EXPECT_LT(row_of(rows, "DF", "J2").fit.slope, 0);
}

TEST(Ranking, AdhesivesRankPfEpiPrfPvaAndSolidWoodTiesPf) {
  const auto ranks = rank_materials(analyse_degradation(read_property_table(table1)));
  ASSERT_EQ(ranks.size(), 5u);
  std::map<std::string, const MaterialRank*> by;
  for (const auto& r : ranks)
    by[r.material] = &r;
  // The seed's conclusion: PF most durable, then EPI, PRF, PVA (strictly).
  EXPECT_LT(by["PF"]->rank, by["EPI"]->rank);
  EXPECT_LT(by["EPI"]->rank, by["PRF"]->rank);
  EXPECT_LT(by["PRF"]->rank, by["PVA"]->rank);
  // DF has no significant degradation either: score 0 like PF, so they share rank 1 and the
  // next rank is 3. Order among equals: table order (PF is listed before DF).
  EXPECT_EQ(by["PF"]->rank, 1);
  EXPECT_EQ(by["DF"]->rank, 1);
  EXPECT_EQ(by["EPI"]->rank, 3);
  EXPECT_EQ(by["PVA"]->rank, 5);
  EXPECT_EQ(ranks[0].material, "PF");
  EXPECT_EQ(ranks[1].material, "DF");
  EXPECT_EQ(by["PF"]->degradation_score, 0);
  EXPECT_TRUE(by["PF"]->significant_properties.empty());
  EXPECT_EQ(by["PVA"]->significant_properties.size(), 4u);
  // Scores: sums of slope/intercept of the bold rows, recomputed by hand from the table, e.g.
  // EPI sigma2: slope -2.575, intercept 152 + 12*2.575 = 182.9 -> -0.014079; J2: -4.2125 /
  // (250.75 + 12*4.2125 = 301.3) -> -0.013981. Round-off of a 4-point fit: 1e-12.
  EXPECT_NEAR(by["EPI"]->degradation_score, -2.575 / 182.9 - 4.2125 / 301.3, 1e-12);
  EXPECT_NEAR(by["PRF"]->degradation_score, -4.9 / 193.8 - 8.075 / 319.4, 1e-12);
}

TEST(Ranking, TiesShareARankAndBadInterceptIsAnError) {
  auto mk = [](const std::string& m, const std::string& p, double slope, double intercept,
               bool significant) {
    DegradationRow r;
    r.material = m;
    r.property = p;
    r.fit.slope = slope;
    r.fit.intercept = intercept;
    r.normalized_rate = intercept > 0 ? slope / intercept : NAN;
    r.significant = significant;
    return r;
  };
  const auto ranks = rank_materials({mk("A", "sigma1", -1, 100, true), mk("B", "J2", -2, 200, true),
                                     mk("C", "sigma2", -1, 50, true),
                                     mk("C", "lb", -1, 5, true), // l_b does not rank
                                     mk("D", "J1", -5, 100, false)});
  ASSERT_EQ(ranks.size(), 4u);
  EXPECT_EQ(ranks[0].material, "D");
  EXPECT_EQ(ranks[0].rank, 1);
  EXPECT_EQ(ranks[1].material, "A");
  EXPECT_EQ(ranks[2].material, "B");
  EXPECT_EQ(ranks[1].rank, 2);
  EXPECT_EQ(ranks[2].rank, 2); // -0.01 both
  EXPECT_EQ(ranks[3].material, "C");
  EXPECT_EQ(ranks[3].rank, 4);
  EXPECT_DOUBLE_EQ(ranks[3].degradation_score, -0.02);
  EXPECT_THROW(rank_materials({mk("E", "J1", -1, -3, true)}), InputError);
}

TEST(Consistency, ExactlyPva24AndDf16AreFlagged) {
  // Hand check of all 20 rows (J1 = (s1*1.0 - s2*0.1)/2, J2 = s2*dc/2, kPa*mm = J/m^2):
  //  - J1 agrees within the printing rounding (0.5 + (1.0*0.5 + 0.1*0.5)/2 = 0.775 J/m^2) in 18
  //    rows (largest miss 0.5); PVA 24 cycles: 123 printed vs. (257 - 14.1)/2 = 121.45 (1.55,
  //    twice the rounding bound; the printed PVA J1 slope -8.7 fits 121.45 better than 123:
  //    -8.666 vs. -8.600); DF 16: 347 vs. (69 - 16.6)/2 = 26.2.
  //  - J2: 19 rows sit 4-6 % below s2 dc/2 (printed/expected 0.938-0.960: 2 J2/s2 = 5.70 mm for
  //    PVA, 3.30 mm for the rest); DF 16: 26 vs. 166*3.5/2 = 290.5 (-91 %).
  const auto issues =
      check_row_consistency(read_property_table(table1), 0.1, 1.0, &seed_delta_c_mm);
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].material, "PVA");
  EXPECT_EQ(issues[0].cycles, 24);
  EXPECT_FALSE(issues[0].j1_consistent);
  EXPECT_TRUE(issues[0].j2_consistent);
  EXPECT_NEAR(issues[0].j1_expected, 121.45, 1e-9);
  EXPECT_NE(issues[0].message.find("J1 printed 123"), std::string::npos) << issues[0].message;
  EXPECT_EQ(issues[1].material, "DF");
  EXPECT_EQ(issues[1].cycles, 16);
  EXPECT_FALSE(issues[1].j1_consistent);
  EXPECT_FALSE(issues[1].j2_consistent);
  EXPECT_NEAR(issues[1].j1_expected, 26.2, 1e-9);
  EXPECT_NEAR(issues[1].j2_expected, 290.5, 1e-9);
  EXPECT_NE(issues[1].message.find("implies sigma2 = 14.857"), std::string::npos)
      << issues[1].message;
  // 347 is 19 % from the expected J2 290.5: outside the J2 band, so not called a swap.
  EXPECT_EQ(issues[1].message.find("swapped"), std::string::npos) << issues[1].message;
}

TEST(Consistency, SystematicJ2OffsetNeedsTheStatedAllowance) {
  // The offset is systematic, not noise: with a 3 % J2 allowance (below the smallest LVL offset,
  // PVA 24: -4.7 %, plus its 0.5 % rounding) every one of the 16 LVL rows is flagged. Only DF
  // rows with J2 of a few J/m^2, where printing to integers is itself 3-26 %, can pass.
  ConsistencyTolerance strict;
  strict.j2_relative = 0.03;
  const auto t = read_property_table(table1);
  std::set<std::string> flagged;
  for (const auto& i : check_row_consistency(t, 0.1, 1.0, &seed_delta_c_mm, strict))
    flagged.insert(i.material + std::to_string(int(i.cycles)));
  for (const char* m : {"PVA", "EPI", "PRF", "PF"})
    for (int c : {0, 8, 16, 24})
      EXPECT_EQ(flagged.count(m + std::to_string(c)), 1u) << m << " " << c;
  // With a generous J1 allowance only the J1 misprints change: DF 16 stays (J2 too).
  ConsistencyTolerance loose_j1;
  loose_j1.j1_relative = 0.05;
  const auto issues = check_row_consistency(t, 0.1, 1.0, &seed_delta_c_mm, loose_j1);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].material, "DF");
}

TEST(Consistency, SwappedRowIsDiagnosedAndConsistentTableIsClean) {
  // s1 = 500, s2 = 200, dc = 3.5: J1 = (500 - 20)/2 = 240, J2 = 350.
  const std::string head = "material,property,c0,c8,c16\n";
  const std::string good = head + "X,sigma1,500,500,500\nX,sigma2,200,200,200\n"
                                  "X,J1,240,240,240\nX,J2,350,350,350\n";
  EXPECT_TRUE(
      check_row_consistency(parse_property_table(good, "good.csv"), 0.1, 1.0, &seed_delta_c_mm)
          .empty());
  const std::string swapped = head + "X,sigma1,500,500,500\nX,sigma2,200,200,200\n"
                                     "X,J1,240,350,240\nX,J2,350,240,350\n";
  const auto issues = check_row_consistency(parse_property_table(swapped, "swapped.csv"), 0.1, 1.0,
                                            &seed_delta_c_mm);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].cycles, 8);
  EXPECT_NE(issues[0].message.find("swapped"), std::string::npos) << issues[0].message;
  EXPECT_THROW(check_row_consistency(parse_property_table(good, "g"), 1.0, 0.1, &seed_delta_c_mm),
               InputError);
}

TEST(Consistency, SeedDeltaC) {
  EXPECT_EQ(seed_delta_c_mm("PVA"), 6.0);
  EXPECT_EQ(seed_delta_c_mm("EPI"), 3.5);
  EXPECT_EQ(seed_delta_c_mm("DF"), 3.5);
}
