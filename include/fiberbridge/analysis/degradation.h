#pragma once
// Degradation statistics vs. moisture cycles and the durability ranking (seed section 3.3,
// Table 1; docs/design.md section 1 "Degradation and ranking").
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace fiberbridge::analysis {

/// Ordinary least squares y = intercept + slope x.
struct LinearRegression {
  double slope = 0, intercept = 0;
  double r2 = 0;              ///< coefficient of determination (0 when y is constant)
  double slope_std_error = 0; ///< standard error of the slope (NaN for 2 points)
  int n = 0;
};
/// Throws InputError for sizes that differ, fewer than 2 points, non-finite values or all x equal.
LinearRegression linear_regression(const std::vector<double>& x, const std::vector<double>& y);

/// One row of a table in the format of reference/seed_table1.csv.
struct PropertyRow {
  std::string material, property;
  std::vector<double> values; ///< one per cycle column (NaN where empty)
  std::string range_text;     ///< for rho_b-style "low-high" cells: the raw text
  double printed_slope = 0, printed_r2 = 0;
  bool has_printed = false;
  std::size_t line = 0;

  /// Raw text of every cycle cell (as printed; empty where the table has no value).
  std::vector<std::string> cells;
  /// Half a unit of the last printed digit of each numeric cycle cell ("661" -> 0.5, "6.7" ->
  /// 0.05; NaN where empty or a range): the rounding the printed value carries.
  std::vector<double> half_units;
  /// For range rows (range_text non-empty): (low, high) per cycle cell, NaN where empty.
  std::vector<std::pair<double, double>> ranges;
  /// Half units of the printed slope and R^2 (meaningful when has_printed).
  double printed_slope_half_unit = 0, printed_r2_half_unit = 0;
};

struct PropertyTable {
  std::string source;
  std::vector<double> cycles; ///< from the column names c0, c8, ... (the number after 'c')
  std::vector<PropertyRow> rows;

  /// The row of (material, property), or nullptr.
  const PropertyRow* find(const std::string& material, const std::string& property) const;
};

/// Reads `material,property,c<N>...,slope,r2`; cells like "40-111" (ranges) are kept as text.
/// Throws InputError naming file/line for missing columns, non-numeric cells, < 3 cycle columns.
/// `slope` and `r2` are optional as a pair (a table without printed statistics has neither);
/// a row holds either numbers or ranges, not both.
PropertyTable read_property_table(const std::string& path);
/// The same, from text (`source_name` is used in error messages).
PropertyTable parse_property_table(const std::string& text, const std::string& source_name);

struct DegradationRow {
  std::string material, property;
  LinearRegression fit;
  double normalized_rate = 0; ///< slope / intercept [1/cycle]
  bool significant = false;   ///< slope < 0 and R^2 >= 0.8 (the paper's bold)
  double printed_slope = 0, printed_r2 = 0;
  bool has_printed = false;
  bool matches_printed = true; ///< recomputed slope and R^2 agree with the printed ones (rounding)

  std::string source;   ///< the table file (for messages)
  std::size_t line = 0; ///< line of the row in the table file
  /// Half-widths of the acceptance band used for matches_printed (see analyse_degradation).
  double slope_tolerance = 0, r2_tolerance = 0;
};

/// Regression for every numeric property row (sigma1, J1, sigma2, J2 and any other numeric row).
/// Range rows are skipped; empty cells are left out of the fit. A row needs at least 2 values
/// (InputError otherwise) and at least 3 to be `significant` (two points always give R^2 = 1).
///
/// matches_printed: a printed value p with last-digit unit u accepts a recomputed v that rounds
/// OR truncates to p (the seed does both: PVA sigma1 R^2 0.9494 is printed 0.94, PRF J1 R^2
/// 0.4573 is printed 0.46), widened by the first-order effect on slope and R^2 of the
/// +-half-unit rounding of the printed inputs (the paper regressed unrounded values).
std::vector<DegradationRow> analyse_degradation(const PropertyTable& table);

/// The trilinear-law properties whose degradation ranks a material: sigma1, J1, sigma2, J2.
/// Other numeric rows (l_b) are regressed and reported but do not enter the score.
bool is_traction_law_property(const std::string& property);

struct MaterialRank {
  std::string material;
  double degradation_score = 0; ///< sum of significant normalized rates (<= 0; 0 = none)
  int rank = 0;                 ///< 1 = most durable; ties share a rank
  std::vector<std::string> significant_properties;
};

/// Most durable first: by summed significant normalized degradation rates (seed: PF > EPI > PRF
/// > PVA). Every material of the table is ranked by the same rule, solid wood (DF) included;
/// equal scores share a rank and the next rank skips ("1, 1, 3"), order of first appearance
/// among equals.
std::vector<MaterialRank> rank_materials(const std::vector<DegradationRow>& rows);

/// A row whose J_1 or J_2 does not follow from its sigma_1, sigma_2 (J_1 = (s1 d2 - s2 d1)/2,
/// J_2 = s2 dc/2, docs/design.md section 1).
struct ConsistencyIssue {
  std::string material;
  double cycles = 0;
  std::string message; ///< e.g. "J1 printed 347, expected 26.2 from sigma1 69, sigma2 166; J1 and
                       ///< J2 look swapped"
  bool j1_consistent = true, j2_consistent = true;
  double j1_printed = 0, j1_expected = 0, j2_printed = 0, j2_expected = 0; ///< [J/m^2]
};

/// How far a printed J may be from the value computed from the printed stresses. The rounding of
/// the printed digits (J, sigma1, sigma2) is always allowed on top of these.
struct ConsistencyTolerance {
  double j1_relative = 0.0;
  /// Every printed J2 of the seed's Table 1 lies 4-6 % below s2 dc/2 (2 J2 / s2 = 5.70 mm for
  /// PVA, 3.30 mm for the others: a convention of the paper's fit we cannot recover). 10 % accepts
  /// that systematic offset with margin and still catches gross misprints (DF 16 cycles: -91 %).
  double j2_relative = 0.10;
};

/// Checks every (material, cycle) with sigma1, sigma2, J1, J2 present; `d1`, `d2` [mm] and the
/// per-material dc [mm] (`dc_of(material)`). Tolerance: the rounding of the printed digits plus
/// ConsistencyTolerance{} (10 % on J2 for the seed's systematic offset, nothing extra on J1).
std::vector<ConsistencyIssue> check_row_consistency(const PropertyTable& table, double d1_mm,
                                                    double d2_mm,
                                                    double (*dc_mm_of)(const std::string&));
/// The same with explicit tolerances (the overload above uses ConsistencyTolerance{}).
std::vector<ConsistencyIssue> check_row_consistency(const PropertyTable& table, double d1_mm,
                                                    double d2_mm,
                                                    double (*dc_mm_of)(const std::string&),
                                                    const ConsistencyTolerance& tolerance);

/// The seed's fixed openings: dc = 6.0 mm for PVA, 3.5 mm for all others.
double seed_delta_c_mm(const std::string& material);

} // namespace fiberbridge::analysis
