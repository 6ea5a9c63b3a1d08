#pragma once
// Degradation statistics vs. moisture cycles and the durability ranking (seed section 3.3,
// Table 1; DESIGN.md section 1 "Degradation and ranking").
#include <string>
#include <vector>

namespace fiberbridge::analysis {

/// Ordinary least squares y = intercept + slope x.
struct LinearRegression {
  double slope = 0, intercept = 0;
  double r2 = 0;              ///< coefficient of determination
  double slope_std_error = 0; ///< standard error of the slope (NaN for 2 points)
  int n = 0;
};
LinearRegression linear_regression(const std::vector<double>& x, const std::vector<double>& y);

/// One row of a table in the format of reference/seed_table1.csv.
struct PropertyRow {
  std::string material, property;
  std::vector<double> values;     ///< one per cycle column (NaN where empty)
  std::string range_text;         ///< for rho_b-style "low-high" cells: the raw text
  double printed_slope = 0, printed_r2 = 0;
  bool has_printed = false;
  std::size_t line = 0;
};

struct PropertyTable {
  std::string source;
  std::vector<double> cycles;     ///< from the column names c0, c8, ... (the number after 'c')
  std::vector<PropertyRow> rows;
};

/// Reads `material,property,c<N>...,slope,r2`; cells like "40-111" (ranges) are kept as text.
/// Throws InputError naming file/line for missing columns, non-numeric cells, < 3 cycle columns.
PropertyTable read_property_table(const std::string& path);

struct DegradationRow {
  std::string material, property;
  LinearRegression fit;
  double normalized_rate = 0; ///< slope / intercept [1/cycle]
  bool significant = false;   ///< slope < 0 and R^2 >= 0.8 (the paper's bold)
  double printed_slope = 0, printed_r2 = 0;
  bool has_printed = false;
  bool matches_printed = true; ///< recomputed slope and R^2 agree with the printed ones (rounding)
};

/// Regression for every numeric property row (sigma1, J1, sigma2, J2 and any other numeric row).
std::vector<DegradationRow> analyse_degradation(const PropertyTable& table);

struct MaterialRank {
  std::string material;
  double degradation_score = 0; ///< sum of significant normalized rates (<= 0; 0 = none)
  int rank = 0;                 ///< 1 = most durable; ties share a rank
  std::vector<std::string> significant_properties;
};

/// Most durable first: by summed significant normalized degradation rates (seed: PF > EPI > PRF
/// > PVA).
std::vector<MaterialRank> rank_materials(const std::vector<DegradationRow>& rows);

/// A row whose J_1 or J_2 does not follow from its sigma_1, sigma_2 (J_1 = (s1 d2 - s2 d1)/2,
/// J_2 = s2 dc/2, DESIGN.md section 1).
struct ConsistencyIssue {
  std::string material;
  double cycles = 0;
  std::string message; ///< e.g. "J1 printed 347, expected 26.2 from sigma1 69, sigma2 166; J1 and
                       ///< J2 look swapped"
};

/// Checks every (material, cycle) with sigma1, sigma2, J1, J2 present; `d1`, `d2` [mm] and the
/// per-material dc [mm] (`dc_of(material)`). Tolerance: stated in the implementation.
std::vector<ConsistencyIssue> check_row_consistency(const PropertyTable& table, double d1_mm,
                                                    double d2_mm,
                                                    double (*dc_mm_of)(const std::string&));

/// The seed's fixed openings: dc = 6.0 mm for PVA, 3.5 mm for all others.
double seed_delta_c_mm(const std::string& material);

} // namespace fiberbridge::analysis
