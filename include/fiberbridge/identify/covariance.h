#pragma once
// Parameter covariance of a weighted least-squares fit from the Jacobian of its residuals at the
// optimum: C = s^2 (J^T J)^-1 with s^2 = chi^2/(n - p) (the residuals' own scatter scales the
// stated one), and the correlation matrix.
#include <string>
#include <vector>

namespace fiberbridge::identify {

struct Covariance {
  std::vector<std::vector<double>> matrix;      ///< p x p, in the parameters' units squared
  std::vector<std::vector<double>> correlation; ///< p x p, 1 on the diagonal
  std::vector<std::string> notes;               ///< a singular J^T J says which column
};

/// jacobian[i][j] = d r_i / d p_j (n rows, p columns, n > p).
Covariance covariance_from_jacobian(const std::vector<std::vector<double>>& jacobian, double chi2);

} // namespace fiberbridge::identify
