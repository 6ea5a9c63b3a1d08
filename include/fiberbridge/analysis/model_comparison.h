#pragma once
// Comparing simulations with each other and closing the loop through the extraction method
// (docs/design.md section 3): analysis of result::SimulationResult, whichever model produced it, so
// plain functions that are tested without running a model (tests/analysis/
// model_comparison_tests.cc). The scene item `compare` (app/items/item_compare.cc) writes them out.
#include "fiberbridge/analysis/inverse.h"
#include "fiberbridge/law/traction_law.h"
#include "fiberbridge/result/rcurve.h"

#include <string>
#include <vector>

namespace fiberbridge::analysis {

/// Differences between two models' R(a) curves.
struct PairwiseDifference {
  std::string model_a, model_b;
  std::string quantity;          ///< "R_energy", "R_J", "R_eq2", "delta_root"
  double rel_l2_developing = 0;  ///< relative L2 over the common a range before either root moves
  double plateau_rel_diff = 0;   ///< (G_ss_b - G_ss_a) / G_ss_a
  double peak_load_rel_diff = 0; ///< (P_max_b - P_max_a) / P_max_a
  int n_points = 0;              ///< points of a's curve in the compared range
};

std::vector<PairwiseDifference> compare_models(const result::SimulationResult& a,
                                               const result::SimulationResult& b);

/// One recovered law of the closed loop (input law -> simulated R(delta_root) -> extraction).
struct ClosedLoopRow {
  std::string model;
  std::string r_source; ///< which simulated R: "R_energy" (what an experiment measures), "R_eq2"
  std::string method;   ///< "eq6" or "dRdd"
  double peak_kPa = 0, peak_true_kPa = 0;
  double delta_at_peak_mm = 0, delta_at_peak_true_mm = 0;
  double area_J_m2 = 0, area_true_J_m2 = 0;
  double curve_rel_l2 = 0; ///< ||sigma_recovered - sigma_true|| / ||sigma_true|| on the grid
  ExtractedLaws laws;      ///< the recovered laws (both methods) on the grid
};

/// Builds R(delta_root) from the rows where delta_root increases (the zone development and the
/// start of the plateau), extracts with Eq. 6 and dR/ddelta on n intervals up to the input law's
/// delta_c with half-width k, and compares with the input law. Throws ComputationError when the
/// simulation has fewer than n/4 distinct delta_root values below delta_c (too coarse to say).
std::vector<ClosedLoopRow> closed_loop(const result::SimulationResult& r,
                                       const law::TractionLaw& law, double j_tip, int n, int k);

/// What `compare` computes for the simulations of one scene: every pair's differences, and, when
/// asked, each model's closed loop (or why it could not be run: a model too coarse for it).
struct ModelComparison {
  std::vector<PairwiseDifference> pairs;
  struct Loop {
    std::string model;
    std::vector<ClosedLoopRow> rows; ///< empty when `diagnosis` says why
    std::string diagnosis;
  };
  std::vector<Loop> loops;
};
/// The pairs in the order of `models` (a before b), then the closed loops with n, k when `loop`.
ModelComparison compare_simulations(const std::vector<const result::SimulationResult*>& models,
                                    const law::TractionLaw& law, double j_tip, bool loop, int n,
                                    int k);

} // namespace fiberbridge::analysis
