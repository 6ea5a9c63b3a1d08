#pragma once
// The one R-curve post-processing of every specimen simulation (beam, FEM, MPM;
// docs/design.md section 2, "Three R curves" and "Steady state and G_ss"): R_energy over the
// neighbouring advances, the steady-state rule that gives G_ss (plateau flatness over a window of
// growth), and the whole post-processing of a finished run (finish_rcurve).
#include "fiberbridge/law/traction_law.h"
#include "fiberbridge/result/rcurve.h"

#include <cstddef>
#include <string>
#include <vector>

namespace fiberbridge::result {

/// Energy released so far for the whole width: W_ext - U - U_zone - KE (KE where the model has
/// it) [J]. Its slope in a is R_energy.
double released_energy(const RCurvePoint& p);

/// R_energy of every row: released energy between the advances before and after the row over
/// B times the growth between them (central; one-sided at the two ends). Central differences are
/// second order in the tip advance and average the ringing of a dynamic model's increments.
void fill_r_energy(std::vector<RCurvePoint>& rcurve, double width);

/// The steady-state rule: the notch root has moved, and R_J has stayed within `tolerance` (spread
/// max - min relative to its mean) over at least `window` of tip growth since then. Every model
/// section names these `Steady state window` and `Plateau tolerance`.
struct SteadyStateRule {
  double window = 10e-3;   ///< growth after the root moved over which R_J must stay flat [m]
  double tolerance = 0.01; ///< relative spread of R_J accepted as flat
  /// The root has moved once it lies more than this ahead of the initial crack [m] (a model
  /// whose root position is only known to a fraction of a cell says so here).
  double root_move = 0;
};

/// What the rule found on the rows so far.
struct SteadyState {
  bool bridging = true;    ///< the law has a zone (else the root need not move)
  bool root_moved = false; ///< true from the first row when the law has no zone
  std::size_t moved = 0;   ///< first row whose root has moved
  bool reached = false;
  std::size_t first = 0, last = 0; ///< the plateau (reached) or the rows after the root moved
  std::size_t used = 0;            ///< rows averaged
  std::size_t left_out = 0;        ///< rows of that stretch the caller excluded
  double G_ss = not_available;     ///< mean R_J over the plateau, or after the root moved
  double spread = not_available;   ///< (max - min)/mean of R_J over the plateau
  double R_energy = not_available; ///< released energy per growth over the plateau [J/m^2]
};

/// Evaluates the rule on `rcurve`. The plateau is the longest stretch ending at the last row,
/// after the root moved, over which R_J stays within the tolerance; steady state when it spans
/// at least the window. `bridging` false (a law without a zone): the root need not move.
/// `excluded[i]` leaves row i out of the plateau without ending it (the MPM's advances where the
/// tip lagged the loading: their R_J belongs to a higher tip toughness); empty = none.
/// Not reached but the root moved: G_ss is the mean R_J after the root moved (Eq. 1 makes R_J
/// the model's G_ss once delta_root = delta_c, whether or not the zone is self-similar).
SteadyState find_steady_state(const std::vector<RCurvePoint>& rcurve, double initial_crack,
                              double width, bool bridging, const SteadyStateRule& rule,
                              const std::vector<bool>& excluded = {});

/// Sets result.G_ss and result.reached_steady_state from `s` and adds one note saying how G_ss
/// was found; `section` names the scene section of the rule's keys ("FEM", "MPM", "Beam").
void report_steady_state(SimulationResult& result, const SteadyState& s,
                         const SteadyStateRule& rule, const std::string& section);

/// The post-processing of a finished run, on its whole R curve: R_energy of every row
/// (fill_r_energy), the steady-state rule (find_steady_state with `bridging` = the law has a zone,
/// reported by report_steady_state under the keys of `section`) and the relative error of R_J
/// against Eq. 2 of `law` (rdelta_error_vs_eq2). `excluded` as in find_steady_state. Returns what
/// the rule found.
SteadyState finish_rcurve(SimulationResult& result, const law::TractionLaw& law, double j_tip,
                          double initial_crack, double width, const SteadyStateRule& rule,
                          const std::string& section, const std::vector<bool>& excluded = {});

} // namespace fiberbridge::result
