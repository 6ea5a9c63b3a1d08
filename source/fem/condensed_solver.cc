// FEM/Linear solver = condensed (condensed_solver.h; docs/design.md section 2, "Condensed arms
// (issue 34 item 3)").
#include "condensed_solver.h"

#include "fiberbridge/core/error.h"

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_templates.h>
#include <deal.II/lac/trilinos_index_access.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace fiberbridge::fem {

using namespace dealii;

namespace {

/// Profile (skyline) Cholesky of an SPD matrix: row i keeps its columns first[i]..i. The arms'
/// interior ordered along x is a band of a few dozen columns, so the profile is the band.
class ProfileCholesky {
public:
  /// `lower`: per row, (column <= row, value), duplicates summed.
  void factorize(const std::vector<std::vector<std::pair<unsigned, double>>>& lower) {
    n_ = lower.size();
    first_.assign(n_, 0);
    start_.assign(n_ + 1, 0);
    for (unsigned i = 0; i < n_; ++i) {
      unsigned f = i;
      for (const auto& [c, v] : lower[i])
        f = std::min(f, c);
      first_[i] = f;
      start_[i + 1] = start_[i] + (i - f + 1);
    }
    a_.assign(start_[n_], 0.0);
    for (unsigned i = 0; i < n_; ++i)
      for (const auto& [c, v] : lower[i])
        row(i)[c] += v;
    for (unsigned i = 0; i < n_; ++i) {
      double* li = row(i);
      for (unsigned j = first_[i]; j < i; ++j) {
        const double* lj = row(j);
        double s = li[j];
        for (unsigned k = std::max(first_[i], first_[j]); k < j; ++k)
          s -= li[k] * lj[k];
        li[j] = s / lj[j];
      }
      double s = li[i];
      for (unsigned k = first_[i]; k < i; ++k)
        s -= li[k] * li[k];
      if (!(s > 0))
        throw ComputationError("FEM/Linear solver = condensed: the arms' interior stiffness is "
                               "not positive definite (mesh generation error)");
      li[i] = std::sqrt(s);
    }
    // Independent blocks (the two arms): a block starts at r when no later row reaches before r.
    block_start_.assign(n_, 0);
    block_end_.assign(n_, n_);
    std::vector<unsigned> reach(n_ + 1, n_);
    for (unsigned r = n_; r-- > 0;)
      reach[r] = std::min(reach[r + 1], first_[r]);
    unsigned s0 = 0;
    for (unsigned r = 0; r < n_; ++r) {
      if (reach[r] == r)
        s0 = r;
      block_start_[r] = s0;
    }
    unsigned e = n_;
    for (unsigned r = n_; r-- > 0;) {
      block_end_[r] = e;
      if (block_start_[r] == r)
        e = r;
    }
  }

  /// x <- A^-1 x, where x is zero outside [from, to) and the rows [from, to) lie in blocks that
  /// end at `to` at the latest (to = size(): any right-hand side).
  void solve(double* x, unsigned from, unsigned to) const {
    for (unsigned i = from; i < to; ++i) {
      const double* li = row(i);
      double s = x[i];
      for (unsigned k = std::max(first_[i], from); k < i; ++k)
        s -= li[k] * x[k];
      x[i] = s / li[i];
    }
    const unsigned bottom = from < n_ ? block_start_[from] : n_;
    for (unsigned i = to; i-- > bottom;) {
      const double* li = row(i);
      x[i] /= li[i];
      const double xi = x[i];
      for (unsigned k = first_[i]; k < i; ++k)
        x[k] -= li[k] * xi;
    }
  }
  unsigned size() const { return n_; }
  unsigned block_end(unsigned r) const { return block_end_[r]; }
  unsigned block_start(unsigned r) const { return block_start_[r]; }

private:
  double* row(unsigned i) { return a_.data() + start_[i] - first_[i]; }
  const double* row(unsigned i) const { return a_.data() + start_[i] - first_[i]; }
  unsigned n_ = 0;
  std::vector<unsigned> first_, block_start_, block_end_;
  std::vector<std::size_t> start_;
  std::vector<double> a_;
};

class Condensed : public JacobianSolver {
public:
  Condensed(CondensedArms arms, TimerOutput& timer) : arms_(std::move(arms)), timer_(timer) {
    setup();
    read_constraints(); // the initial tie set: refused here (ComputationError) if not ours
  }

