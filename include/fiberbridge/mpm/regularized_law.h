#pragma once
// Rigid laws (sigma(0) > 0: linear or exponential softening) would make a new crack segment an
// infinitely stiff spring, which no explicit time step can integrate. They get a short elastic
// rise from (0,0) to (delta_e, sigma(delta_e)) instead; R then changes by
// -sigma(0) delta_e / 2 + O(delta_e^2), which the driver reports.
#include "fiberbridge/law/traction_law.h"

namespace fiberbridge::mpm {

/// The law with an elastic rise to delta_e if it is rigid, else nullptr (use the law as given).
/// Piecewise-linear laws use PiecewiseLinearLaw::with_elastic_rise; others are wrapped (the
/// wrapper refers to `law`, which must outlive it).
law::TractionLawPtr regularize_rigid_law(const law::TractionLaw& law, double delta_e);

} // namespace fiberbridge::mpm
