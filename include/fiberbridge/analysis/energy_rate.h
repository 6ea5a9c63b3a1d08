#pragma once
// The direct-energy rate R = dD/(B da) of a record from its dissipated energy D = W - P opening/2
// and a crack length, with its band (docs/design.md section 6, "Direct energy on step-wise
// crack readings"). Shared by the reductions against measured and against equivalent cracks.
#include "fiberbridge/analysis/test_record.h"

#include <cstddef>
#include <vector>

namespace fiberbridge::analysis {

/// D = W - P opening/2 at every row, W the trapezoid work of the load over the opening [J].
std::vector<double> dissipated_energy(const TestRecord& record);

/// Slopes of D against a (a non-decreasing) in local least-squares lines over the points within
/// window/2 of each point, and the band +-2 s, s the larger of the slope's standard error and
/// the scatter of neighbouring estimates (RMS difference to the slope over twice the window,
/// x sqrt(4/3), over the points within two windows either side; record_reduction.h says why).
struct EnergySlopes {
  std::vector<double> slope, lo, hi; ///< dD/da and its band [J/m]
  std::vector<double> window;        ///< the window of each point [m]
};
EnergySlopes energy_slopes(const std::vector<double>& a, const std::vector<double>& D,
                           double window);

/// The same slopes and band with a given window at each point (`window[j]` at `a[j]`).
EnergySlopes energy_slopes_per_point(const std::vector<double>& a, const std::vector<double>& D,
                                     const std::vector<double>& window);

/// The same slopes and band with a window chosen at each point from the data: intersection of
/// confidence intervals (Lepski/ICI) over windows from `w_min` growing by sqrt(2) up to `w_max`.
/// The interval of each slope is +-2 sigma/sqrt(Sxx), sigma the median residual standard
/// deviation of the `w_min` lines, scaled up where the slopes over `w_min` scatter more than
/// those residuals say (reading errors correlated over more than `w_min`, as in cracks read in
/// steps); the widest window whose interval still meets those of all narrower ones is kept,
/// and the choices are smoothed by a running median over `w_max`. Where R bends (the rise after
/// initiation, the onset of the plateau) the wider slopes leave the narrow ones' intervals and
/// the window stays short; where R is straight or the record is noisy it grows to `w_max`.
EnergySlopes energy_slopes_adaptive(const std::vector<double>& a, const std::vector<double>& D,
                                    double w_min, double w_max);

/// A monotone smooth crack length at every row from the fresh readings (rows `readings` of
/// `record`): isotonic regression of the readings against time (pool-adjacent-violators: a crack
/// does not heal), then, at each row, a local straight line in time through the isotonic values
/// of the readings within `time_window`/2 (at least 3 readings), held non-decreasing. Rows before
/// the first reading and after the last take the isotonic end values. Uses the row index as
/// time when the record has no time column. [m]
std::vector<double> monotone_crack(const TestRecord& record,
                                   const std::vector<std::size_t>& readings, double time_window);

/// Pool-adjacent-violators: the non-decreasing sequence closest to y in least squares.
std::vector<double> isotonic(const std::vector<double>& y);

} // namespace fiberbridge::analysis