  bool needs_spd_tangents() const override { return false; }

  void update(const std::vector<double>& tangents, unsigned epoch) override {
    const TimerOutput::Scope timed(timer_, "factorize");
    if (!built_) {
      built_ = true;
      read_constraints();
      rebuild(tangents);
      epoch_ = epoch;
      return;
    }
    if (epoch != epoch_) {
      const std::vector<bool> before = zero_;
      read_constraints();
      epoch_ = epoch;
      std::vector<unsigned> added;
      for (unsigned k = 0; k < m_; ++k) {
        if (zero_[k] && !before[k]) { // a tie added: not a release, start again
          rebuild(tangents);
          return;
        }
        if (!zero_[k] && before[k])
          added.push_back(k);
      }
      low_rank(tangents);
      if (!added.empty())
        border(added);
      return;
    }
    low_rank(tangents);
  }

  void solve(const Vec& rhs, Vec& x) override {
    const TimerOutput::Scope timed(timer_, "solve");
    const double* r = rhs.trilinos_vector()[0];
    // y_I = K_II^-1 r_I; the Schur right-hand side r_B - K_BI y_I, in the jump unknowns.
    for (unsigned i = 0; i < n_i_; ++i)
      yi_[i] = r[idof_[i]];
    chol_.solve(yi_.data(), 0, n_i_);
    for (unsigned k = 0; k < m_; ++k) {
      double s = r[arms_.boundary[k]];
      for (const auto& [c, v] : kbi_[k])
        s -= v * yi_[c];
      rb_[k] = s;
    }
    for (unsigned k = 0; k < m_; ++k)
      if (bottom_of_[k] >= 0)
        rb_[bottom_of_[k]] += rb_[k];
    for (unsigned a = 0; a < f_; ++a)
      rv_[a] = rb_[var_[a]];
    dense_solve();
    // u_B from the unknowns (jumps back to top displacements), then x_I = K_II^-1 (r_I - K_IB u_B).
    std::fill(ub_.begin(), ub_.end(), 0.0);
    for (unsigned a = 0; a < f_; ++a)
      ub_[var_[a]] = vf_[a];
    for (unsigned k = 0; k < m_; ++k)
      if (bottom_of_[k] >= 0)
        ub_[k] += ub_[bottom_of_[k]];
    for (unsigned i = 0; i < n_i_; ++i)
      yi_[i] = r[idof_[i]];
    for (unsigned k = 0; k < m_; ++k)
      if (ub_[k] != 0)
        for (const auto& [c, v] : kbi_[k])
          yi_[c] -= v * ub_[k];
    chol_.solve(yi_.data(), 0, n_i_);
    double* out = x.trilinos_vector()[0];
    for (unsigned i = 0; i < n_i_; ++i)
      out[idof_[i]] = yi_[i];
    for (unsigned k = 0; k < m_; ++k)
      out[arms_.boundary[k]] = ub_[k];
    ++stats_.n_linear_solves;
  }

private:
  /// Relative residual of the dense solve above which it is refined once: a few hundred times
  /// the round-off of a fresh inverse (measured 3e-13 on the seed mesh), 10 times below the
  /// largest error accepted.
  static constexpr double kRefine = 1e-10;
  /// ... and after refinement, above which the inverse is formed again: far below what Newton
  /// notices (a step exact to 1e-9 relative converges as the exact one), far above round-off.
  static constexpr double kMaxDrift = 1e-9;

