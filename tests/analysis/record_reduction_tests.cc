// R(a) from raw records (record_reduction.h): the shared real records against their author's
// own G_I column, the energy method against MBT, and the averaging of replicates.
#include "../common/elastica.h"
#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/analysis/record_reduction.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

using namespace fiberbridge;
using namespace fiberbridge::analysis;
using units::mm;

namespace {

const char* const shared_records[] = {"DCB-01", "DCB-02", "DCB-03", "DCB-05"};

std::string record_path(const std::string& name) {
  return std::string(FIBERBRIDGE_DATA_DIR) + "/dcb_records/" + name + "_Toughness.csv";
}

RecordReadOptions shared_columns() {
  RecordReadOptions o;
  o.columns = RecordColumnMap::parse(
      "time_s: Time, opening_mm: Disp, load_N: Force, a_mm: CrackExt", "test");
  return o;
}

/// The geometry data/dcb_records/README.md states: width 25 mm, arms 2.7 mm.
specimen::Specimen shared_specimen() {
  auto s = specimen::Specimen::unknown();
  s.width = 25 * mm;
  s.height = 2 * 2.7 * mm; // both arms
  s.length = 123 * mm;
  return s;
}

/// The author's G_I (kJ/m^2 in the file) at each source line, in J/m^2.
std::map<std::size_t, double> author_G(const std::string& path) {
  const CsvTable t = CsvTable::read(path);
  const auto G = t.numeric("G_I");
  std::map<std::size_t, double> by_line;
  for (std::size_t r = 0; r < t.n_rows(); ++r)
    by_line[t.line_of_row(r)] = G[r] * 1e3;
  return by_line;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

} // namespace

// The author's G_I column is MBT without the large-displacement correction: the Delta it
// implies, 3 P delta / (2 B G_I) - a, is constant along each record to +-0.4 mm (5-95 %), and
// our MBT without F reproduces G_I at every crack reading to within a few per cent; with F and N
// it is 0.3-0.5 % higher (F/N = 0.99-1 at the openings of a third of the crack length reached
// here, and N shortens |Delta| a little).
// Measured medians of R_MBT(no F)/G_I over the readings with G_I > 100 J/m^2: DCB-01 0.989,
// DCB-02 0.984, DCB-03 0.977, DCB-05 0.977 (docs/verification.md, "Test records"). The residual
// is the author's |Delta|, 0.9-1.7 mm shorter than ours (fitted, we think, over every row rather
// than the rows with a fresh crack reading; the script is not published), which at a = 35-105 mm
// is 1-2.5 %; the tolerance of 3 % on the median and 5 % on the 5-95 % range covers that and no
// more.
TEST(RecordReduction, MbtReproducesTheAuthorsGI) {
  for (const char* name : shared_records) {
    const auto rec = read_test_records(record_path(name), shared_columns()).at(0);
    const auto G = author_G(record_path(name));
    double median_with_F = 0;
    for (bool F : {true, false}) {
      ReduceOptions o;
      o.large_displacement_correction = F;
      const auto r = reduce_record(rec, shared_specimen(), o);
      std::vector<double> ratio;
      for (std::size_t i = 0; i < r.a.size(); ++i) {
        const double g = G.at(r.line[i]);
        if (g > 100) // below 100 J/m^2 the ratio of two small numbers is noise (first readings)
          ratio.push_back(r.R_MBT[i] / g);
      }
      ASSERT_GT(ratio.size(), 100u) << name;
      std::sort(ratio.begin(), ratio.end());
      const double med = ratio[ratio.size() / 2];
      const double p5 = ratio[ratio.size() / 20], p95 = ratio[19 * ratio.size() / 20];
      std::printf("%s MBT %s F / author's G_I: median %.4f, 5-95 %% %.4f-%.4f, |Delta| %.2f mm\n",
                  name, F ? "with" : "without", med, p5, p95, r.mbt_delta / mm);
      if (F) {
        median_with_F = med;
        continue;
      }
      EXPECT_NEAR(med, 1.0, 0.03) << name;
      EXPECT_GT(p5, 0.95) << name;
      EXPECT_LT(p95, 1.05) << name;
      // With F and N together the correction at these openings (delta/a <= 0.35) is small: F/N
      // is 1 - 0.043 (delta/a)^2 - 0.375 delta l1/a^2 to second order, under 1 %, and N also
      // enters the compliance fit (|Delta| 0.1-0.6 mm shorter). Measured: +0.3 to +0.5 % on
      // the median. F alone (N = 1 with hinges, the reduction's former error, see
      // ElasticaDcbIsReducedExactlyWithFOverN) lowered it by 1.6-2.9 %: 1.5 % separates them.
      EXPECT_NEAR(median_with_F, med, 0.015) << name << ": F/N should change MBT by < 1.5 % here";
    }
  }
}

// The large-displacement corrections against an exact solution: a DCB whose arms are
// inextensible elasticas (loaded on their mid-plane, l1 -> 0, no end blocks), growing at a
// constant R = 1000 J/m^2 from a = 40 to 120 mm, so that the opening reaches 0.45 of the crack
// length (the shared records reach 0.35). G of the elastica is exact (J at the clamped root), so
// every beam-theory reduction with F and N should return R: the compliance is exactly
// (2 a^3/(3 EI)) N to O((delta/a)^4), so the MBT, CC and MCC fits of C/N are exact
// (|Delta| = 0, n = 3), and F/N is the elastica's G over 3 P delta/(2 B a) to O((delta/a)^4).
// Measured with a stand-alone quadrature of the same elastica: F/N is off the exact ratio by
// -0.003 % at delta/a = 0.32, -0.04 % at 0.5, -0.08 % at 0.6, and the compliance by 0.01-0.06 %
// over the same range, so 0.3 % bounds the reductions with room for the fits. F alone (N = 1
// with hinges, as the reduction once did) is 4 % low at delta/a = 0.45; no correction at all is
// 1 % high there (F/N = 0.99): both fail, and the uncorrected one is checked to be out too.
TEST(RecordReduction, ElasticaDcbIsReducedExactlyWithFOverN) {
  const double B = 25 * mm, h = 2.7 * mm, E = 19.3e9, EI = E * B * h * h * h / 12, R = 1000;
  const double a0 = 40 * mm;
  TestRecord rec;
  rec.name = "elastica";
  rec.source = "elastica DCB (test)";
  auto add = [&](const exact::ArmElastica& e, double a) {
    rec.time.push_back(static_cast<double>(rec.load.size()));
    rec.load.push_back(e.p * EI / (a * a));
    rec.opening.push_back(2 * e.deflection * a);
    rec.crack_length.push_back(a);
    rec.line.push_back(rec.load.size() + 1);
  };
  const exact::ArmElastica initiation = exact::elastica_at_G(R, EI, a0, B);
  double tip_rotation_c = 0;
  { // the tip rotation at initiation (bisection on p, which rises with the rotation)
    double lo = 0, hi = 1.3;
    for (int it = 0; it < 100; ++it) {
      const double mid = 0.5 * (lo + hi);
      (exact::arm_elastica(mid).p < initiation.p ? lo : hi) = mid;
    }
    tip_rotation_c = 0.5 * (lo + hi);
  }
  for (int k = 1; k <= 20; ++k) // loading to initiation at a0
    add(exact::arm_elastica(tip_rotation_c * k / 20), a0);
  for (double a = a0 + 0.25 * mm; a <= 120 * mm + 1e-9; a += 0.25 * mm)
    add(exact::elastica_at_G(R, EI, a, B), a);

  auto sp = specimen::Specimen::unknown();
  sp.width = B;
  sp.height = 2 * h;             // both arms
  sp.pin_to_arm_midplane = 1e-9; // the elastica is loaded on its mid-plane: l1 -> 0
  double worst_corrected = 0, worst_plain = 0, largest = 0;
  for (bool corrected : {true, false}) {
    ReduceOptions o;
    o.large_displacement_correction = corrected;
    const auto r = reduce_record(rec, sp, o);
    ASSERT_GT(r.a.size(), 300u);
    for (std::size_t i = 0; i < r.a.size(); ++i) {
      const double worst = std::max({std::abs(r.R_MBT[i] / R - 1), std::abs(r.R_CC[i] / R - 1),
                                     std::abs(r.R_MCC[i] / R - 1)});
      (corrected ? worst_corrected : worst_plain) =
          std::max(corrected ? worst_corrected : worst_plain, worst);
    }
    largest = r.max_opening_over_a;
    if (corrected) {
      // Not a check, a figure for docs/verification.md: the direct energy assumes linear
      // unloading (U = P delta / 2, seed Eq. 2), which stiffening arms break at large openings.
      std::vector<double> energy_error;
      for (std::size_t i = 0; i < r.a.size(); ++i)
        if (r.a[i] > a0 + r.window) // two-sided windows only
          energy_error.push_back(r.R_energy[i] / R - 1);
      std::printf("elastica DCB: direct energy R / R_exact - 1 from %.4f (delta/a %.2f) to %.4f "
                  "(delta/a %.2f)\n",
                  energy_error.front(),
                  r.opening[r.a.size() - energy_error.size()] /
                      r.a[r.a.size() - energy_error.size()],
                  energy_error.back(), r.opening.back() / r.a.back());
      EXPECT_LT(r.mbt_delta, 0.2 * mm) << "a clamped elastica has no root rotation";
      EXPECT_NEAR(r.cc_n, 3.0, 0.02);
    }
  }
  std::printf("elastica DCB to delta/a = %.3f: worst |R/R_exact - 1| of MBT, CC, MCC %.4f with F "
              "and N, %.4f without\n",
              largest, worst_corrected, worst_plain);
  EXPECT_GT(largest, 0.4);
  EXPECT_LT(worst_corrected, 0.003);
  EXPECT_GT(worst_plain, 0.006) << "the test must see the large displacements";
}

// The direct energy needs no beam theory; where the arms are still nearly linear (opening below
// a fifth of the crack length) and the window is two-sided, it should agree with MBT. Measured
// medians of R_energy/R_MBT there with the automatic 10.8 mm window: DCB-01 0.937, DCB-02 0.936,
// DCB-05 0.933 (MBT with F and N); with the windows chosen from the data (median 5.7-8.3 mm
// here): 1.029, 0.934, 0.928. The energy slope's own band is +-5-10 % (2 s.e.) at these
// readings, so the 10 % tolerance is that band, not more. DCB-03 does not agree: 0.79 (0.81). Over
// da = 5-12 mm its energy R stays at 490-530 J/m^2 while MBT rises from 560 to 710, then the energy
// R catches up: the crack readings run ahead of the energy dissipated there (a tracked tip ahead of
// the compliance crack), which the energy method divides by and MBT, which takes its crack from the
// compliance fit, does not. That is a finding about the record, kept visible here rather than
// tolerated away (docs/verification.md, "Test records").
TEST(RecordReduction, EnergyAgreesWithMbtWhereArmsAreLinear) {
  for (const char* name : shared_records) {
    const auto rec = read_test_records(record_path(name), shared_columns()).at(0);
    const auto r = reduce_record(rec, shared_specimen());
    // The automatic windows are chosen from the data between 5 reading spacings and the larger
    // of 10 spacings and 4 arm thicknesses (10.8 mm here); these records' correlated reading
    // errors keep the median well above the narrowest (about 1.3 mm).
    EXPECT_LE(r.window, 4 * 2.7 * mm * (1 + 1e-12)) << name << ": above the widest window";
    EXPECT_GE(r.window, 4 * mm) << name << ": the windows follow the reading errors";
    std::vector<double> ratio;
    for (std::size_t i = 0; i < r.a.size(); ++i)
      if (r.opening[i] / r.a[i] < 0.2 && r.da[i] >= r.window / 2)
        ratio.push_back(r.R_energy[i] / r.R_MBT[i]);
    ASSERT_GT(ratio.size(), 10u) << name;
    const double med = median(ratio);
    std::printf("%s: R_energy/R_MBT where opening/a < 0.2: median %.3f over %zu readings\n", name,
                med, ratio.size());
    if (std::string(name) == "DCB-03")
      EXPECT_LT(med, 0.9) << "DCB-03 now agrees: update docs/verification.md";
    else
      EXPECT_NEAR(med, 1.0, 0.10) << name;
    // The band brackets the estimate and is finite wherever the window holds 3 readings.
    for (std::size_t i = 0; i < r.a.size(); ++i) {
      ASSERT_TRUE(std::isfinite(r.R_energy[i])) << name << " line " << r.line[i];
      EXPECT_LE(r.R_energy_lo[i], r.R_energy[i]);
      EXPECT_GE(r.R_energy_hi[i], r.R_energy[i]);
    }
  }
}

TEST(RecordReduction, ReplicatesOnACommonExtensionGrid) {
  std::vector<ReducedRecord> reduced;
  double shortest = INFINITY;
  for (const char* name : shared_records) {
    reduced.push_back(reduce_record(read_test_records(record_path(name), shared_columns()).at(0),
                                    shared_specimen()));
    shortest = std::min(shortest, reduced.back().da.back());
  }
  const auto m = average_reduced(reduced, 1.0 / 3.0, 51);
  EXPECT_EQ(m.n_records, 4);
  ASSERT_EQ(m.da.size(), 51u);
  EXPECT_DOUBLE_EQ(m.da.back(), shortest);
  // The mean of the four at the grid's end is their interpolated mean, and they do scatter.
  double sum = 0;
  for (const auto& r : reduced) {
    std::vector<double> at = {shortest};
    sum += resample_linear(r.da, r.R_MBT, at)[0];
  }
  EXPECT_NEAR(m.R_MBT.back(), sum / 4, 1e-9 * sum);
  EXPECT_GT(m.R_MBT_std[25], 0.0);
  EXPECT_GT(m.mbt.plateau, m.mbt.initiation);
}

TEST(RecordReduction, GeometryAndInitialCrackErrors) {
  const auto rec = read_test_records(record_path("DCB-01"), shared_columns()).at(0);
  specimen::Specimen s = shared_specimen();
  s.width = NAN;
  EXPECT_THROW(reduce_record(rec, s), InputError);
  s = shared_specimen();
  s.initial_crack = 40 * mm; // the first reading is 37.64 mm
  try {
    reduce_record(rec, s);
    FAIL() << "a0 beyond the first reading accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("beyond the first crack reading 37.64 mm"),
              std::string::npos)
        << e.what();
  }
}

