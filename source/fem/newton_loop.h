#pragma once
// The one Newton loop of the FEM (docs/design.md section 2, "One Newton"). The full Newton
// (newton_solver.cc), the crack-plane Newton of the condensed arms (condensed_solver.cc) and the
// bordered Newton of the crack-tip opening control (dcb_model_tip_control.templates.h) differ in
// their unknowns, their linear solves and their merit; they iterate, search and stop the same
// way, here. KINSOL (kinsol_coupling.cc) is the alternative to this loop, on the same residual,
// Jacobian and test.

namespace fiberbridge::fem {

/// How a Newton loop ended; the strategy's owner decides what a stop other than `converged`
/// means (the round-off floor, a diagnosis, a hand-over to the full Newton).
enum class NewtonStop { converged, no_decrease, iteration_limit };

/// Backtracking: the step is halved up to this many trials ...
inline constexpr int kLineSearchTrials = 8;
/// ... until the merit falls by this fraction of the step (Armijo's sufficient decrease: any
/// decrease of a full Newton step passes, a short step must decrease in proportion).
inline constexpr double kSufficientDecrease = 1e-4;

/// Newton with backtracking line search. A `Strategy` holds the state and supplies:
///   bool converged();          the convergence test at the current state;
///   void direction();          linearizes at the current state and solves for the step;
///   double merit();            the current state's merit (called after direction(): the
///                              bordered merit weighs the constraint with the direction);
///   double trial(double a);    evaluates the state + a step; returns its merit;
///   void keep_trial(bool on);  the last trial is the best so far (`on`: the search goes on
///                              past it, so a strategy that reuses trials keeps a copy);
///   bool accept(double a, bool last);  moves to the state + a step (`last`: the last trial
///                              evaluated is that state); true when the new state counts as
///                              converged although the test says not (a round-off plateau).
/// Counts its iterations (linearizations) into n_iterations.
template <class Strategy>
NewtonStop newton_loop(Strategy& s, unsigned max_iterations, unsigned& n_iterations) {
  for (unsigned it = 0; it <= max_iterations; ++it) {
    if (s.converged())
      return NewtonStop::converged;
    if (it == max_iterations)
      break;
    ++n_iterations;
    s.direction();
    const double merit = s.merit();
    double alpha = 1, best_alpha = 0, best_merit = merit, last_alpha = 0;
    for (int ls = 0; ls < kLineSearchTrials; ++ls, alpha *= 0.5) {
      const double trial_merit = s.trial(alpha);
      last_alpha = alpha;
      const bool enough = trial_merit <= (1 - kSufficientDecrease * alpha) * merit;
      if (trial_merit < best_merit) {
        best_merit = trial_merit;
        best_alpha = alpha;
        s.keep_trial(!enough && ls + 1 < kLineSearchTrials);
      }
      if (enough)
        break;
    }
    if (best_alpha == 0)
      return NewtonStop::no_decrease;
    if (s.accept(best_alpha, best_alpha == last_alpha))
      return NewtonStop::converged;
  }
  return NewtonStop::iteration_limit;
}

} // namespace fiberbridge::fem