  /// Once per mesh (inside the model's "setup" section): K_II factorized, S formed.
  void setup() {
    const auto& K = *arms_.bulk;
    const unsigned n = K.m();
    m_ = arms_.boundary.size();
    std::vector<int> bpos(n, -1);
    for (unsigned k = 0; k < m_; ++k)
      bpos[arms_.boundary[k]] = int(k);
    bpos_ = bpos;
    // I along the arms: x-major within each arm, so its stiffness is a narrow band.
    for (unsigned d = 0; d < n; ++d)
      if (bpos[d] < 0)
        idof_.push_back(d);
    std::sort(idof_.begin(), idof_.end(),
              [&](unsigned a, unsigned b) { return arms_.order[a] < arms_.order[b]; });
    n_i_ = idof_.size();
    std::vector<int> ipos(n, -1);
    for (unsigned i = 0; i < n_i_; ++i)
      ipos[idof_[i]] = int(i);
    std::vector<std::vector<std::pair<unsigned, double>>> lower(n_i_);
    kbi_.assign(m_, {});
    std::vector<double> S(std::size_t(m_) * m_, 0.0);
    // The rows by Epetra's local views (deal.II's row iterator copies each row per entry).
    const Epetra_CrsMatrix& A = K.trilinos_matrix();
    for (int lr = 0; lr < A.NumMyRows(); ++lr) {
      int count = 0;
      double* values = nullptr;
      int* columns = nullptr;
      A.ExtractMyRowView(lr, count, values, columns);
      const unsigned r = TrilinosWrappers::global_row_index(A, lr);
      for (int e = 0; e < count; ++e) {
        const unsigned c = TrilinosWrappers::global_column_index(A, columns[e]);
        const double v = values[e];
        if (v == 0)
          continue;
        if (ipos[r] >= 0 && ipos[c] >= 0) {
          if (ipos[c] <= ipos[r])
            lower[ipos[r]].emplace_back(unsigned(ipos[c]), v);
        } else if (bpos[r] >= 0 && ipos[c] >= 0)
          kbi_[bpos[r]].emplace_back(unsigned(ipos[c]), v);
        else if (bpos[r] >= 0 && bpos[c] >= 0)
          S[std::size_t(bpos[r]) * m_ + bpos[c]] += v;
      }
    }
    chol_.factorize(lower);
    // S = K_BB - K_BI K_II^-1 K_IB, a column per B dof (K_IB = K_BI^T: K is symmetric); each
    // right-hand side sits in one arm near its dof, so the solve covers that arm's band only.
    yi_.assign(n_i_, 0.0);
    for (unsigned j = 0; j < m_; ++j) {
      if (kbi_[j].empty())
        continue;
      unsigned from = n_i_, to = 0;
      for (const auto& [c, v] : kbi_[j]) {
        yi_[c] += v;
        from = std::min(from, c);
        to = std::max(to, chol_.block_end(c));
      }
      chol_.solve(yi_.data(), from, to);
      for (unsigned i = 0; i < m_; ++i) {
        double s = 0;
        for (const auto& [c, v] : kbi_[i])
          s += v * yi_[c];
        S[std::size_t(i) * m_ + j] -= s;
      }
      std::fill(yi_.begin() + chol_.block_start(from), yi_.begin() + to, 0.0);
    }
    // The jump unknowns: for a pair (t, b) the unknown at t is u_t - u_b, so u = P v with
    // u_t = v_t + v_b; the condensed matrix is P^T S P, symmetrized (round-off only).
    bottom_of_.assign(m_, -1);
    for (const auto& [t, b] : arms_.pairs) {
      if (bpos[t] < 0 || bpos[b] < 0)
        throw ComputationError("FEM/Linear solver = condensed: a crack-plane pair outside the "
                               "condensed dofs");
      bottom_of_[bpos[t]] = bpos[b];
    }
    for (unsigned t = 0; t < m_; ++t)
      if (bottom_of_[t] >= 0) {
        const unsigned b = bottom_of_[t];
        for (unsigned j = 0; j < m_; ++j)
          S[std::size_t(b) * m_ + j] += S[std::size_t(t) * m_ + j];
      }
    for (unsigned t = 0; t < m_; ++t)
      if (bottom_of_[t] >= 0) {
        const unsigned b = bottom_of_[t];
        for (unsigned i = 0; i < m_; ++i)
          S[std::size_t(i) * m_ + b] += S[std::size_t(i) * m_ + t];
      }
    sp_.assign(S.size(), 0.0);
    for (unsigned i = 0; i < m_; ++i)
      for (unsigned j = 0; j < m_; ++j)
        sp_[std::size_t(i) * m_ + j] =
            0.5 * (S[std::size_t(i) * m_ + j] + S[std::size_t(j) * m_ + i]);
    // Interface points on the jump unknowns (the opening of the nodes' vertical jumps).
    for (const auto& nodes : arms_.points) {
      std::vector<std::pair<unsigned, double>> v;
      for (const auto& [top, w] : nodes) {
        if (bpos[top] < 0 || bottom_of_[bpos[top]] < 0)
          throw ComputationError("FEM/Linear solver = condensed: an interface node outside the "
                                 "crack-plane pairs");
        v.emplace_back(unsigned(bpos[top]), w);
      }
      point_vars_.push_back(std::move(v));
    }
    g_.assign(std::size_t(m_) * m_, 0.0);
    pos_.assign(m_, -1);
    zero_.assign(m_, true);
    rb_.assign(m_, 0.0);
    ub_.assign(m_, 0.0);
    rv_.assign(m_, 0.0);
    vf_.assign(m_, 0.0);
    mv_.assign(m_, 0.0);
    res_.assign(m_, 0.0);
    dv_.assign(m_, 0.0);
    mf_.assign(std::size_t(m_) * m_, 0.0);
  }