// Issue 12 (part 2 follow-up): on DCB-01 beyond a = 62 mm the direct energy swings by
// +-150-200 J/m^2 about MBT with periods of 10-15 mm, which the old +-2 s.e. band did not hold.
// The band now includes the scatter of neighbouring estimates (record_reduction.h); it should
// be as wide as those swings: MBT inside it at most readings there.
TEST(RecordReduction, EnergyBandHoldsTheSwingsOnDcb01) {
  const auto r = reduce_record(read_test_records(record_path("DCB-01"), shared_columns()).at(0),
                               shared_specimen());
  std::size_t n = 0, inside = 0;
  double swing2 = 0, half = 0;
  for (std::size_t i = 0; i < r.a.size(); ++i) {
    if (r.a[i] < 62 * mm || r.a.back() - r.a[i] < r.window / 2)
      continue;
    ++n;
    inside += r.R_energy_lo[i] <= r.R_MBT[i] && r.R_MBT[i] <= r.R_energy_hi[i];
    swing2 += std::pow(r.R_energy[i] - r.R_MBT[i], 2);
    half += 0.5 * (r.R_energy_hi[i] - r.R_energy_lo[i]);
  }
  ASSERT_GT(n, 50u);
  std::printf("DCB-01, a >= 62 mm: RMS of R_energy - R_MBT %.0f J/m^2, mean band half-width %.0f "
              "J/m^2, MBT inside the band at %.0f %% of %zu readings\n",
              std::sqrt(swing2 / n), half / n, 100.0 * inside / n, n);
  // Measured: swings 137 J/m^2 RMS, band half-width 270 J/m^2 (1.97 x the swings' RMS: the
  // +-2 sigma the band states), MBT inside it at 97 % of 156 readings. Bounds: MBT inside at 90 %
  // or more (the nominal 95 % less the sampling scatter of a few swing periods), and the band no
  // wider than 2.5 x the swings' RMS, so that it is not simply made wide.
  EXPECT_GT(static_cast<double>(inside) / n, 0.90);
  EXPECT_LT(half / n, 2.5 * std::sqrt(swing2 / n));
  EXPECT_GT(half / n, 1.5 * std::sqrt(swing2 / n));
}

