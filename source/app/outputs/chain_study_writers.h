#pragma once
// The table, plots and summary block of `chain study` (item_chain_study.cc), apart from its runs
// (docs/design.md section 4, "Parse once and writers apart").
#include "fiberbridge/app/scene/scene_context.h"

#include <cmath>
#include <string>
#include <vector>

namespace fiberbridge::app {

/// One case of the chain study: its truth, what the measuring chain gave back or why it refused.
struct ChainRow {
  std::string name, factor;
  double value = 0; ///< the varied factor's value (NaN for named cases)
  bool table1 = false;
  /// "recovered", "refused" (the chain's InputError/ComputationError: a result, not a crash) or
  /// "fem_failed" (the virtual test itself did not run).
  std::string outcome;
  std::string stage;  ///< where it stopped: "fem" or "chain"
  std::string reason; ///< the refusal's message
  // Truth (from the case's Cohesive law) and recovered (summary.json of the chain's scene).
  double j_tip_true = 0, g_ss_true = 0, delta_c_true = 0, sigma1_true = 0, sigma2_true = 0;
  double j_tip = 0, g_ss = 0, delta_c = 0, sigma1 = 0, sigma2 = 0; ///< NaN when refused
  /// The fit's correction by simulation (Fit/Model correction): "converged" (the recovered values
  /// above are the corrected ones), "not converged" (they are the seed's fit, the reason in the
  /// chain's summary.json) or "" (not run). `uncorrected`: the seed's fit and J_tip, and
  /// extract's plateau G_ss; the corrected G_ss is the corrected law's J_tip + J1 + J2.
  std::string correction;
  struct Uncorrected {
    double j_tip = NAN, g_ss = NAN, delta_c = NAN, sigma1 = NAN, sigma2 = NAN;
  } uncorrected;
  /// || fitted trilinear - true law ||_2 / || true law ||_2 over [0, true delta_c].
  double law_l2_rel = 0;
  bool targets_met = false;
  std::string missed; ///< which of issue 39's targets it missed ("; "-separated)
  double fem_wall_s = 0, chain_wall_s = 0;
  /// `identify` on the same virtual test (Chain study/Identify): the machine record with the DIC
  /// crack lengths, no delta_root; the identified law's sigma at the same d1, d2, its J_tip,
  /// G_ss and delta_c, and its L2 error against the truth. outcome "" when it did not run.
  struct Identified {
    std::string outcome, reason;
    double j_tip = NAN, g_ss = NAN, delta_c = NAN, sigma1 = NAN, sigma2 = NAN, law_l2_rel = NAN;
    double wall_s = 0;
  } identified;
};

/// chain_recovery.csv, chain_recovery_vs_frame_rate.png, chain_recovery_vs_noise.png and the
/// summary block `chain_study`.
void write_chain_study(const SceneContext& ctx, const std::vector<ChainRow>& rows, double wall_s,
                       ItemReport& report);

} // namespace fiberbridge::app
