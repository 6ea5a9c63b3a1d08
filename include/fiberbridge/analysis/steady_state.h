#pragma once
// Locating J_tip, G_ss and the steady-state onset delta_c on a measured R(delta) curve.
#include "fiberbridge/analysis/rdelta_data.h"

#include <string>

namespace fiberbridge::analysis {

struct SteadyStateOptions {
  double delta_c = 0;         ///< > 0: user-given delta_c [m] (must lie inside the data)
  double j_tip = 0;           ///< > 0: user-given J_tip [J/m^2]
  double tail_fraction = 0.2; ///< plateau window: the last fraction of the delta range
  double plateau_band = 0.02; ///< |slope*window| must stay below this fraction of G_B
};

struct SteadyState {
  double j_tip = 0;   ///< [J/m^2]
  double G_ss = 0;    ///< [J/m^2]
  double delta_c = 0; ///< [m]
  bool delta_c_automatic = true;
  bool j_tip_automatic = true;
  /// R falls over the last stretch of the data beyond the plateau band: the zone meets the
  /// specimen's far end (the tip reading runs ahead of the work done), so the record's plateau
  /// is cut short and G_ss is read before the fall (the last flat stretch, or R at a given
  /// delta_c when no stretch is flat). A model of the
  /// specimen that holds its far end can take the effect out (Fit/Model correction = auto).
  bool end_effect = false;
  std::string criterion; ///< the stated criterion and the numbers it used (for the report)
};

/// Automatic criterion (documented in the implementation and reported in `criterion`):
///  - G_ss: mean of R over the last `tail_fraction` of the delta range; the tail must be flat:
///    a least-squares slope over it times its width below `plateau_band` * (G_ss - J_tip), else
///    ComputationError "no steady state in <file>".
///  - J_tip: the flat level of a hinge fit (R constant up to a hinge, then rising linearly) to
///    the points with delta below 5 % of the range (at least 6); R is exactly flat below d1 for
///    laws with an elastic rise and rises linearly just after it (seed Eq. 2).
///  - delta_c: where the rising branch meets the plateau: the first grid point whose R reaches
///    G_ss - 5 % of G_B, then the line fitted to the rising branch just before it is extended to
///    G_ss (the kink of R at delta_c has a non-zero left slope for trilinear laws).
/// User values override; a user delta_c outside the data, or J_tip >= G_ss, throws InputError.
SteadyState find_steady_state(const RDeltaCurve& curve, const SteadyStateOptions& options,
                              const std::string& source);

} // namespace fiberbridge::analysis