  /// The free unknowns of the current tie set. A constrained dof fixes its own unknown at zero:
  /// a tie u_t = u_b fixes the jump; a prescribed dof fixes itself (a prescribed top whose
  /// bottom is prescribed too has a zero jump). Anything else is not this strategy's.
  void read_constraints() {
    const auto& c = *arms_.constraints;
    zero_.assign(m_, false);
    for (const auto& line : c.get_lines()) {
      const int k = line.index < bpos_.size() ? bpos_[line.index] : -1;
      bool ok = k >= 0;
      if (ok && !line.entries.empty())
        ok = bottom_of_[k] >= 0 && line.entries.size() == 1 &&
             line.entries[0].first == arms_.boundary[bottom_of_[k]] &&
             line.entries[0].second == 1.0;
      else if (ok && bottom_of_[k] >= 0)
        ok = c.is_constrained(arms_.boundary[bottom_of_[k]]) &&
             c.get_constraint_entries(arms_.boundary[bottom_of_[k]])->empty();
      if (!ok)
        throw ComputationError("FEM/Linear solver = condensed: a constraint other than a tie or "
                               "a prescribed crack-plane or load-line dof (use klu)");
      zero_[k] = true;
    }
  }

  /// Forms G = (S'_FF + T_FF)^-1 from scratch: O(f^3), once per run unless round-off drift.
  void rebuild(const std::vector<double>& tangents) {
    var_.clear();
    std::fill(pos_.begin(), pos_.end(), -1);
    for (unsigned k = 0; k < m_; ++k)
      if (!zero_[k]) {
        pos_[k] = int(var_.size());
        var_.push_back(k);
      }
    f_ = var_.size();
    for (unsigned a = 0; a < f_; ++a)
      for (unsigned b = 0; b < f_; ++b)
        g_[std::size_t(a) * m_ + b] = mf_[std::size_t(a) * m_ + b] =
            sp_[std::size_t(var_[a]) * m_ + var_[b]];
    for (unsigned p = 0; p < point_vars_.size(); ++p)
      if (tangents[p] != 0)
        for (const auto& [i, ni] : point_vars_[p])
          for (const auto& [j, nj] : point_vars_[p])
            if (pos_[i] >= 0 && pos_[j] >= 0)
              g_[std::size_t(pos_[i]) * m_ + pos_[j]] += tangents[p] * ni * nj;
    // Cholesky (LAPACK potrf + potri, half the work of LU) where M is positive definite, as at
    // the start of a run (no softening point yet); Gauss-Jordan otherwise.
    const types::blas_int n = f_, lda = m_;
    types::blas_int info = 0;
    std::vector<double> copy(g_.begin(), g_.begin() + std::size_t(f_) * m_);
    potrf("U", &n, g_.data(), &lda, &info);
    if (info == 0)
      potri("U", &n, g_.data(), &lda, &info);
    if (info == 0) { // the upper triangle in column-major = the lower one here: mirror it
      for (unsigned a = 0; a < f_; ++a)
        for (unsigned b = 0; b < a; ++b)
          g_[std::size_t(b) * m_ + a] = g_[std::size_t(a) * m_ + b];
    } else {
      FullMatrix<double> M(f_, f_);
      for (unsigned a = 0; a < f_; ++a)
        for (unsigned b = 0; b < f_; ++b)
          M(a, b) = copy[std::size_t(a) * m_ + b];
      M.gauss_jordan();
      for (unsigned a = 0; a < f_; ++a)
        for (unsigned b = 0; b < f_; ++b)
          g_[std::size_t(a) * m_ + b] = M(a, b);
    }
    applied_ = tangents;
    ++stats_.n_factorizations;
  }

