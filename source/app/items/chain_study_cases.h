#pragma once
// The cases of `chain study` (item_chain_study.cc; docs/design.md, "Virtual tests as the chain's
// verification"): a one-factor-at-a-time design around the scene's own virtual test (the base:
// the paper's 1 Hz, 0.002 mm noise, VIC), plus the full list of laws at the base. A case is only
// a list of "Section/Key=value" settings on top of the scene, so that it runs exactly what a
// user's scene with those keys would run.
#include "fiberbridge/analysis/degradation.h"

#include <string>
#include <vector>

namespace fiberbridge::app {

struct ChainCase {
  std::string name;
  /// The factor varied from the base ("base", "law", "layout", "noise_mm", "failed_fraction",
  /// "frame_rate_Hz", "crosshead_mm_min") and its value for the plots (NaN for names).
  std::string factor;
  double value = 0;
  std::vector<std::string> sets;
  /// A Table 1 law at the base case: the targets apply to it.
  bool table1 = false;
};

/// Every case: the base, the 20 Table 1 laws (d1 = 0.1 mm, d2 = 1.0 mm, delta_c as the paper
/// fixed it: PVA 6 mm, the others 3.5 mm), linear, bilinear, exponential, short and long zones,
/// the layouts, noise, failed points, frame rates and crosshead rates.
std::vector<ChainCase> chain_study_cases(const analysis::PropertyTable& table1);

/// The cases named in `list` ("all", or names separated by commas); InputError naming `where`
/// and the known names for an unknown one.
std::vector<ChainCase> select_chain_cases(const std::vector<ChainCase>& all,
                                          const std::string& list, const std::string& where);

} // namespace fiberbridge::app
