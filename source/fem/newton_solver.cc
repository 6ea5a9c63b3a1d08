// Newton with backtracking line search on the condensed residual (equilibrium_problem.h).
#include "equilibrium_problem.h"

#include "fiberbridge/fem/dcb_common.h"

namespace fiberbridge::fem {

bool newton_solve(EquilibriumProblem& problem, Vec& u, const NonlinearSettings& settings,
                  unsigned& n_iterations, std::string& diagnosis) {
  Vec r, rf, du, trial, rhs;
  for (Vec* v : {&r, &rf, &du, &trial, &rhs})
    problem.reinit_vector(*v);
  problem.residual(u, r, rf);
  double ref = problem.reaction_norm(rf);
  double nrm = problem.norm(r);
  for (unsigned it = 0; it <= settings.max_iterations; ++it) {
    if (nrm <= settings.tolerance * ref)
      return true;
    if (it == settings.max_iterations)
      break;
    ++n_iterations;
    problem.setup_jacobian(u);
    rhs = r;
    rhs *= -1.0;
    problem.solve_jacobian(rhs, du);

    // Backtracking line search on the condensed residual norm.
    double alpha = 1, best_alpha = 0, best_norm = nrm, best_ref = ref, last_alpha = 0;
    for (int ls = 0; ls < 8; ++ls, alpha *= 0.5) {
      trial = u;
      trial.add(alpha, du);
      problem.residual(trial, r, rf);
      last_alpha = alpha;
      const double trial_ref = problem.reaction_norm(rf);
      const double trial_norm = problem.norm(r);
      if (trial_norm < best_norm) {
        best_norm = trial_norm;
        best_alpha = alpha;
        best_ref = trial_ref;
      }
      if (trial_norm <= (1 - 1e-4 * alpha) * nrm)
        break;
    }
    if (best_alpha == 0) {
      // Stagnation at the residual's round-off floor is equilibrium, not a failure: the
      // tolerance relative to the reactions can fall below the round-off of the terms that
      // cancel in K u (stiff thin layers, the contact penalty) on refined meshes
      // (docs/design.md section 2). Accepted only when no step decreases the residual.
      if (nrm <= problem.roundoff_floor(u))
        return true;
      diagnosis = "line search found no decrease of the residual " + fmt(nrm) + " N" +
                  problem.contact_summary();
      return false;
    }
    // The accepted state is almost always the last one tried (the full step): its residual is
    // in r and rf already, so it is taken as it is rather than evaluated again (a third of the
    // residual evaluations; the same bits, since u becomes that very vector).
    if (best_alpha == last_alpha)
      u = trial;
    else {
      u.add(best_alpha, du);
      problem.residual(u, r, rf);
    }
    ref = best_ref;
    const double before = nrm;
    nrm = problem.norm(r);
    problem.note_contraction(nrm / before);
    // The same stagnation when a step still finds a sliver of decrease: with finite kinematics
    // the internal forces of rotated arms cancel large terms, and after its quadratic phase
    // Newton crept along the round-off plateau to the iteration limit (measured: 10-20 wasted
    // iterations per solve on arms at opening/a 0.7). Less than 10 % decrease below the floor
    // is that plateau; above the tolerance and the floor, a slow step is never accepted.
    if (nrm > 0.9 * before && nrm > settings.tolerance * ref && nrm <= problem.roundoff_floor(u))
      return true;
  }
  if (nrm <= problem.roundoff_floor(u)) // the iteration limit reached at round-off: equilibrium
    return true;
  diagnosis = "no convergence in " + std::to_string(settings.spent + settings.max_iterations) +
              " Newton iterations (residual " + fmt(nrm / ref) + " of the reaction, tolerance " +
              fmt(settings.tolerance) + ")" + problem.contact_summary();
  return false;
}

} // namespace fiberbridge::fem
