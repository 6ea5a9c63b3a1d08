// FEM/Linear solver = condensed (condensed_solver.h; docs/design.md section 2, "Condensed arms
// (issue 34 item 3)").
#include "condensed_solver.h"
#include "newton_loop.h"

#include "fiberbridge/core/error.h"

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_templates.h>
#include <deal.II/lac/trilinos_index_access.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

// LAPACK's condition estimate of an LU factorization (deal.II 9.4's lapack_templates.h does
// not wrap it).
extern "C" void dgecon_(const char* norm, const dealii::types::blas_int* n, const double* a,
                        const dealii::types::blas_int* lda, const double* anorm, double* rcond,
                        double* work, dealii::types::blas_int* iwork,
                        dealii::types::blas_int* info);

namespace fiberbridge::fem {

using namespace dealii;

namespace {

/// first + sum of a[k] b[k] over [from, to) in four partial sums: a single sum is a chain of
/// dependent additions that does not vectorize (the band solve's forward half took twice its
/// backward axpy half).
double dot(const double* a, const double* b, unsigned from, unsigned to, double first = 0) {
  double s0 = first, s1 = 0, s2 = 0, s3 = 0;
  unsigned k = from;
  for (; k + 4 <= to; k += 4) {
    s0 += a[k] * b[k];
    s1 += a[k + 1] * b[k + 1];
    s2 += a[k + 2] * b[k + 2];
    s3 += a[k + 3] * b[k + 3];
  }
  for (; k < to; ++k)
    s0 += a[k] * b[k];
  return (s0 + s1) + (s2 + s3);
}

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
      x[i] = (x[i] - dot(li, x, std::max(first_[i], from), i)) / li[i];
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

class Condensed : public CondensedSolver {
public:
  Condensed(CondensedArms arms, TimerOutput& timer) : arms_(std::move(arms)), timer_(timer) {
    setup();
    read_constraints(); // the initial tie set: refused here (ComputationError) if not ours
  }

  bool needs_spd_tangents() const override { return false; }

  void update(const std::vector<double>& tangents, unsigned epoch) override {
    const TimerOutput::Scope timed(timer_, "factorize");
    current_ = tangents;
    if (!follow_constraints(epoch))
      prepare_pending();
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
    write_full(r, x);
    ++stats_.n_linear_solves;
  }

