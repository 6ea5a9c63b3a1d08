#pragma once
// The small interface the nonlinear solvers drive (docs/design.md section 2, "One engine"): one
// Newton with backtracking line search and one SUNDIALS KINSOL coupling solve the same condensed
// residual with the same Jacobian and the same convergence test.
#include "mpi_algebra.h"

#include <string>

namespace fiberbridge::fem {

class EquilibriumProblem {
public:
  virtual ~EquilibriumProblem() = default;
  virtual void reinit_vector(Vec& v) const = 0;
  virtual MPI_Comm communicator() const = 0;
  virtual double n_dofs() const = 0;
  /// r_full = K u + interface forces (its load-line rows are the reactions); r = r_full condensed.
  virtual void residual(const Vec& u, Vec& r, Vec& r_full) = 0;
  /// The reference of the convergence test: the load-line reaction norm of r_full (> 0).
  virtual double reaction_norm(const Vec& r_full) const = 0;
  /// The norm of the convergence test (identical on every rank).
  virtual double norm(const Vec& v) const = 0;
  /// Linearizes at u (the model's state becomes u).
  virtual void setup_jacobian(const Vec& u) = 0;
  /// Newton reports the residual reduction of its last step (new norm / old norm): a model may
  /// keep an older Jacobian while the steps contract well (a chord step). Without a report since
  /// the last linearization (KINSOL) the model linearizes afresh.
  virtual void note_contraction(double /*ratio*/) {}
  /// x = J^-1 rhs with the tied dofs following their partners.
  virtual void solve_jacobian(const Vec& rhs, Vec& x) = 0;
  /// Residual norm below which round-off of the terms that cancel in K u rules.
  virtual double roundoff_floor(const Vec& u) const = 0;
  /// "; N crack-face points in contact ..." of the model's current state, for a diagnosis.
  virtual std::string contact_summary() = 0;
};

/// Convergence test of both solvers: residual norm <= tolerance x reaction norm within
/// max_iterations (or at the round-off floor).
struct NonlinearSettings {
  double tolerance = 1e-9;
  unsigned max_iterations = 25;
  /// Iterations already spent on this solve by the crack-plane Newton (condensed_solver.h), whose
  /// state the full Newton continues from with what is left of the budget: only for the count
  /// a failure names.
  unsigned spent = 0;
};

/// Newton with backtracking line search from u (the predictor) to equilibrium. Returns false
/// with a diagnosis when it fails; counts its iterations into n_iterations.
bool newton_solve(EquilibriumProblem& problem, Vec& u, const NonlinearSettings& settings,
                  unsigned& n_iterations, std::string& diagnosis);

/// The same with SUNDIALS KINSOL (line-search strategy); `opening` scales its step tolerance.
/// Its result is re-checked against the Newton test (docs/design.md section 7).
bool kinsol_solve(EquilibriumProblem& problem, Vec& u, const NonlinearSettings& settings,
                  double opening, unsigned& n_iterations, std::string& diagnosis);

} // namespace fiberbridge::fem
