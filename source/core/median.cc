// The two medians (median.h; why two: docs/design.md, "Small shared helpers").
#include "fiberbridge/core/median.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge {

namespace {

/// The finite values of `v`, with the upper middle one at index n/2 and the others partitioned
/// around it (std::nth_element).
void partition_finite(std::vector<double>& v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (!v.empty())
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
}

} // namespace

double median(std::vector<double> v) {
  partition_finite(v);
  if (v.empty())
    return NAN;
  const std::size_t n = v.size(), m = n / 2;
  if (n % 2 == 1)
    return v[m];
  // The lower middle value is the largest of the values partitioned below the upper one.
  const double lo = *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(m));
  return lo + 0.5 * (v[m] - lo);
}

double median_upper(std::vector<double> v) {
  partition_finite(v);
  return v.empty() ? NAN : v[v.size() / 2];
}

} // namespace fiberbridge
