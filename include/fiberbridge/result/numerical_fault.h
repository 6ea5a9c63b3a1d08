#pragma once
// The R-curve boundary of the numerical-fault checks (core/numerical_fault.h): the row of every
// accepted tip advance, checked once per model.
#include "fiberbridge/core/numerical_fault.h"
#include "fiberbridge/result/rcurve.h"

namespace fiberbridge::result {

/// The row of an accepted tip advance: every column the row sets must be finite (NaN means "not
/// available" in RCurvePoint, so the columns every model always measures, a, delta_root, load
/// and load_point_opening, must not be NaN, and no column may be +-Inf). Throws NumericalFault
/// naming the column; on success the row becomes the step that later diagnoses report.
void check_rcurve_point(const RCurvePoint& p);

} // namespace fiberbridge::result
