#pragma once
// R(a) from a raw DCB record (docs/design.md, "Test records"): by direct energy, with no beam or
// process-zone assumption (seed section 2.2), and by the beam-theory reductions of ASTM D5528 /
// ISO 15024 (MBT, CC, MCC) that the seed says are never correct with bridging, side by side.
#include "fiberbridge/analysis/equivalent_crack.h"
#include "fiberbridge/analysis/initiation_values.h"
#include "fiberbridge/analysis/rdelta_data.h"
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/specimen/specimen.h"

#include <string>
#include <vector>

namespace fiberbridge::analysis {

struct ReduceOptions {
  /// Width in crack length of the local straight-line fits that differentiate the dissipated
  /// energy [m]; NaN: automatic (record_reduction.cc says how).
  double smoothing_window = NAN;
  /// ASTM D5528 / ISO 15024 large-displacement corrections F and N (N with l2 = 0 without end
  /// blocks: its (delta/a)^2 term is the arms' own) on MBT, CC and MCC.
  bool large_displacement_correction = true;
  /// The plateau is the mean over the last this fraction of each record's crack extension.
  double plateau_fraction = 1.0 / 3.0;
  /// Reduce against the CBBM equivalent crack (equivalent_crack.h) even when the record has crack
  /// readings (they are then reported beside it). A record without readings is always reduced
  /// against it. The scene's `Test/Crack length = equivalent` sets this.
  bool use_equivalent_crack = false;
  /// G13 of the arms for CBBM's shear term [Pa] (Material/G_LT; --shear-modulus); NaN: none.
  double shear_modulus = NAN;
  /// E22 [Pa] (Material/E_T): with G13, the root-rotation correction |Delta| = chi h of corrected
  /// beam theory for records without crack readings (with readings, MBT's |Delta| is used).
  double transverse_modulus = NAN;
  /// |Delta| for CBBM [m]; NaN: as above (MBT's, else chi h, else 0 with a note).
  double root_rotation = NAN;
  /// a0 [m] of a record without crack readings when the specimen's initial_crack is NaN (the
  /// scene's Specimen/Initial crack, which records with readings replace by their first reading).
  double initial_crack_without_readings = NAN;
  /// Steps of the equivalent crack at which a record without readings is reduced [m]; NaN: h/10.
  double equivalent_step = NAN;
  /// Direct energy against measured readings: "readings" (D and a at the rows with a fresh
  /// reading, as read) or "monotone" (a from isotonic regression of the readings against time,
  /// smoothed over a few reading intervals; energy_rate.h). docs/design.md section 6 says which
  /// is the default and why.
  std::string energy_crack = "readings";
  /// The direct-energy windows of an earlier reduction as a function of crack extension
  /// (ReducedRecord::da and ::windows): when given, the slopes take them (linear in the
  /// extension, held at the ends) instead of choosing their own. The fit's correction by
  /// simulation reduces each simulated record with its measured record's windows: the windows a
  /// noisy record chooses are wider than a clean simulation's, and with its own windows the chain
  /// would not be the same statistic on both (docs/verification.md, "The correction's records
  /// reduced with the measured windows"). Empty: the smoothing window above.
  std::vector<double> window_da, window_width;
};

/// Initiation and plateau of one method's R(a).
struct MethodSummary {
  double initiation = NAN;  ///< at the first crack reading beyond a0 (visual onset) [J/m^2]
  double plateau = NAN;     ///< mean over the last plateau_fraction of the extension [J/m^2]
  double plateau_std = NAN; ///< standard deviation over those readings [J/m^2]
};

/// One record reduced: one row per crack reading beyond a0 (the rows where the reading changes).
struct ReducedRecord {
  std::string name, source;
  std::vector<std::size_t> line;     ///< source line of each row
  std::vector<std::size_t> rows;     ///< the record's row of each row
  std::vector<double> a, da;         ///< crack length from the load line, extension a - a0 [m]
  std::vector<double> load, opening; ///< [N], [m] at the reading
  std::vector<double> R_energy, R_energy_lo, R_energy_hi; ///< direct energy and its band [J/m^2]
  std::vector<double> R_MBT, R_CC, R_MCC;                 ///< [J/m^2]
  std::vector<double> delta_root;                         ///< [m], empty when not measured
  /// "measured": rows are the fresh crack readings and a is read; "equivalent": rows are steps of
  /// the CBBM equivalent crack, a = a_eq and R_MBT/CC/MCC are NaN (they need measured cracks).
  std::string crack = "measured";
  /// CBBM beside (or instead of) the measured crack, at every row: the equivalent crack from the
  /// load line (a_e - |Delta|) [m], G by CBBM [J/m^2], direct energy against a_eq and its band.
  /// Empty when CBBM could not be calibrated (notes say why).
  std::vector<double> a_eq, R_CBBM, R_energy_eq, R_energy_eq_lo, R_energy_eq_hi;
  std::vector<double> R_energy_readings; ///< direct energy against the readings as read (the
                                         ///< default; beside when energy_crack = monotone)
  double flexural_modulus = NAN;         ///< E_f of CBBM [Pa]
  double cbbm_delta = NAN;               ///< |Delta| CBBM used [m]
  double initial_compliance = NAN;       ///< C0 [m/N]
  double opening_offset = NAN;           ///< opening at zero load of the initial line [m]
  InitiationValues initiation;
  double a0 = NAN;                 ///< [m]
  double window = NAN;             ///< smoothing window used (median over the rows) [m]
  std::vector<double> windows;     ///< the direct-energy window of each row [m]
  double mbt_delta = NAN;          ///< |Delta| of MBT [m]
  double cc_n = NAN;               ///< CC exponent n (slope of log C against log a)
  double mcc_A1 = NAN;             ///< MCC slope A1 of a/(2h) against C^(1/3) [N^(1/3) m^(-1/3)]
  double max_opening_over_a = NAN; ///< largest delta/a over the readings (F matters above ~0.4)
  MethodSummary energy, mbt, cc, mcc, cbbm, energy_eq;
  std::vector<std::string> cleaning; ///< the reader's cleaning sentences
  std::vector<std::string> notes;    ///< how the reduction ran (window, fits, corrections)
};

/// Reduces one cleaned record. Direct energy: D = W - U with W the trapezoid integral of P over
/// the opening and U = P opening / 2 (linear unloading to the origin, seed Eq. 2's assumption);
/// R = dD/(B da) is the slope of D against a in a local least-squares line over the readings
/// within window/2 of each reading (D only at the rows where a new crack reading is made). Its
/// band is +-2 s, s the larger of that slope's standard error from the fit's residuals and the
/// scatter of neighbouring estimates: sqrt(4/3) x the RMS difference, over the readings within
/// two windows either side, between the slope over the window and over twice the window (this
/// sees crack readings whose error is correlated over millimetres, which bend D(a) smoothly
/// inside one window and leave its residuals small). Beam theory (ASTM D5528 / ISO 15024), C =
/// opening/load, fits over the readings beyond a0:
///  - MBT: G = 3 P delta F / (2 B (a + |Delta|) N), Delta from the line (C/N)^(1/3) against a;
///  - CC:  G = n P delta F / (2 B a N), n the slope of log(C/N) against log a;
///  - MCC: G = 3 P^2 (C/N)^(2/3) F / (2 A1 B 2h), A1 the slope of a/(2h) against (C/N)^(1/3);
///  - F = 1 - 3/10 (delta/a)^2 - 3/2 (delta l1/a^2),
///    N = 1 - (l2/a)^3 - 9/8 (1 - (l2/a)^2) delta l1/a^2 - 9/35 (delta/a)^2
///    (l1, l2 from the specimen's pin distances; l1 = h/2 and l2 = 0 without blocks). F/N is
///    checked against the exact elastica of a DCB arm (tests/analysis/record_reduction_tests.cc).
/// CBBM (equivalent_crack.h) beside: E_f from the initial compliance at a0 + |Delta|, a_eq from
/// the compliance (opening - offset)/(load N) at each row, G by CBBM x F/N; direct energy against
/// a_eq too. A record without crack readings (crack_length empty, or use_equivalent_crack) is
/// reduced against a_eq alone: rows where the running maximum of a_eq passes a0 + k
/// equivalent_step. ASTM D5528 initiation values (initiation_values.h) on every record.
/// Throws InputError (naming the record's file) if the geometry fails
/// specimen::Specimen::check_test_geometry, a0 from the specimen lies beyond the first readings, or
/// fewer than 5 readings lie beyond a0 (equivalent: fewer than 5 steps of a_eq beyond a0, or no
/// initial linear part).
ReducedRecord reduce_record(const TestRecord& record, const specimen::Specimen& specimen,
                            const ReduceOptions& options = {});

/// Sets `options` to reduce with `measured`'s direct-energy windows (ReduceOptions::window_da).
void reduce_with_windows_of(const ReducedRecord& measured, ReduceOptions& options);

/// Replicates on a common crack-extension grid: each method's mean and sample standard
/// deviation over the records at each point.
struct ReducedMean {
  std::vector<double> da; ///< [0, smallest largest extension] [m]
  std::vector<double> R_energy, R_energy_std, R_MBT, R_MBT_std, R_CC, R_CC_std, R_MCC, R_MCC_std;
  std::vector<double> R_CBBM, R_CBBM_std; ///< against each record's own abscissa (a or a_eq)
  int n_records = 0;
  MethodSummary energy, mbt, cc, mcc,
      cbbm; ///< of the mean curves (initiation: first grid point > 0)
  double plateau_fraction = 1.0 / 3.0;
};

/// Linear interpolation of each record in da; n_grid points including both ends. Throws
/// InputError for no records.
ReducedMean average_reduced(const std::vector<ReducedRecord>& records, double plateau_fraction,
                            int n_grid = 101);

/// R(delta_root) of records that measured delta_root, as the replicates `extract`/`fit` read
/// (R from the direct energy; delta_root held at its running maximum so it does not decrease).
/// Throws InputError when a record has no delta_root.
RDeltaData to_rdelta(const std::vector<ReducedRecord>& records, const std::string& source);

} // namespace fiberbridge::analysis
