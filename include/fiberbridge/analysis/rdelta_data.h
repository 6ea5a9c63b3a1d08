#pragma once
// Measured R curves: reading, converting R(a) to R(delta) and averaging replicates
// (docs/design.md section 1, "Data preparation"). SI inside: delta in m, R in J/m^2.
#include <string>
#include <vector>

namespace fiberbridge::analysis {

/// One replicate as read: rows in time order (or file order when there is no time column).
struct Replicate {
  std::string label;             ///< value of the `replicate` column, or "1"
  std::vector<double> time_s;    ///< empty when the file has no time_s column
  std::vector<double> a;         ///< crack-tip position [m]; empty when no a_mm column
  std::vector<double> delta;     ///< notch-root opening [m]
  std::vector<double> R;         ///< [J/m^2]
  std::vector<std::size_t> line; ///< file line of each row (for messages)
};

/// A file as read: one or more replicates (split on the `replicate` column).
struct RDeltaData {
  std::string source;
  std::vector<Replicate> replicates;
};

/// Reads CSV columns delta_mm, R_J_m2 (required) and a_mm, time_s, replicate (optional).
/// Rows are ordered by time_s within a replicate when present. Throws InputError naming the file
/// and line for: missing columns, NaN/non-numbers, negative delta or R, delta that decreases in
/// time order (the reference parameter must be monotone), fewer than 8 rows in a replicate.
RDeltaData read_rdelta_csv(const std::string& path);

/// The columns of an R(delta) table held in memory (the Python module's arrays), in the file's
/// units; a_mm, time_s and replicate may be empty.
struct RDeltaColumns {
  std::vector<double> delta_mm, R_J_m2, a_mm, time_s;
  std::vector<std::string> replicate;
};

/// The same table as read_rdelta_csv makes, with its checks, from columns in memory: messages
/// name `source` and the 1-based row. Also refused: columns of different lengths, non-finite
/// values (the file reader refuses them as cells).
RDeltaData rdelta_from_columns(const std::string& source, const RDeltaColumns& columns);

/// One R(delta) curve on a grid (the averaged replicates).
struct RDeltaCurve {
  std::vector<double> delta; ///< increasing [m]
  std::vector<double> R;     ///< [J/m^2]
  std::vector<double> R_std; ///< standard deviation over replicates at each grid point (0 for one)
  int n_replicates = 1;
  std::string report; ///< what was done (grid, range, replicates), for summary.json
};

/// Averages replicates on a common uniform grid of `n_grid` points over [0, min over replicates
/// of their largest delta] (linear interpolation within each replicate; the curve below the first
/// measured delta is held at the first R, which is J_tip territory where R is flat, seed Eq. 2).
/// One replicate: the same resampling.
RDeltaCurve average_replicates(const RDeltaData& data, int n_grid = 401);

} // namespace fiberbridge::analysis