// R without crack readings on the shared records (issue 31 item 3): each record with its crack
// column dropped, reduced against the CBBM equivalent crack (a0 = its first reading; G13 and E22
// from data/dcb_records/README.md's approximate moduli, 2.29 and 6.11 GPa), against the MBT
// plateau of the same record with its readings. |Delta| decides it: MBT's |Delta| on these
// records is 5.9-16.7 mm, far above corrected beam theory's chi h (2.4-3.6 mm with the E_f each
// calibrates), so the readings' origin or the crosshead's own compliance is not what a beam at a0
// expects. Measured (docs/verification.md, "R without crack readings and step-wise readings"):
// with chi h the plateau is +11, +13, +45, +26 % off MBT's (the equivalent crack ends 5-12 mm
// short of the last reading); with MBT's |Delta| given (ReduceOptions::root_rotation, as a lab
// would carry it from a calibration test with readings) +4.3, +5.2, -5.4, -6.1 %. The bound is on
// the second: 8 %, the measured worst plus the 2 % by which CBBM and MBT already differ beside the
// readings (Timoshenko's shear term against MBT's fitted line).
TEST(RecordReduction, SharedRecordsWithoutTheCrackColumn) {
  for (const char* name : shared_records) {
    const auto rec = read_test_records(record_path(name), shared_columns()).at(0);
    const auto with = reduce_record(rec, shared_specimen());
    TestRecord bare = rec;
    bare.crack_length.clear();
    specimen::Specimen sp = shared_specimen();
    sp.initial_crack = rec.crack_length.front();
    ReduceOptions o;
    o.shear_modulus = 2.29e9;
    o.transverse_modulus = 6.11e9;
    const auto chi = reduce_record(bare, sp, o);
    ASSERT_EQ(chi.crack, "equivalent");
    o.root_rotation = with.mbt_delta;
    const auto eq = reduce_record(bare, sp, o);
    std::printf("%s: MBT plateau %.0f J/m^2 with readings (|Delta| %.2f mm); without: CBBM "
                "plateau %.0f (%+.1f %%) with MBT's |Delta|, %.0f (%+.1f %%) with chi h %.2f mm; "
                "direct energy vs a_eq %.0f (%+.1f %%); final a_eq %.1f / %.1f mm vs last reading "
                "%.1f mm; beside the readings CBBM %.0f\n",
                name, with.mbt.plateau, with.mbt_delta / mm, eq.cbbm.plateau,
                100 * (eq.cbbm.plateau / with.mbt.plateau - 1), chi.cbbm.plateau,
                100 * (chi.cbbm.plateau / with.mbt.plateau - 1), chi.cbbm_delta / mm,
                eq.energy.plateau, 100 * (eq.energy.plateau / with.mbt.plateau - 1),
                eq.a.back() / mm, chi.a.back() / mm, with.a.back() / mm, with.cbbm.plateau);
    std::printf(
        "   initiation NL / 5 %%-max / VIS: MBT %.0f / %.0f / %.0f, CBBM %.0f / %.0f / %.0f "
        "J/m^2 (lines %zu / %zu / %zu)\n",
        with.initiation.nl.G_MBT, with.initiation.offset5_max.G_MBT, with.initiation.vis.G_MBT,
        with.initiation.nl.G_CBBM, with.initiation.offset5_max.G_CBBM, with.initiation.vis.G_CBBM,
        with.initiation.nl.line, with.initiation.offset5_max.line, with.initiation.vis.line);
    EXPECT_NEAR(eq.cbbm.plateau / with.mbt.plateau, 1, 0.08) << name;
  }
}