  bool crack_plane_newton(Vec& u, const CrackPlaneForces& forces, unsigned epoch,
                          const NonlinearSettings& settings, double reaction_floor,
                          unsigned& used) override {
    used = 0;
    PlaneState cur;
    {
      const TimerOutput::Scope timed(timer_, "assembly");
      // v: the B values in the jump unknowns; lin = S' v from the B rows of K u (the interior
      // is in equilibrium: (K u)_B = S u_B), moved onto the jump unknowns like a residual.
      const double* uu = u.trilinos_vector()[0];
      const Epetra_CrsMatrix& K = arms_.bulk->trilinos_matrix();
      cur.v.resize(m_);
      cur.lin.assign(m_, 0.0);
      for (unsigned k = 0; k < m_; ++k) {
        cur.v[k] = uu[arms_.boundary[k]];
        int count = 0;
        double* values = nullptr;
        int* columns = nullptr;
        K.ExtractMyRowView(int(arms_.boundary[k]), count, values, columns);
        double row = 0;
        for (int e = 0; e < count; ++e)
          row += values[e] * uu[columns[e]];
        cur.lin[k] = row;
      }
      for (unsigned k = 0; k < m_; ++k)
        if (bottom_of_[k] >= 0) {
          cur.v[k] -= cur.v[bottom_of_[k]];
          cur.lin[bottom_of_[k]] += cur.lin[k];
        }
    }
    std::vector<double> tangents(point_vars_.size()), dv(m_), sdv(m_);
    {
      // The constraint set of this epoch first (a release frees unknowns: the residual of
      // their rows counts from now on).
      const TimerOutput::Scope timed(timer_, "factorize");
      for (unsigned p = 0; p < point_vars_.size(); ++p)
        tangents[p] = forces.interface->respond(p, opening(p, cur.v)).stiffness;
      current_ = tangents;
      follow_constraints(epoch); // the pending changes are prepared by the first update()
    }
    {
      const TimerOutput::Scope timed(timer_, "assembly");
      evaluate(cur, forces, reaction_floor);
    }
    // The one Newton loop (newton_loop.h) on the jumps: the same line search and test as the
    // full Newton's, on the same norm.
    struct PlaneNewton {
      Condensed& self;
      const CrackPlaneForces& forces;
      const unsigned epoch;
      const double tolerance, reaction_floor;
      PlaneState& cur;
      std::vector<double>& tangents;
      std::vector<double>& dv;
      std::vector<double>& sdv;
      PlaneState tried, best;

      bool converged() const { return cur.norm <= tolerance * cur.ref; }
      void direction() {
        for (unsigned p = 0; p < self.point_vars_.size(); ++p)
          tangents[p] = forces.interface->respond(p, self.opening(p, cur.v)).stiffness;
        self.update(tangents, epoch);
        self.step(cur, dv, sdv);
      }
      double merit() const { return cur.norm; }
      double trial(double alpha) {
        const TimerOutput::Scope timed(self.timer_, "assembly");
        tried.v = cur.v;
        tried.lin = cur.lin;
        for (unsigned k = 0; k < self.m_; ++k) {
          tried.v[k] += alpha * dv[k];
          tried.lin[k] += alpha * sdv[k];
        }
        self.evaluate(tried, forces, reaction_floor);
        return tried.norm;
      }
      void keep_trial(bool search_goes_on) {
        if (search_goes_on)
          best = tried; // kept only where the search goes on
      }
      bool accept(double /*alpha*/, bool last) {
        std::swap(cur, last ? tried : best);
        // (The full Newton also accepts a creeping step at its round-off floor, which is not
        // known here: such a run ends without decrease or at the iteration limit, and the full
        // Newton from u decides.)
        return false;
      }
    } newton{*this, forces, epoch, settings.tolerance, reaction_floor, cur, tangents, dv,
             sdv,   {},     {}};
    const NewtonStop stop = newton_loop(newton, settings.max_iterations, used);
    if (stop == NewtonStop::no_decrease)
      // The full Newton takes this iteration again from the same state (and counts it), where
      // its round-off floor and diagnosis decide.
      --used;
    write_state(cur.v, u);
    return stop == NewtonStop::converged;
  }

private:
  /// A crack-plane state: the unknowns (jumps), S' v, the residual on the unknowns, the norm of
  /// the condensed residual and the reaction norm of the convergence test.
  struct PlaneState {
    std::vector<double> v, lin, r;
    double norm = 0, ref = 0;
  };

  double opening(unsigned p, const std::vector<double>& v) const {
    double o = 0;
    for (const auto& [i, ni] : point_vars_[p])
      o += ni * v[i];
    return o;
  }

  /// r = S' v + the interface forces (on the jumps: a point's force acts +N on the top and -N
  /// on the bottom, so on a bottom unknown it cancels); the norm of the condensed residual in
  /// the physical unknowns, as the full model's (a free bottom under a free jump carries
  /// r_b = r'_b - r'_t; held unknowns none); the reaction norm from the load-line rows.
  void evaluate(PlaneState& s, const CrackPlaneForces& forces, double reaction_floor) const {
    s.r = s.lin;
    for (unsigned p = 0; p < point_vars_.size(); ++p) {
      if (!forces.active[p])
        continue;
      const double F = forces.interface->respond(p, opening(p, s.v)).force;
      if (F == 0)
        continue;
      for (const auto& [i, ni] : point_vars_[p])
        s.r[i] += ni * F;
    }
    double n2 = 0;
    for (unsigned k = 0; k < m_; ++k) {
      if (zero_[k])
        continue;
      double x = s.r[k];
      if (top_of_[k] >= 0 && !zero_[top_of_[k]])
        x -= s.r[top_of_[k]];
      n2 += x * x;
    }
    s.norm = std::sqrt(n2);
    double r2 = 0;
    for (const auto& [plus, minus] : reaction_rows_) {
      const double x = s.r[plus] - (minus >= 0 ? s.r[minus] : 0.0);
      r2 += x * x;
    }
    s.ref = std::max(std::sqrt(r2), reaction_floor);
  }

