// SUNDIALS KINSOL on the condensed residual (equilibrium_problem.h).
#include "equilibrium_problem.h"

#include "fiberbridge/fem/dcb_common.h"

#include <deal.II/sundials/kinsol.h>

#include <algorithm>
#include <cmath>

namespace fiberbridge::fem {

bool kinsol_solve(EquilibriumProblem& problem, Vec& u, const NonlinearSettings& settings,
                  double opening, unsigned& n_iterations, std::string& diagnosis) {
  // KINSOL on TrilinosWrappers::MPI::Vector (its N_Vector wrapper reduces over the vectors'
  // communicator), on the same residual, Jacobian and linear solves as newton_solve(). The
  // release library does not report a failed solve (docs/design.md section 7): the result is
  // re-checked against the Newton test here.
  Vec r, rf;
  problem.reinit_vector(r);
  problem.reinit_vector(rf);
  problem.residual(u, r, rf);
  const double ref = problem.reaction_norm(rf);
  if (problem.norm(r) <= settings.tolerance * ref)
    return true;
  using Kinsol = dealii::SUNDIALS::KINSOL<Vec>;
  typename Kinsol::AdditionalData data;
  data.strategy = Kinsol::AdditionalData::linesearch;
  data.maximum_non_linear_iterations = settings.max_iterations;
  // Max-norm stop below tolerance / sqrt(n) guarantees the l2 test; the step tolerance stops
  // only on stagnation. As in newton_solve(), a residual at its round-off floor is equilibrium:
  // the tolerance relative to the reactions can fall below the round-off of the terms that
  // cancel in K u on refined thin-arm meshes, and KINSOL would then iterate on noise until it
  // gives up.
  const double floor = problem.roundoff_floor(u);
  data.function_tolerance = std::max(settings.tolerance * ref, floor) / std::sqrt(problem.n_dofs());
  data.step_tolerance = 1e-3 * settings.tolerance * opening;
  data.maximum_setup_calls = 1;
  Kinsol solver(data, problem.communicator());
  std::string callback_error;
  auto guarded = [&](const auto& body) -> int {
    try {
      body();
      return 0;
    } catch (const std::exception& e) {
      callback_error = e.what();
      return -1;
    }
  };
  solver.reinit_vector = [&](Vec& v) { problem.reinit_vector(v); };
  solver.residual = [&](const Vec& x, Vec& f) {
    return guarded([&] {
      Vec full;
      problem.reinit_vector(full);
      problem.residual(x, f, full);
    });
  };
  solver.setup_jacobian = [&](const Vec& x, const Vec&) {
    return guarded([&] { problem.setup_jacobian(x); });
  };
  solver.solve_with_jacobian = [&](const Vec& rhs, Vec& x, double) {
    return guarded([&] { problem.solve_jacobian(rhs, x); });
  };
  Vec solution = u;
  unsigned iterations = 0;
  try {
    iterations = solver.solve(solution);
  } catch (const std::exception& e) {
    callback_error = e.what();
  }
  n_iterations += iterations;
  u = solution;
  problem.residual(u, r, rf);
  const double final_ref = problem.reaction_norm(rf);
  const double nrm = problem.norm(r);
  if (callback_error.empty() &&
      nrm <= std::max(settings.tolerance * final_ref, problem.roundoff_floor(u)))
    return true;
  diagnosis = "KINSOL returned after " + std::to_string(iterations) + " of at most " +
              std::to_string(settings.max_iterations) + " Newton iterations with residual " +
              fmt(nrm / final_ref) + " of the reaction (tolerance " + fmt(settings.tolerance) +
              ")" +
              (callback_error.empty() ? "" : "; KINSOL or a callback failed: " + callback_error);
  return false;
}

} // namespace fiberbridge::fem
