#pragma once
// Straight-line numerics shared by the analysis chain: least-squares lines through samples and
// piecewise-linear interpolation of sorted samples.
#include <cstddef>
#include <vector>

namespace fiberbridge::analysis {

/// y = y_mean + slope (x - x_mean). `valid` is false for fewer than two points or no spread in x.
struct LineFit {
  double slope = 0;
  double x_mean = 0, y_mean = 0;
  std::size_t n = 0;
  bool valid = false;
  double at(double x) const { return y_mean + slope * (x - x_mean); }
};

/// Least-squares line through (x[i], y[i]) for i in [begin, end). Centred two-pass sums, so a
/// narrow window far from the origin loses no digits (running raw sums of x^2 would).
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y, std::size_t begin,
                 std::size_t end);

/// Values at `at` (non-decreasing) of the polyline through (x, y) (x strictly increasing); held
/// constant at y.front() / y.back() outside [x.front(), x.back()]. O(x.size() + at.size()).
std::vector<double> resample_linear(const std::vector<double>& x, const std::vector<double>& y,
                                    const std::vector<double>& at);

/// One value of the same polyline (binary search).
double interpolate_linear(const std::vector<double>& x, const std::vector<double>& y, double at);

/// The same inside [x.front(), x.back()], NaN outside it (and for an empty x): a curve compared
/// only where it has values (the campaign's Fig. 10 and law tables, the model comparison).
double interpolate_within(const std::vector<double>& x, const std::vector<double>& y, double at);

} // namespace fiberbridge::analysis