  /// The Newton step dv = -M^-1 r on the free unknowns and S' dv: on the free rows
  /// -r - T dv (M = S'_FF + T), on the held rows the reactions read from S' itself.
  void step(const PlaneState& s, std::vector<double>& dv, std::vector<double>& sdv) {
    const TimerOutput::Scope timed(timer_, "solve");
    for (unsigned a = 0; a < f_; ++a)
      rv_[a] = -s.r[var_[a]];
    dense_solve();
    ++stats_.n_linear_solves;
    std::fill(dv.begin(), dv.end(), 0.0);
    std::fill(sdv.begin(), sdv.end(), 0.0);
    for (unsigned a = 0; a < f_; ++a) {
      dv[var_[a]] = vf_[a];
      sdv[var_[a]] = rv_[a];
    }
    for (unsigned p = 0; p < point_vars_.size(); ++p)
      if (current_[p] != 0) {
        const double o = opening(p, dv);
        if (o != 0)
          for (const auto& [i, ni] : point_vars_[p])
            if (pos_[i] >= 0)
              sdv[i] -= current_[p] * ni * o;
      }
    for (const unsigned l : lpos_) {
      if (!zero_[l])
        continue; // a free row has its S' dv above
      double x = 0;
      for (unsigned a = 0; a < f_; ++a)
        x += sp_[std::size_t(l) * m_ + var_[a]] * vf_[a];
      sdv[l] = x;
    }
  }

  /// u from the crack-plane unknowns: u_B, then the interior u_I = -K_II^-1 K_IB u_B.
  void write_state(const std::vector<double>& v, Vec& u) {
    const TimerOutput::Scope timed(timer_, "solve");
    std::copy(v.begin(), v.end(), ub_.begin());
    write_full(nullptr, u);
  }

  /// x from the B unknowns in ub_ (jumps, turned into displacements here) and the interior
  /// x_I = K_II^-1 (r_I - K_IB u_B) (r null: no interior right-hand side).
  void write_full(const double* r, Vec& x) {
    for (unsigned k = 0; k < m_; ++k)
      if (bottom_of_[k] >= 0)
        ub_[k] += ub_[bottom_of_[k]];
    for (unsigned i = 0; i < n_i_; ++i)
      yi_[i] = r ? r[idof_[i]] : 0.0;
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
  }

  /// Relative residual of the dense solve above which it is refined once: a few hundred times
  /// the round-off of a fresh inverse (measured 3e-13 on the seed mesh), 10 times below the
  /// largest error accepted.
  static constexpr double kRefine = 1e-10;
  /// ... and after refinement, above which the inverse is formed again: far below what Newton
  /// notices (a step exact to 1e-9 relative converges as the exact one), far above round-off.
  static constexpr double kMaxDrift = 1e-9;
  /// Pending tangent changes (jumps) past which they are folded into G: a solve's Woodbury part
  /// costs O(f k + k^3), a fold O(k f^2); with f of a few hundred, a few dozen pending jumps
  /// cost less than a tenth of the solve's G r.
  static constexpr std::size_t kMaxPending = 48;
  /// Releases between two residual checks of G (see border()).
  static constexpr unsigned kCheckEvery = 8;
  /// Condition (1-norm, LAPACK's estimate) of the capacitance I + G_EE D above which each solve is
  /// checked: its round-off then reaches 1e-16 x 1e6 = 1e-10, the refinement threshold kRefine.
  static constexpr double kMaxCapacitanceCondition = 1e6;

