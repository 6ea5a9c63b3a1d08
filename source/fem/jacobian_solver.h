#pragma once
// The linear solver of the condensed Jacobian as a strategy (docs/design.md section 2, "One
// engine": in the style of ASPECT's Stokes-solver interface). The model says what changed (the
// interface tangents, the constraint set); the strategy decides whether to factorize again, to
// correct by a low-rank update, or to set up its preconditioner again.
#include "fiberbridge/fem/dcb_simulation.h"
#include "mpi_algebra.h"

#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <array>
#include <memory>
#include <vector>

namespace fiberbridge::fem {

/// What a strategy needs from the model: the condensed Jacobian for given interface tangents
/// and the condensed opening operator of one interface point (a column of the low-rank terms).
class JacobianSystem {
public:
  virtual ~JacobianSystem() = default;
  /// Assembles the condensed Jacobian of the current constraint set into `jacobian` (its
  /// pattern is rebuilt when the constraint set changed).
  virtual void assemble_jacobian(const std::vector<double>& tangents,
                                 dealii::TrilinosWrappers::SparseMatrix& jacobian) = 0;
  /// c with c . u = the opening of interface point p, condensed like a residual.
  virtual void opening_operator(unsigned p, Vec& c) = 0;
  virtual const dealii::IndexSet& owned_dofs() const = 0;
  virtual MPI_Comm communicator() const = 0;
};

/// Counters of the linear algebra, for the run's summary (the times are the model's
/// TimerOutput sections "factorize" and "solve").
struct JacobianSolverStats {
  unsigned n_factorizations = 0; ///< Jacobian assemblies + factorizations (or AMG setups)
  unsigned n_linear_solves = 0;
  // FEM/Linear solver = condensed (condensed_solver.h): its updates of the explicit inverse.
  unsigned n_bordered = 0;        ///< releases taken by bordering
  unsigned n_low_rank = 0;        ///< solves' tangent changes taken by the Woodbury identity
  unsigned n_folds = 0;           ///< pending tangent changes folded into the inverse
  unsigned n_refinements = 0;     ///< solves refined once for round-off drift
  unsigned n_drift_refreshes = 0; ///< inverses formed again for round-off drift
};

class JacobianSolver {
public:
  virtual ~JacobianSolver() = default;
  /// Brings the solver to the Jacobian with these interface tangents; `epoch` counts the
  /// constraint sets (a release starts a new one).
  virtual void update(const std::vector<double>& tangents, unsigned epoch) = 0;
  /// x = J^-1 rhs for the Jacobian of the last update().
  virtual void solve(const Vec& rhs, Vec& x) = 0;
  /// True when the matrix must be SPD: a softening point then enters with its secant.
  virtual bool needs_spd_tangents() const = 0;
  const JacobianSolverStats& stats() const { return stats_; }

protected:
  JacobianSolverStats stats_;
};

/// The rigid-body modes of the AMG near null space: each owned dof's component and support
/// point (by index within the owned set), with the centre the coordinates are taken from.
struct RigidBodyModes {
  unsigned dim = 2;
  std::vector<std::array<double, 4>> owned_support; ///< (component, x, y, z)
  std::array<double, 3> centre{{0, 0, 0}};
  std::vector<std::vector<bool>> constant_modes; ///< DoFTools::extract_constant_modes
};

/// FEM/Linear solver: Amesos KLU or MUMPS with the Woodbury update (`max_low_rank` changed
/// points at most), or CG + ML AMG. Factorizations (AMG setups) and solves are timed in the
/// sections "factorize" and "solve" of `timer`.
std::unique_ptr<JacobianSolver> make_jacobian_solver(const FemParameters& parameters,
                                                     JacobianSystem& system,
                                                     std::size_t max_low_rank, RigidBodyModes modes,
                                                     dealii::TimerOutput& timer);

} // namespace fiberbridge::fem
