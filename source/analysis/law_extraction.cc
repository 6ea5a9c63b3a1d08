#include "fiberbridge/analysis/law_extraction.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <string>

namespace fiberbridge::analysis {

using units::mm;

ExtractionOutcome extract_law(const ExtractionOptions& o) {
  if (o.intervals < 4)
    throw InputError("Data/Intervals: need at least 4 grid intervals for Eq. 6, got " +
                     std::to_string(o.intervals));
  if (o.half_width < 1 || 2 * o.half_width >= o.intervals)
    throw InputError("Data/Smoothing half-width: must lie in [1, intervals/2), got " +
                     std::to_string(o.half_width));
  ExtractionOutcome e;
  e.curve = average_replicates(o.data ? *o.data : read_rdelta_csv(o.data_file), o.grid_points);
  SteadyStateOptions so;
  so.delta_c = o.delta_c;
  so.j_tip = o.j_tip;
  e.steady = find_steady_state(e.curve, so, o.data_file);
  e.laws = extract_cohesive_laws(e.curve, e.steady.delta_c, o.intervals, o.half_width);
  return e;
}

TrilinearFit fit_extracted_law(const ExtractionOutcome& e, const FitOptions& o) {
  const double dc = e.steady.delta_c;
  const double G_B = e.steady.G_ss - e.steady.j_tip;
  TrilinearFit fit;
  if (o.free_breakpoints) {
    const double d2_max = o.d2_max > 0 ? o.d2_max : 0.5 * dc;
    fit = fit_trilinear_free(e.laws.delta, e.laws.sigma_eq6, dc, G_B, o.d1_min, o.d1_max, d2_max);
  } else {
    if (!(o.d1 > 0 && o.d1 < o.d2 && o.d2 < dc))
      throw InputError("Fit: need 0 < Delta 1 < Delta 2 < delta_c (" + std::to_string(dc / mm) +
                       " mm); got Delta 1 = " + std::to_string(o.d1 / mm) +
                       " mm, Delta 2 = " + std::to_string(o.d2 / mm) + " mm");
    fit = fit_trilinear_fixed(e.laws.delta, e.laws.sigma_eq6, o.d1, o.d2, dc, G_B);
  }
  return fit;
}

RankingOutcome rank_property_table(const RankOptions& o) {
  RankingOutcome r;
  r.table = read_property_table(o.table_file);
  r.rows = analyse_degradation(r.table);
  r.ranks = rank_materials(r.rows);
  r.issues = check_row_consistency(r.table, o.d1_mm, o.d2_mm, &seed_delta_c_mm);
  return r;
}

} // namespace fiberbridge::analysis