  /// Brings G to the constraint set of `epoch` (current_: the tangents of a rebuild): a
  /// release borders it, anything else forms it again. True where G was formed again (no
  /// tangent change pending).
  bool follow_constraints(unsigned epoch) {
    if (!built_) {
      built_ = true;
      read_constraints();
      rebuild(current_);
      epoch_ = epoch;
      return true;
    }
    if (epoch == epoch_)
      return false;
    const std::vector<bool> before = zero_;
    read_constraints();
    epoch_ = epoch;
    std::vector<unsigned> added;
    for (unsigned k = 0; k < m_; ++k) {
      if (zero_[k] && !before[k]) { // a tie added: not a release, start again
        rebuild(current_);
        return true;
      }
      if (!zero_[k] && before[k])
        added.push_back(k);
    }
    if (!added.empty())
      border(added); // with the tangents G holds; the changed ones stay pending
    return false;
  }

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
    top_of_.assign(m_, -1);
    for (const auto& [t, b] : arms_.pairs) {
      if (bpos[t] < 0 || bpos[b] < 0)
        throw ComputationError("FEM/Linear solver = condensed: a crack-plane pair outside the "
                               "condensed dofs");
      bottom_of_[bpos[t]] = bpos[b];
      top_of_[bpos[b]] = bpos[t];
    }
    // A load-line dof may be a crack-plane dof too (a load line on the crack plane's end):
    // its reaction is then r_t = r'_t (a top) or r_b = r'_b - r'_t (a bottom).
    std::vector<bool> tracked(m_, false);
    for (const auto d : arms_.loads) {
      if (bpos[d] < 0)
        throw ComputationError("FEM/Linear solver = condensed: a load-line dof outside the "
                               "condensed dofs");
      const unsigned k = bpos[d];
      const int minus = top_of_[k];
      reaction_rows_.emplace_back(k, minus);
      tracked[k] = true;
      if (minus >= 0)
        tracked[minus] = true;
    }
    for (unsigned k = 0; k < m_; ++k)
      if (tracked[k])
        lpos_.push_back(k);
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
    pe_.clear(); // the tangents are all in G
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
      symmetrize();
    }
    applied_ = tangents;
    g_changed_ = true;
    ++stats_.n_factorizations;
  }