  /// The points whose tangent changed since G was formed enter by the rank-k identity
  /// (M + E D E^T)^-1 = G - G E D (I + E^T G E D)^-1 E^T G on the free jumps E they touch.
  void low_rank(const std::vector<double>& tangents) {
    std::vector<unsigned> e; // positions in G
    std::vector<int> local(f_, -1);
    std::vector<std::pair<unsigned, double>> changed;
    for (unsigned p = 0; p < point_vars_.size(); ++p)
      if (tangents[p] != applied_[p]) {
        changed.emplace_back(p, tangents[p] - applied_[p]);
        applied_[p] = tangents[p];
        for (const auto& [i, ni] : point_vars_[p])
          if (pos_[i] >= 0 && local[pos_[i]] < 0) {
            local[pos_[i]] = int(e.size());
            e.push_back(pos_[i]);
          }
      }
    const unsigned k = e.size();
    if (k == 0)
      return;
    FullMatrix<double> D(k, k);
    for (const auto& [p, dk] : changed)
      for (const auto& [i, ni] : point_vars_[p])
        for (const auto& [j, nj] : point_vars_[p])
          if (pos_[i] >= 0 && pos_[j] >= 0)
            D(local[pos_[i]], local[pos_[j]]) += dk * ni * nj;
    // A = I + G_EE D, Q = D A^-1.
    FullMatrix<double> A(k, k), Q(k, k);
    for (unsigned a = 0; a < k; ++a)
      for (unsigned b = 0; b < k; ++b) {
        double s = a == b ? 1.0 : 0.0;
        for (unsigned c = 0; c < k; ++c)
          s += g(e[a], e[c]) * D(c, b);
        A(a, b) = s;
      }
    A.gauss_jordan();
    D.mmult(Q, A);
    // U = G_{:,E} (columns, as rows by symmetry), V = U Q; G -= V U^T.
    std::vector<std::vector<double>> U(k, std::vector<double>(f_)), V(k, std::vector<double>(f_));
    for (unsigned a = 0; a < k; ++a)
      for (unsigned i = 0; i < f_; ++i)
        U[a][i] = g(e[a], i);
    for (unsigned b = 0; b < k; ++b)
      for (unsigned i = 0; i < f_; ++i) {
        double s = 0;
        for (unsigned a = 0; a < k; ++a)
          s += U[a][i] * Q(a, b);
        V[b][i] = s;
      }
    for (unsigned i = 0; i < f_; ++i) {
      double* gi = g_.data() + std::size_t(i) * m_;
      for (unsigned b = 0; b < k; ++b) {
        const double vib = V[b][i];
        const double* ub = U[b].data();
        for (unsigned j = 0; j < f_; ++j)
          gi[j] -= vib * ub[j];
      }
    }
    symmetrize();
    ++stats_.n_low_rank;
  }

  /// G is symmetric (M is); the updates use rows for columns, so round-off asymmetry would feed
  /// back into every later update: average it out.
  void symmetrize() {
    constexpr unsigned tile = 32; // in tiles: the column walk stays in cache
    for (unsigned i0 = 0; i0 < f_; i0 += tile)
      for (unsigned j0 = 0; j0 <= i0; j0 += tile)
        for (unsigned i = i0; i < std::min(f_, i0 + tile); ++i)
          for (unsigned j = j0; j < std::min(i, j0 + tile); ++j) {
            double& a = g_[std::size_t(i) * m_ + j];
            double& b = g_[std::size_t(j) * m_ + i];
            a = b = 0.5 * (a + b);
          }
  }

