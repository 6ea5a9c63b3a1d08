#include "fiberbridge/analysis/line_fit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fiberbridge::analysis {

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y, std::size_t begin,
                 std::size_t end) {
  LineFit f;
  f.n = end > begin ? end - begin : 0;
  if (f.n == 0)
    return f;
  double sx = 0, sy = 0;
  for (std::size_t i = begin; i < end; ++i) {
    sx += x[i];
    sy += y[i];
  }
  const double count = static_cast<double>(f.n);
  f.x_mean = sx / count;
  f.y_mean = sy / count;
  double sxx = 0, sxy = 0;
  for (std::size_t i = begin; i < end; ++i) {
    const double dx = x[i] - f.x_mean;
    sxx += dx * dx;
    sxy += dx * (y[i] - f.y_mean);
  }
  if (f.n < 2 || !(sxx > 0))
    return f;
  f.slope = sxy / sxx;
  f.valid = true;
  return f;
}

std::vector<double> resample_linear(const std::vector<double>& x, const std::vector<double>& y,
                                    const std::vector<double>& at) {
  if (x.empty() || x.size() != y.size())
    throw std::logic_error("resample_linear: x and y must be non-empty and of equal size");
  std::vector<double> out(at.size());
  std::size_t j = 0; // x[j] <= t < x[j+1] for the current t once t is inside the data
  for (std::size_t i = 0; i < at.size(); ++i) {
    const double t = at[i];
    if (t <= x.front()) {
      out[i] = y.front();
      continue;
    }
    if (t >= x.back()) {
      out[i] = y.back();
      continue;
    }
    while (j + 1 < x.size() && x[j + 1] <= t)
      ++j;
    const double w = (t - x[j]) / (x[j + 1] - x[j]);
    out[i] = y[j] + w * (y[j + 1] - y[j]);
  }
  return out;
}

double interpolate_linear(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (x.empty() || x.size() != y.size())
    throw std::logic_error("interpolate_linear: x and y must be non-empty and of equal size");
  if (at <= x.front())
    return y.front();
  if (at >= x.back())
    return y.back();
  const std::size_t j =
      static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin()) - 1;
  const double w = (at - x[j]) / (x[j + 1] - x[j]);
  return y[j] + w * (y[j + 1] - y[j]);
}

double interpolate_within(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (x.empty() || at < x.front() || at > x.back())
    return NAN;
  return interpolate_linear(x, y, at);
}

} // namespace fiberbridge::analysis
