#pragma once
// FEM/Linear solver = condensed (docs/design.md section 2, "Condensed arms (issue 34 item 3)"):
// the JacobianSolver strategy that condenses the linear elastic arms onto the crack plane. The
// dofs split into B (crack-plane dofs of both arms, load-line dofs: every dof a constraint or an
// interface opening touches) and I (the rest). The bulk block K_II never changes: it is factorized
// once (a profile Cholesky: each arm is a slender band), and the Schur complement
// S = K_BB - K_BI K_II^-1 K_IB is formed once per mesh. On B the unknowns are each crack-plane
// pair's bottom displacement and its jump (top - bottom): a tie then fixes a jump at zero, so the
// tied condensed system is S (in these unknowns) restricted to the free ones plus the interface
// tangents. Its inverse is kept explicitly: a release adds the released jumps as new unknowns
// (a bordered inverse, O(m^2)); a tangent change is a low-rank update on the jumps it touches
// (O(k m^2)). The model's algorithm (Newton, controls, J, outputs) is untouched: this strategy
// solves the same systems as klu, without assembling or factorizing the Trilinos Jacobian.
// Serial (one rank), small-strain kinematics only.
#include "equilibrium_problem.h"
#include "jacobian_solver.h"

#include "fiberbridge/fem/cohesive_interface.h"

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace fiberbridge::fem {

/// What the condensed strategy reads from the model (all on one rank; dofs are global indices).
struct CondensedArms {
  using dof_index = dealii::types::global_dof_index;
  const dealii::TrilinosWrappers::SparseMatrix* bulk = nullptr; ///< K, unconstrained
  /// The homogeneous constraints of the current tie set (read again at each new epoch).
  const dealii::AffineConstraints<double>* constraints = nullptr;
  std::vector<dof_index> boundary;                    ///< B: crack-plane and load-line dofs
  std::vector<std::pair<dof_index, dof_index>> pairs; ///< (top, bottom) crack-plane pairs
  /// Per interface point: (top dof of the opening component, weight) of its nodes.
  std::vector<std::vector<std::pair<dof_index, double>>> points;
  /// Per dof: sort key (arm, x, z, y, component) ordering I into slender bands.
  std::vector<std::array<double, 5>> order;
  /// The load-line dofs (in B): their rows of K u are the reactions of the convergence test.
  std::vector<dof_index> loads;
};

/// What the crack-plane Newton reads of the interface: the points' responses, and which points
/// carry forces (those of segments no longer intact, as CrackPlane::add_forces).
struct CrackPlaneForces {
  const CohesiveInterface* interface = nullptr;
  std::vector<bool> active;
};

/// The condensed strategy with its own Newton on the crack-plane unknowns.
class CondensedSolver : public JacobianSolver {
public:
  /// Newton on the crack plane (docs/design.md section 2, "Condensed arms"): from u, whose
  /// interior is in equilibrium with its crack plane (K_II u_I + K_IB u_B = 0 to round-off: a
  /// converged state, scaled or with ties released), the arms' response is linear, so the
  /// residual's bulk part is followed on the crack-plane unknowns alone (S' v, kept up to date
  /// from each step's S' dv = rhs - T dv) and the interior is formed once at the end. Same steps,
  /// line search and test as newton_solve() (equilibrium_problem.h). Leaves u at its last state
  /// (the interior formed from it) and returns its iterations in `used`: true where it
  /// converged; false where it stopped short (a line search without decrease, the iteration
  /// limit), and the caller's full Newton goes on from u with what is left of the budget (it
  /// knows the round-off floor, which may accept such a state). Either way the full Newton
  /// checks the state with the full residual.
  virtual bool crack_plane_newton(Vec& u, const CrackPlaneForces& forces, unsigned epoch,
                                  const NonlinearSettings& settings, double reaction_floor,
                                  unsigned& used) = 0;
};

std::unique_ptr<CondensedSolver> make_condensed_solver(CondensedArms arms,
                                                       dealii::TimerOutput& timer);

} // namespace fiberbridge::fem
