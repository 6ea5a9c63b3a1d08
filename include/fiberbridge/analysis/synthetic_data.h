#pragma once
// Synthetic measured R curves: replicates generated from a known law through seed Eq. 2, with the
// scatter a real test series has. They exercise the whole analysis chain against a known answer.
#include "fiberbridge/analysis/rdelta_data.h"
#include "fiberbridge/law/traction_law.h"

#include <string>
#include <vector>

namespace fiberbridge::analysis {

/// `n_replicates` replicates of R(delta) = Eq. 2 of `law` (SI: j_tip, noise_J_m2 in J/m^2,
/// delta_max in m). Each replicate r has
///  - its own J_tip: j_tip (1 + 0.02 z_r), z_r standard normal clipped to [-3, 3] (specimen
///  scatter);
///  - its own delta range: delta_max (1 - 0.05 u_r), u_r uniform in [0, 1) (tests stop at
///    different openings), sampled at n_points_per_replicate openings from 0, equally spaced up
///    to a uniform jitter of +-0.4 spacing (so delta still increases strictly);
///  - time_s = 0, 1, 2, ... (images at 1 Hz, seed section 2.2), label "1", "2", ...;
///  - Gaussian noise of standard deviation noise_J_m2 on each R, clipped at R >= 0.
/// One std::mt19937 seeded with `seed` drives everything in a fixed order: reproducible.
/// Throws InputError for n_replicates < 1, n_points_per_replicate < 8, noise < 0, j_tip < 0, or
/// delta_max not beyond the law's delta_c (the steady-state plateau must be in the data).
RDeltaData make_synthetic_rdelta(const law::TractionLaw& law, double j_tip, int n_replicates,
                                 int n_points_per_replicate, double noise_J_m2, double delta_max,
                                 unsigned seed);

/// Comment lines for write_rdelta_csv() stating that the data are synthetic and how
/// make_synthetic_rdelta() made them with these arguments (law points in mm and kPa, J_tip, the
/// scatter model, noise, seed), so the file documents its own provenance.
std::vector<std::string> describe_synthetic_rdelta(const law::TractionLaw& law, double j_tip,
                                                   int n_replicates, int n_points_per_replicate,
                                                   double noise_J_m2, double delta_max,
                                                   unsigned seed);

/// Writes `data` as CSV with columns replicate,time_s,delta_mm,R_J_m2 (time_s 0, 1, ... in row
/// order for replicates that have no times), preceded by `comment_lines` as '#' lines (say there
/// that the data are synthetic and how they were made). Atomic (temporary file + rename).
/// Throws InputError if a replicate label contains a comma or a line break.
void write_rdelta_csv(const std::string& path, const RDeltaData& data,
                      const std::vector<std::string>& comment_lines);

} // namespace fiberbridge::analysis
