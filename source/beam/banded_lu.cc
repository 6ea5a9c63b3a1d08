#include "banded_lu.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fiberbridge::beam::internal {

BandedLU::BandedLU(std::size_t n, std::size_t kl, std::size_t ku)
    : n_(n), kl_(kl), ku_(ku), width_(2 * kl + ku + 1), a_(n * width_, 0.0), pivot_(n, 0) {}

void BandedLU::set_zero() {
  std::fill(a_.begin(), a_.end(), 0.0);
}

bool BandedLU::factorize() {
  auto& A = *this;
  const std::size_t reach = kl_ + ku_; // upper bandwidth after fill-in
  for (std::size_t k = 0; k < n_; ++k) {
    const std::size_t last_row = std::min(n_ - 1, k + kl_);
    const std::size_t last_col = std::min(n_ - 1, k + reach);
    std::size_t p = k;
    for (std::size_t i = k + 1; i <= last_row; ++i)
      if (std::abs(A(i, k)) > std::abs(A(p, k)))
        p = i;
    pivot_[k] = p;
    if (A(p, k) == 0.0)
      return false;
    // As in dgbtrf, only the columns from k on are swapped: the multipliers stored left of k
    // belong to the row positions at the time they were computed and are applied in that order.
    if (p != k)
      for (std::size_t j = k; j <= last_col; ++j)
        std::swap(A(k, j), A(p, j));
    const double pivot = A(k, k);
    for (std::size_t i = k + 1; i <= last_row; ++i) {
      const double l = A(i, k) / pivot;
      A(i, k) = l;
      if (l != 0.0)
        for (std::size_t j = k + 1; j <= last_col; ++j)
          A(i, j) -= l * A(k, j);
    }
  }
  return true;
}

void BandedLU::solve(std::vector<double>& b) const {
  const auto& A = *this;
  for (std::size_t k = 0; k < n_; ++k) {
    std::swap(b[k], b[pivot_[k]]);
    const std::size_t last_row = std::min(n_ - 1, k + kl_);
    for (std::size_t i = k + 1; i <= last_row; ++i)
      b[i] -= A(i, k) * b[k];
  }
  for (std::size_t i = n_; i-- > 0;) {
    const std::size_t last_col = std::min(n_ - 1, i + kl_ + ku_);
    double s = b[i];
    for (std::size_t j = i + 1; j <= last_col; ++j)
      s -= A(i, j) * b[j];
    b[i] = s / A(i, i);
  }
}

} // namespace fiberbridge::beam::internal