  /// A release frees the released pairs' jumps: the new unknowns N border the system,
  /// [[M, b], [b^T, c]]^-1 = [[G + g s^-1 g^T, -g s^-1], [-s^-1 g^T, s^-1]], g = G b,
  /// s = c - b^T g. O(f^2 q) instead of O(f^3).
  void border(const std::vector<unsigned>& added) {
    const unsigned q = added.size();
    std::vector<int> nloc(m_, -1);
    for (unsigned l = 0; l < q; ++l)
      nloc[added[l]] = int(l);
    // Columns of the new unknowns over F (b) and over N (c), tangents included.
    std::vector<std::vector<double>> b(q, std::vector<double>(f_));
    FullMatrix<double> c(q, q);
    for (unsigned l = 0; l < q; ++l) {
      const std::size_t col = added[l];
      for (unsigned a = 0; a < f_; ++a)
        b[l][a] = sp_[std::size_t(var_[a]) * m_ + col];
      for (unsigned l2 = 0; l2 < q; ++l2)
        c(l2, l) = sp_[std::size_t(added[l2]) * m_ + col];
    }
    for (unsigned p = 0; p < point_vars_.size(); ++p) {
      if (applied_[p] == 0)
        continue;
      for (const auto& [j, nj] : point_vars_[p]) {
        if (nloc[j] < 0)
          continue;
        for (const auto& [i, ni] : point_vars_[p]) {
          const double t = applied_[p] * ni * nj;
          if (pos_[i] >= 0)
            b[nloc[j]][pos_[i]] += t;
          else if (nloc[i] >= 0)
            c(nloc[i], nloc[j]) += t;
        }
      }
    }
    std::vector<std::vector<double>> gb(q, std::vector<double>(f_, 0.0));
    for (unsigned l = 0; l < q; ++l)
      symmetric_multiply(g_, b[l], gb[l]);
    FullMatrix<double> s(q, q);
    for (unsigned l1 = 0; l1 < q; ++l1)
      for (unsigned l2 = 0; l2 < q; ++l2) {
        double v = c(l1, l2);
        for (unsigned i = 0; i < f_; ++i)
          v -= b[l1][i] * gb[l2][i];
        s(l1, l2) = v;
      }
    s.gauss_jordan();
    // gs = g s^-1 (columns), then the blocks.
    std::vector<std::vector<double>> gs(q, std::vector<double>(f_, 0.0));
    for (unsigned l2 = 0; l2 < q; ++l2)
      for (unsigned l1 = 0; l1 < q; ++l1)
        for (unsigned i = 0; i < f_; ++i)
          gs[l2][i] += gb[l1][i] * s(l1, l2);
    for (unsigned i = 0; i < f_; ++i) {
      double* gi = g_.data() + std::size_t(i) * m_;
      for (unsigned l = 0; l < q; ++l) {
        const double a = gs[l][i];
        const double* gl = gb[l].data();
        for (unsigned j = 0; j < f_; ++j)
          gi[j] += a * gl[j];
      }
    }
    for (unsigned l = 0; l < q; ++l) {
      const unsigned a = f_ + l;
      for (unsigned i = 0; i < f_; ++i) {
        g_[std::size_t(i) * m_ + a] = -gs[l][i];
        g_[std::size_t(a) * m_ + i] = -gs[l][i];
      }
      for (unsigned l2 = 0; l2 < q; ++l2)
        g_[std::size_t(a) * m_ + f_ + l2] = s(l, l2);
      pos_[added[l]] = int(a);
      var_.push_back(added[l]);
    }
    f_ += q;
    symmetrize();
    for (unsigned l = 0; l < q; ++l)
      for (unsigned i = 0; i < f_; ++i) {
        const double v = sp_[std::size_t(var_[i]) * m_ + added[l]];
        mf_[std::size_t(i) * m_ + pos_[added[l]]] = v;
        mf_[std::size_t(pos_[added[l]]) * m_ + i] = v;
      }
    ++stats_.n_bordered;
  }

  double g(unsigned a, unsigned b) const { return g_[std::size_t(a) * m_ + b]; }