// The fit's correction by simulation reduces each simulated record with its measured record's
// windows (ReduceOptions::window_da, reduce_with_windows_of), so that the chain is one statistic
// on both. Checked on a shared record: reduced with its own windows it gives back its own R
// (the windows are the same, so the slopes are, to round-off); and the option does take effect:
// with the windows of another record (DCB-02's) the slopes differ and follow those windows.
TEST(RecordReduction, ReducedWithTheWindowsOfAnotherReduction) {
  const auto rec = read_test_records(record_path("DCB-01"), shared_columns()).at(0);
  const auto own = reduce_record(rec, shared_specimen());
  ASSERT_EQ(own.windows.size(), own.R_energy.size());
  ReduceOptions with_own;
  reduce_with_windows_of(own, with_own);
  ASSERT_FALSE(with_own.window_da.empty());
  const auto again = reduce_record(rec, shared_specimen(), with_own);
  ASSERT_EQ(again.R_energy.size(), own.R_energy.size());
  for (std::size_t i = 0; i < own.R_energy.size(); ++i) {
    EXPECT_NEAR(again.windows[i], own.windows[i], 1e-12) << "reading " << i;
    // The readings-as-read slopes (R_energy_readings) are the windowed ones before R at
    // initiation is refitted; both must repeat.
    EXPECT_NEAR(again.R_energy_readings[i], own.R_energy_readings[i],
                1e-9 * std::abs(own.R_energy_readings[i]))
        << "reading " << i;
  }
  const auto other = reduce_record(read_test_records(record_path("DCB-02"), shared_columns()).at(0),
                                   shared_specimen());
  ReduceOptions with_other;
  reduce_with_windows_of(other, with_other);
  const auto moved = reduce_record(rec, shared_specimen(), with_other);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < moved.windows.size(); ++i) {
    const double expected =
        interpolate_linear(with_other.window_da, with_other.window_width, moved.da[i]);
    EXPECT_NEAR(moved.windows[i], expected, 1e-12) << "reading " << i;
    differ += std::abs(moved.R_energy_readings[i] - own.R_energy_readings[i]) >
              1e-6 * std::abs(own.R_energy_readings[i]);
  }
  EXPECT_GT(differ, moved.windows.size() / 4) << "the other windows changed too few slopes";

  // Against the CBBM equivalent crack (no crack column) the windows are the equivalent path's,
  // one per row, and give its own R back the same way.
  TestRecord bare = rec;
  bare.crack_length.clear();
  specimen::Specimen sp = shared_specimen();
  sp.initial_crack = rec.crack_length.front();
  ReduceOptions eq_options;
  eq_options.shear_modulus = 2.29e9; // data/dcb_records/README.md's approximate moduli
  eq_options.transverse_modulus = 6.11e9;
  const auto eq = reduce_record(bare, sp, eq_options);
  ASSERT_EQ(eq.crack, "equivalent");
  ASSERT_EQ(eq.windows.size(), eq.R_energy.size());
  ReduceOptions eq_own = eq_options;
  reduce_with_windows_of(eq, eq_own);
  const auto eq_again = reduce_record(bare, sp, eq_own);
  ASSERT_EQ(eq_again.R_energy.size(), eq.R_energy.size());
  std::size_t finite = 0;
  for (std::size_t i = 0; i < eq.R_energy.size(); ++i) {
    // The first steps' windows hold fewer than 3 points: NaN in both, as before.
    ASSERT_EQ(std::isfinite(eq_again.R_energy[i]), std::isfinite(eq.R_energy[i])) << i;
    if (!std::isfinite(eq.R_energy[i]))
      continue;
    ++finite;
    EXPECT_NEAR(eq_again.R_energy[i], eq.R_energy[i], 1e-9 * std::abs(eq.R_energy[i]))
        << "equivalent row " << i;
  }
  EXPECT_GT(finite, eq.R_energy.size() / 2);
}
