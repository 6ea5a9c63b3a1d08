#pragma once
// A small banded LU with partial pivoting (LAPACK dgbtrf/dgbtrs layout of the algorithm, row-wise
// storage). The beam's tangent couples only neighbouring nodes, so a solve costs O(n); softening
// bridging tangents can make it indefinite, hence the pivoting. Private to the beam library.
#include <cstddef>
#include <vector>

namespace fiberbridge::beam::internal {

class BandedLU {
public:
  /// n x n matrix with kl sub- and ku super-diagonals; room for the kl extra super-diagonals
  /// that pivoting fills in.
  BandedLU(std::size_t n, std::size_t kl, std::size_t ku);

  void set_zero();
  /// Entry (i, j), |i - j| within the band (not checked in release builds).
  double& operator()(std::size_t i, std::size_t j) { return a_[i * width_ + (j + kl_ - i)]; }
  double operator()(std::size_t i, std::size_t j) const { return a_[i * width_ + (j + kl_ - i)]; }
  std::size_t size() const { return n_; }

  /// In-place factorization. Returns false when a pivot is exactly zero (singular matrix).
  bool factorize();
  /// Solves A x = b with the factors; b is overwritten by x.
  void solve(std::vector<double>& b) const;

private:
  std::size_t n_, kl_, ku_, width_;
  std::vector<double> a_;
  std::vector<std::size_t> pivot_;
};

} // namespace fiberbridge::beam::internal
