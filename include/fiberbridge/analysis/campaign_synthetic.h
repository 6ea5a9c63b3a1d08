#pragma once
// A synthetic campaign with a known answer (issue 33 item 8 and its verification): every
// specimen's R(delta) made by make_synthetic_rdelta (synthetic_data.h, what `fiberbridge synth`
// runs) from its group's trilinear law with a stated specimen-to-specimen scatter, and the
// manifest that lists them.
#include "fiberbridge/analysis/degradation.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <string>
#include <vector>

namespace fiberbridge::analysis {

/// One group's true law.
struct SyntheticGroupTruth {
  std::string material;
  double cycles = 0;
  law::TrilinearParameters law; ///< SI
  double j_tip = 200;           ///< [J/m^2]
};

/// The laws of a Table 1 in the format of data/reference/seed_table1.csv: sigma1 and sigma2 of
/// every (material, cycles) with d1 = 0.1 mm, d2 = 1.0 mm and delta_c = seed_delta_c_mm (the
/// seed's fixed values), J_tip `j_tip` for all.
std::vector<SyntheticGroupTruth> table1_truth(const PropertyTable& table, double j_tip = 200);

struct SyntheticCampaignOptions {
  int replicates = 5; ///< specimens per group
  /// Specimen-to-specimen scatter: each specimen's sigma1 and sigma2 are the group's times
  /// independent factors 1 + stress_cv z, z standard normal clipped to [-2.5, 2.5] (mean 1: the
  /// group's mean law is the truth). On top, make_synthetic_rdelta's own 2 % J_tip scatter.
  double stress_cv = 0.10;
  double noise_J_m2 = 4;          ///< R measurement noise per row
  int rows = 150;                 ///< rows per specimen
  double delta_max_over_dc = 1.5; ///< tests run past delta_c into the plateau
  unsigned seed = 1;
  bool write_delta_c = true; ///< the manifest gives each row its group's delta_c (seed: fixed)
};

/// Writes one CSV per specimen (`<material>_c<cycles>_s<k>.csv`, '#' lines stating the law, the
/// scatter and the seed) and `manifest.csv` into `dir` (created). Returns the manifest's path.
/// Deterministic given options.seed.
std::string write_synthetic_campaign(const std::string& dir,
                                     const std::vector<SyntheticGroupTruth>& truth,
                                     const SyntheticCampaignOptions& options);

} // namespace fiberbridge::analysis
