#pragma once
// The table, plots and summary block of `programme study` (item_programme_study.cc), apart from
// its runs (docs/design.md section 4, "Parse once and writers apart").
#include "fiberbridge/app/scene/scene_context.h"

#include <string>
#include <vector>

namespace fiberbridge::app {

/// One group of the simulated programme: its Table 1 law, the mean of its specimens' scattered
/// laws, and what the campaign gave back with its bootstrap intervals (kPa, J/m^2, mm).
struct ProgrammeGroup {
  std::string material;
  double cycles = 0;
  int n_specimens = 0;
  double sigma1_true = 0, sigma2_true = 0, delta_c_true = 0, j_tip_true = 0, g_ss_true = 0;
  double sigma1_specimen_mean = 0, sigma2_specimen_mean = 0;
  double sigma1 = 0, sigma1_lo = 0, sigma1_hi = 0, sigma2 = 0, sigma2_lo = 0, sigma2_hi = 0;
  double j_tip = 0, g_ss = 0, delta_c = 0;
  bool ok = false;
};

struct ProgrammeOutcome {
  std::vector<ProgrammeGroup> groups;
  std::vector<std::string> ranking;          ///< the campaign's, best first
  std::vector<std::string> expected_ranking; ///< the seed's: PF, EPI, PRF, PVA
  double generation_wall_s = 0, campaign_wall_s = 0;
  int n_sets = 0, n_generated = 0; ///< DIC sets in the manifest, of them made by this run
  std::string campaign_dir, refusal;
};

/// programme_recovery.csv, programme_sigma_recovered_vs_true.png, programme_laws_<material>.png
/// and the summary block `programme_study`.
void write_programme_study(const SceneContext& ctx, const ProgrammeOutcome& o, ItemReport& report);

} // namespace fiberbridge::app