  /// v = M^-1 r by the explicit inverse, with one step of iterative refinement where the
  /// inverse has drifted (the updates accumulate round-off): the residual of every solve is
  /// measured, so no solve returns a step less exact than kMaxDrift; past it G is formed again.
  void dense_solve() {
    multiply_inverse(rv_, vf_);
    double d = drift(vf_);
    if (d > kRefine) {
      for (unsigned a = 0; a < f_; ++a)
        res_[a] = rv_[a] - mv_[a];
      multiply_inverse(res_, dv_);
      for (unsigned a = 0; a < f_; ++a)
        vf_[a] += dv_[a];
      ++stats_.n_refinements;
      d = drift(vf_);
    }
    if (d > kMaxDrift) {
      rebuild(applied_);
      ++stats_.n_drift_refreshes;
      multiply_inverse(rv_, vf_);
    }
  }

  /// v = G r as a sum of rows (G is symmetric): axpy loops vectorize, dot products (a chain of
  /// dependent additions) do not.
  void multiply_inverse(const std::vector<double>& r, std::vector<double>& v) const {
    symmetric_multiply(g_, r, v);
  }

  void symmetric_multiply(const std::vector<double>& A, const std::vector<double>& x,
                          std::vector<double>& y) const {
    double* out = y.data();
    std::fill(out, out + f_, 0.0);
    for (unsigned b = 0; b < f_; ++b) {
      const double xb = x[b];
      if (xb == 0)
        continue;
      const double* ab = A.data() + std::size_t(b) * m_;
      for (unsigned a = 0; a < f_; ++a)
        out[a] += xb * ab[a];
    }
  }

  /// |M v - r| / |r| for the right-hand side rv_ (M v kept in mv_), M = S'_FF + the applied
  /// tangents.
  double drift(const std::vector<double>& v) {
    symmetric_multiply(mf_, v, mv_);
    for (unsigned p = 0; p < point_vars_.size(); ++p)
      if (applied_[p] != 0) {
        double o = 0;
        for (const auto& [i, ni] : point_vars_[p])
          if (pos_[i] >= 0)
            o += ni * v[pos_[i]];
        if (o != 0)
          for (const auto& [i, ni] : point_vars_[p])
            if (pos_[i] >= 0)
              mv_[pos_[i]] += applied_[p] * ni * o;
      }
    double num = 0, den = 0;
    for (unsigned a = 0; a < f_; ++a) {
      num += (mv_[a] - rv_[a]) * (mv_[a] - rv_[a]);
      den += rv_[a] * rv_[a];
    }
    return den > 0 ? std::sqrt(num / den) : 0.0;
  }

  CondensedArms arms_;
  TimerOutput& timer_;
  unsigned m_ = 0, n_i_ = 0, f_ = 0;
  std::vector<int> bpos_;                                     ///< B index of a dof, -1 in I
  std::vector<unsigned> idof_;                                ///< I in band order
  ProfileCholesky chol_;                                      ///< K_II
  std::vector<std::vector<std::pair<unsigned, double>>> kbi_; ///< K_BI rows (I in band order)
  std::vector<int> bottom_of_; ///< B index of a top's bottom partner, -1 for others
  std::vector<double> sp_;     ///< P^T S P (m x m)
  std::vector<std::vector<std::pair<unsigned, double>>> point_vars_;
  std::vector<bool> zero_;      ///< unknowns held at zero by the current constraints
  std::vector<int> pos_;        ///< position of an unknown in G, -1 when held
  std::vector<unsigned> var_;   ///< unknown at a position of G
  std::vector<double> g_;       ///< the explicit inverse (stride m)
  std::vector<double> applied_; ///< the tangents G includes
  bool built_ = false;
  unsigned epoch_ = ~0u;
  std::vector<double> yi_, rb_, ub_, rv_, vf_, mv_, res_, dv_;
  std::vector<double> mf_; ///< S'_FF by positions in G (stride m)
};

} // namespace

std::unique_ptr<JacobianSolver> make_condensed_solver(CondensedArms arms, TimerOutput& timer) {
  return std::make_unique<Condensed>(std::move(arms), timer);
}

} // namespace fiberbridge::fem
