#pragma once
// Numerical faults are diagnosed, not propagated (issue 15): a NaN or Inf in a model's state ends
// the run with the model, the step and the quantity named, never a table or plot of NaNs. The
// checks sit at the two boundaries every model passes through: the traction law evaluation
// (TractionLaw::respond, every cohesive point of every model at every iteration) and the
// R-curve row of each accepted tip advance (check_rcurve_point, one call per model).
#include "fiberbridge/core/error.h"
#include "fiberbridge/law/rcurve.h"

#include <string>

namespace fiberbridge::law {

/// A NaN or Inf found in a simulation; what() names the model, the step and the quantity.
class NumericalFault : public ComputationError {
public:
  using ComputationError::ComputationError;
};

/// Starts the diagnosis context of one simulation run of `model` ("beam", "fem", "mpm"): the
/// step count restarts at 0 (no advance accepted yet). Called by each model at its start.
void begin_fault_context(const std::string& model);

/// "mpm, step 12 (after tip advance 12, a = 131.5 mm)": where the current run is.
std::string fault_location();

/// Throws NumericalFault when `value` is not finite: "<model>, <step>: <quantity> is nan".
void check_finite(double value, const std::string& quantity);

/// The row of an accepted tip advance: every column the row sets must be finite (NaN means "not
/// available" in RCurvePoint, so the columns every model always measures, a, delta_root, load
/// and load_point_opening, must not be NaN, and no column may be +-Inf). Throws NumericalFault
/// naming the column; on success the row becomes the step that later diagnoses report.
void check_rcurve_point(const RCurvePoint& p);

} // namespace fiberbridge::law