  /// Folds the pending tangent changes into G by the rank-k identity
  /// (M + E D E^T)^-1 = G - G E Q E^T G, Q = D (I + E^T G E D)^-1 (symmetric), on the free
  /// jumps E they touch. O(k f^2): only where too many changes are pending (prepare_pending()).
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
    // U = G_{:,E} (rows, by symmetry): G -= U Q U^T.
    std::vector<std::vector<double>> copies(k);
    std::vector<const double*> rows(k);
    for (unsigned a = 0; a < k; ++a) {
      const double* row = g_.data() + std::size_t(e[a]) * m_;
      copies[a].assign(row, row + f_);
      rows[a] = copies[a].data();
    }
    symmetric_update(rows, Q, -1.0);
    g_changed_ = true;
    ++stats_.n_folds;
  }

  /// G += sign U C U^T for a symmetric k x k C and U with the columns `columns` (each f long;
  /// they may be rows of G itself: copied first). Done as sum_l lambda_l h_l h_l^T over the
  /// eigenpairs of C, h_l = U v_l, each entry summed over l in the same order from the product
  /// h_l[i] h_l[j]: G stays exactly symmetric (the solves read rows for columns), so no pass
  /// that averages the two halves is needed, and the whole update is one pass over G.
  void symmetric_update(const std::vector<const double*>& columns, const FullMatrix<double>& C,
                        double sign) {
    const unsigned k = columns.size();
    std::vector<double> sym(std::size_t(k) * k);
    for (unsigned a = 0; a < k; ++a)
      for (unsigned b = 0; b < k; ++b)
        sym[std::size_t(b) * k + a] = 0.5 * (C(a, b) + C(b, a));
    const types::blas_int n = k;
    types::blas_int info = 0, lwork = -1;
    std::vector<double> lambda(k);
    double query = 0;
    syev("V", "U", &n, sym.data(), &n, lambda.data(), &query, &lwork, &info);
    lwork = types::blas_int(query);
    std::vector<double> work(std::max<types::blas_int>(lwork, 1));
    syev("V", "U", &n, sym.data(), &n, lambda.data(), work.data(), &lwork, &info);
    if (info != 0)
      throw ComputationError("FEM/Linear solver = condensed: no eigen-decomposition of a "
                             "low-rank update (LAPACK dsyev info " +
                             std::to_string(info) + ")");
    std::vector<std::vector<double>> h(k, std::vector<double>(f_, 0.0));
    for (unsigned l = 0; l < k; ++l) {
      lambda[l] *= sign;
      for (unsigned a = 0; a < k; ++a) {
        const double w = sym[std::size_t(l) * k + a];
        const double* col = columns[a];
        double* hl = h[l].data();
        for (unsigned i = 0; i < f_; ++i)
          hl[i] += col[i] * w;
      }
    }
    std::vector<double> t(f_);
    for (unsigned i = 0; i < f_; ++i) {
      std::fill(t.begin(), t.end(), 0.0);
      for (unsigned l = 0; l < k; ++l) {
        const double hi = h[l][i], lam = lambda[l];
        const double* hl = h[l].data();
        for (unsigned j = 0; j < f_; ++j)
          t[j] += (hi * hl[j]) * lam;
      }
      double* gi = g_.data() + std::size_t(i) * m_;
      for (unsigned j = 0; j < f_; ++j)
        gi[j] += t[j];
    }
  }

  /// Makes G exactly symmetric (after a Gauss-Jordan inverse, whose halves differ by round-off).
  void symmetrize() {
    for (unsigned i = 0; i < f_; ++i)
      for (unsigned j = 0; j < i; ++j) {
        double& a = g_[std::size_t(i) * m_ + j];
        double& b = g_[std::size_t(j) * m_ + i];
        a = b = 0.5 * (a + b);
      }
  }

  /// A release frees the released pairs' jumps: the new unknowns N border the system,
  /// [[M, b], [b^T, c]]^-1 = [[G + g s^-1 g^T, -g s^-1], [-s^-1 g^T, s^-1]], g = G b,
  /// s = c - b^T g. O(f^2 q) instead of O(f^3), in two passes over G (g, then the update).
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
    // g = G b, all q columns in one pass over G.
    std::vector<std::vector<double>> gb(q, std::vector<double>(f_, 0.0));
    for (unsigned r = 0; r < f_; ++r) {
      const double* gr = g_.data() + std::size_t(r) * m_;
      for (unsigned l = 0; l < q; ++l) {
        const double x = b[l][r];
        if (x == 0)
          continue;
        double* out = gb[l].data();
        for (unsigned a = 0; a < f_; ++a)
          out[a] += x * gr[a];
      }
    }
    FullMatrix<double> s(q, q);
    for (unsigned l1 = 0; l1 < q; ++l1)
      for (unsigned l2 = 0; l2 < q; ++l2) {
        double v = c(l1, l2);
        for (unsigned i = 0; i < f_; ++i)
          v -= b[l1][i] * gb[l2][i];
        s(l1, l2) = v;
      }
    s.gauss_jordan();
    for (unsigned l1 = 0; l1 < q; ++l1) // s^-1 symmetric (s is): exactly so
      for (unsigned l2 = 0; l2 < l1; ++l2)
        s(l1, l2) = s(l2, l1) = 0.5 * (s(l1, l2) + s(l2, l1));
    // gs = g s^-1 (columns): the new off-diagonal blocks, computed before G changes.
    std::vector<std::vector<double>> gs(q, std::vector<double>(f_, 0.0));
    for (unsigned l2 = 0; l2 < q; ++l2)
      for (unsigned l1 = 0; l1 < q; ++l1)
        for (unsigned i = 0; i < f_; ++i)
          gs[l2][i] += gb[l1][i] * s(l1, l2);
    std::vector<const double*> columns(q);
    for (unsigned l = 0; l < q; ++l)
      columns[l] = gb[l].data();
    symmetric_update(columns, s, 1.0);
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
    for (unsigned l = 0; l < q; ++l)
      for (unsigned i = 0; i < f_; ++i) {
        const double v = sp_[std::size_t(var_[i]) * m_ + added[l]];
        mf_[std::size_t(i) * m_ + pos_[added[l]]] = v;
        mf_[std::size_t(pos_[added[l]]) * m_ + i] = v;
      }
    // The residual check after every kCheckEvery-th release (and every rebuild and fold): a
    // bordering is exact up to round-off of O(f) terms, and the check costs a pass over S'.
    if (++borders_since_check_ >= kCheckEvery) {
      borders_since_check_ = 0;
      g_changed_ = true;
    }
    ++stats_.n_bordered;
  }

  double g(unsigned a, unsigned b) const { return g_[std::size_t(a) * m_ + b]; }

  /// v = M^-1 r by the explicit inverse, with one step of iterative refinement where the
  /// inverse has drifted (the updates accumulate round-off): the residual of every solve is
  /// measured, so no solve returns a step less exact than kMaxDrift; past it G is formed again.
  void dense_solve() {
    multiply_inverse(rv_, vf_);
    // The residual check after each change of G (rebuild, release, fold): G is only ever
    // changed by those, so the solves in between are as exact as the one checked.
    if (!g_changed_ && !check_each_solve_)
      return;
    g_changed_ = false;
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
      rebuild(current_);
      pe_.clear();
      g_changed_ = false;
      ++stats_.n_drift_refreshes;
      multiply_inverse(rv_, vf_);
    }
  }

  /// v = M^-1 r with M = S'_FF + the current tangents: G r (a sum of rows, G is symmetric:
  /// axpy loops vectorize, dot products do not), then the pending tangent changes by the
  /// Woodbury identity M^-1 r = y - G E D (I + G_EE D)^-1 y_E, y = G r.
  void multiply_inverse(const std::vector<double>& r, std::vector<double>& v) {
    symmetric_multiply(g_, r, v);
    const unsigned k = pe_.size();
    if (k == 0)
      return;
    for (unsigned a = 0; a < k; ++a)
      pz_[a] = v[pe_[a]];
    const types::blas_int n = k, one = 1;
    types::blas_int info = 0;
    getrs("N", &n, &one, pa_.data(), &n, pipiv_.data(), pz_.data(), &n, &info); // A^-1 y_E
    std::fill(pc_.begin(), pc_.end(), 0.0);
    for (unsigned b = 0; b < k; ++b)
      for (const auto& [a, d] : pd_[b]) // D z, column b
        pc_[a] += d * pz_[b];
    for (unsigned a = 0; a < k; ++a) {
      const double za = pc_[a];
      if (za == 0)
        continue;
      const double* ga = g_.data() + std::size_t(pe_[a]) * m_; // row = column (symmetric)
      double* out = v.data();
      for (unsigned i = 0; i < f_; ++i)
        out[i] -= za * ga[i];
    }
  }

  /// The points whose tangent differs from the one G holds, on the free jumps E they touch:
  /// D = sum (t - t_G) n n^T and the capacitance (I + G_EE D)^-1 for the solves. A tangent change
  /// thus costs O(f k) per solve instead of an O(k f^2) update of G; past kMaxPending jumps (the
  /// zone has grown or moved) the changes are folded into G (low_rank()), which then starts a
  /// fresh pending set.
  void prepare_pending() {
    pe_.clear();
    std::vector<int> local(f_, -1);
    std::vector<std::pair<unsigned, double>> changed;
    for (unsigned p = 0; p < point_vars_.size(); ++p)
      if (current_[p] != applied_[p]) {
        bool touches = false;
        for (const auto& [i, ni] : point_vars_[p])
          if (pos_[i] >= 0) {
            touches = true;
            if (local[pos_[i]] < 0) {
              local[pos_[i]] = int(pe_.size());
              pe_.push_back(pos_[i]);
            }
          }
        if (touches)
          changed.emplace_back(p, current_[p] - applied_[p]);
      }
    if (pe_.size() > kMaxPending) {
      pe_.clear();
      low_rank(current_);
      return;
    }
    const unsigned k = pe_.size();
    pz_.assign(k, 0.0);
    pc_.assign(k, 0.0);
    if (k == 0)
      return;
    // D by columns (each point couples the two or three jumps of its element: D is sparse).
    std::vector<double> dense(std::size_t(k) * k, 0.0);
    for (const auto& [p, dk] : changed)
      for (const auto& [i, ni] : point_vars_[p])
        for (const auto& [j, nj] : point_vars_[p])
          if (pos_[i] >= 0 && pos_[j] >= 0)
            dense[std::size_t(local[pos_[j]]) * k + local[pos_[i]]] += dk * ni * nj;
    pd_.assign(k, {});
    for (unsigned b = 0; b < k; ++b)
      for (unsigned c = 0; c < k; ++c)
        if (dense[std::size_t(b) * k + c] != 0)
          pd_[b].emplace_back(c, dense[std::size_t(b) * k + c]);
    // A = I + G_EE D, column-major for LAPACK: LU once per linearization, a solve per solve.
    pa_.assign(std::size_t(k) * k, 0.0);
    for (unsigned b = 0; b < k; ++b) {
      double* col = pa_.data() + std::size_t(b) * k;
      col[b] = 1.0;
      for (const auto& [c, d] : pd_[b])
        for (unsigned a = 0; a < k; ++a)
          col[a] += g(pe_[a], pe_[c]) * d;
    }
    const types::blas_int n = k;
    types::blas_int info = 0;
    std::vector<double> work(4 * std::size_t(k));
    const double norm_a = lange("1", &n, &n, pa_.data(), &n, work.data());
    pipiv_.assign(k, 0);
    getrf(&n, &n, pa_.data(), &n, pipiv_.data(), &info);
    // An ill-conditioned capacitance (M itself near singular) loses the accuracy the check on
    // G vouches for: the solves with it are then checked one by one. A singular one (info > 0)
    // is folded into G instead, where the check and the refresh handle it.
    if (info != 0) {
      pe_.clear();
      low_rank(current_);
      return;
    }
    double rcond = 0;
    std::vector<types::blas_int> iwork(k);
    dgecon_("1", &n, pa_.data(), &n, &norm_a, &rcond, work.data(), iwork.data(), &info);
    check_each_solve_ = !(rcond * kMaxCapacitanceCondition > 1);
    ++stats_.n_low_rank;
  }

  void symmetric_multiply(const std::vector<double>& A, const std::vector<double>& x,
                          std::vector<double>& y) const {
    // Only the upper triangle is read (A is exactly symmetric): the product streams half the
    // matrix, which is what it costs (a few hundred kB to MB, past the L2 cache).
    double* out = y.data();
    const double* xs = x.data();
    std::fill(out, out + f_, 0.0);
    for (unsigned b = 0; b < f_; ++b) {
      const double xb = xs[b];
      const double* ab = A.data() + std::size_t(b) * m_;
      if (xb != 0)
        for (unsigned a = b + 1; a < f_; ++a)
          out[a] += xb * ab[a];
      out[b] += dot(ab, xs, b + 1, f_, ab[b] * xb);
    }
  }

  /// |M v - r| / |r| for the right-hand side rv_ (M v kept in mv_), M = S'_FF + the current
  /// tangents.
  double drift(const std::vector<double>& v) {
    symmetric_multiply(mf_, v, mv_);
    for (unsigned p = 0; p < point_vars_.size(); ++p)
      if (current_[p] != 0) {
        double o = 0;
        for (const auto& [i, ni] : point_vars_[p])
          if (pos_[i] >= 0)
            o += ni * v[pos_[i]];
        if (o != 0)
          for (const auto& [i, ni] : point_vars_[p])
            if (pos_[i] >= 0)
              mv_[pos_[i]] += current_[p] * ni * o;
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
  std::vector<int> top_of_;    ///< B index of a bottom's top partner, -1 for others
  /// The reactions: r'[first] - r'[second] (second -1: none), one per load-line dof.
  std::vector<std::pair<unsigned, int>> reaction_rows_;
  std::vector<unsigned> lpos_; ///< B indices whose S' v the reactions read
  std::vector<double> sp_;     ///< P^T S P (m x m)
  std::vector<std::vector<std::pair<unsigned, double>>> point_vars_;
  std::vector<bool> zero_;      ///< unknowns held at zero by the current constraints
  std::vector<int> pos_;        ///< position of an unknown in G, -1 when held
  std::vector<unsigned> var_;   ///< unknown at a position of G
  std::vector<double> g_;       ///< the explicit inverse (stride m)
  std::vector<double> applied_; ///< the tangents G includes
  std::vector<double> current_; ///< the tangents of the last update()
  /// The pending changes current_ - applied_ (prepare_pending()): the jumps E (positions in
  /// G), D on them, the inverse capacitance (I + G_EE D)^-1, and y_E of a solve.
  std::vector<unsigned> pe_;
  std::vector<std::vector<std::pair<unsigned, double>>> pd_; ///< D by columns
  std::vector<double> pa_;                                   ///< LU of I + G_EE D
  std::vector<types::blas_int> pipiv_;
  std::vector<double> pz_, pc_;
  bool g_changed_ = true;         ///< G changed since the last checked solve
  bool check_each_solve_ = false; ///< the capacitance is ill-conditioned
  unsigned borders_since_check_ = 0;
  bool built_ = false;
  unsigned epoch_ = ~0u;
  std::vector<double> yi_, rb_, ub_, rv_, vf_, mv_, res_, dv_;
  std::vector<double> mf_; ///< S'_FF by positions in G (stride m)
};

} // namespace

std::unique_ptr<CondensedSolver> make_condensed_solver(CondensedArms arms, TimerOutput& timer) {
  return std::make_unique<Condensed>(std::move(arms), timer);
}

} // namespace fiberbridge::fem
