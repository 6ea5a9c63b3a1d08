#include "fiberbridge/identify/covariance.h"

#include <cmath>
#include <limits>

namespace fiberbridge::identify {

Covariance covariance_from_jacobian(const std::vector<std::vector<double>>& jac, double chi2) {
  const std::size_t n = jac.size(), p = n ? jac[0].size() : 0;
  // Normal matrix scaled to unit diagonal first, so that parameters of very different units
  // (mm against kPa) do not decide the pivots.
  std::vector<std::vector<double>> a(p, std::vector<double>(p, 0.0));
  for (const auto& row : jac)
    for (std::size_t i = 0; i < p; ++i)
      for (std::size_t j = 0; j < p; ++j)
        a[i][j] += row[i] * row[j];
  std::vector<double> scale(p, 1.0);
  for (std::size_t i = 0; i < p; ++i)
    scale[i] = a[i][i] > 0 ? 1 / std::sqrt(a[i][i]) : 1.0;
  for (std::size_t i = 0; i < p; ++i)
    for (std::size_t j = 0; j < p; ++j)
      a[i][j] *= scale[i] * scale[j];
  Covariance c;
  // Gauss-Jordan with partial pivoting on the scaled (correlation-like) normal matrix.
  std::vector<std::vector<double>> inv(p, std::vector<double>(p, 0.0));
  for (std::size_t i = 0; i < p; ++i)
    inv[i][i] = 1;
  for (std::size_t k = 0; k < p; ++k) {
    std::size_t piv = k;
    for (std::size_t i = k + 1; i < p; ++i)
      if (std::abs(a[i][k]) > std::abs(a[piv][k]))
        piv = i;
    std::swap(a[k], a[piv]);
    std::swap(inv[k], inv[piv]);
    if (std::abs(a[k][k]) < 1e-12) {
      c.notes.push_back("the Jacobian is rank deficient (column " + std::to_string(k + 1) +
                        " is a combination of the others): uncertainties are not available");
      const double nan = std::numeric_limits<double>::quiet_NaN();
      c.matrix.assign(p, std::vector<double>(p, nan));
      c.correlation.assign(p, std::vector<double>(p, nan));
      return c;
    }
    const double d = a[k][k];
    for (std::size_t j = 0; j < p; ++j) {
      a[k][j] /= d;
      inv[k][j] /= d;
    }
    for (std::size_t i = 0; i < p; ++i)
      if (i != k) {
        const double f = a[i][k];
        for (std::size_t j = 0; j < p; ++j) {
          a[i][j] -= f * a[k][j];
          inv[i][j] -= f * inv[k][j];
        }
      }
  }
  const double s2 = n > p ? chi2 / static_cast<double>(n - p) : 1.0;
  c.matrix.assign(p, std::vector<double>(p, 0.0));
  c.correlation.assign(p, std::vector<double>(p, 0.0));
  for (std::size_t i = 0; i < p; ++i)
    for (std::size_t j = 0; j < p; ++j)
      c.matrix[i][j] = s2 * inv[i][j] * scale[i] * scale[j];
  for (std::size_t i = 0; i < p; ++i)
    for (std::size_t j = 0; j < p; ++j)
      c.correlation[i][j] = c.matrix[i][j] / std::sqrt(c.matrix[i][i] * c.matrix[j][j]);
  return c;
}

} // namespace fiberbridge::identify
