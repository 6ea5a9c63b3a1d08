// The full Newton on the condensed residual (equilibrium_problem.h), as a strategy of the one
// Newton loop (newton_loop.h).
#include "equilibrium_problem.h"
#include "newton_loop.h"

#include "fiberbridge/fem/dcb_common.h"

namespace fiberbridge::fem {

namespace {

/// The full model's unknowns u, the residual r (and r_full, whose load-line rows are the
/// reactions) and the step du.
class FullNewton {
public:
  FullNewton(EquilibriumProblem& problem, Vec& u, double tolerance)
      : problem_(problem), u_(u), tolerance_(tolerance) {
    for (Vec* v : {&r_, &rf_, &du_, &trial_, &rhs_})
      problem_.reinit_vector(*v);
    problem_.residual(u_, r_, rf_);
    ref_ = problem_.reaction_norm(rf_);
    norm_ = problem_.norm(r_);
  }

  bool converged() const { return norm_ <= tolerance_ * ref_; }

  void direction() {
    problem_.setup_jacobian(u_);
    rhs_ = r_;
    rhs_ *= -1.0;
    problem_.solve_jacobian(rhs_, du_);
  }

  double merit() const { return norm_; }

  double trial(double alpha) {
    trial_ = u_;
    trial_.add(alpha, du_);
    problem_.residual(trial_, r_, rf_);
    return problem_.norm(r_);
  }

  void keep_trial(bool /*search goes on*/) { best_ref_ = problem_.reaction_norm(rf_); }

  bool accept(double alpha, bool last) {
    // The accepted state is almost always the last one tried (the full step): its residual is
    // in r and rf already, so it is taken as it is rather than evaluated again (a third of the
    // residual evaluations; the same bits, since u becomes that very vector).
    if (last)
      u_ = trial_;
    else {
      u_.add(alpha, du_);
      problem_.residual(u_, r_, rf_);
    }
    ref_ = best_ref_;
    const double before = norm_;
    norm_ = problem_.norm(r_);
    problem_.note_contraction(norm_ / before);
    // Stagnation on the round-off plateau: with finite kinematics the internal forces of
    // rotated arms cancel large terms, and after its quadratic phase Newton crept along the
    // plateau to the iteration limit (measured: 10-20 wasted iterations per solve on arms at
    // opening/a 0.7). Less than 10 % decrease below the floor is that plateau; above the
    // tolerance and the floor, a slow step is never accepted.
    return norm_ > 0.9 * before && !converged() && at_floor();
  }

  /// Stagnation at the residual's round-off floor is equilibrium, not a failure: the tolerance
  /// relative to the reactions can fall below the round-off of the terms that cancel in K u
  /// (stiff thin layers, the contact penalty) on refined meshes (docs/design.md section 2).
  bool at_floor() const { return norm_ <= problem_.roundoff_floor(u_); }
  double norm() const { return norm_; }
  double ref() const { return ref_; }

private:
  EquilibriumProblem& problem_;
  Vec& u_;
  const double tolerance_;
  Vec r_, rf_, du_, trial_, rhs_;
  double ref_ = 0, norm_ = 0, best_ref_ = 0;
};

} // namespace

bool newton_solve(EquilibriumProblem& problem, Vec& u, const NonlinearSettings& settings,
                  unsigned& n_iterations, std::string& diagnosis) {
  FullNewton newton(problem, u, settings.tolerance);
  const NewtonStop stop = newton_loop(newton, settings.max_iterations, n_iterations);
  // Without a decrease or at the iteration limit, a residual at its round-off floor is
  // equilibrium (at_floor above).
  if (stop == NewtonStop::converged || newton.at_floor())
    return true;
  if (stop == NewtonStop::no_decrease)
    diagnosis = "line search found no decrease of the residual " + fmt(newton.norm()) + " N" +
                problem.contact_summary();
  else
    diagnosis = "no convergence in " + std::to_string(settings.spent + settings.max_iterations) +
                " Newton iterations (residual " + fmt(newton.norm() / newton.ref()) +
                " of the reaction, tolerance " + fmt(settings.tolerance) + ")" +
                problem.contact_summary();
  return false;
}

} // namespace fiberbridge::fem
