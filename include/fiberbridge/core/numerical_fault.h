#pragma once
// Numerical faults are diagnosed, not propagated (issue 15): a NaN or Inf in a model's state ends
// the run with the model, the step and the quantity named, never a table or plot of NaNs. The
// checks sit at the two boundaries every model passes through: the traction law evaluation
// (law::TractionLaw::respond, every cohesive point of every model at every iteration) and the
// R-curve row of each accepted tip advance (result::check_rcurve_point, one call per model,
// result/numerical_fault.h). This header holds the diagnosis context both report.
#include "fiberbridge/core/error.h"

#include <string>

namespace fiberbridge {

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

/// Counts one accepted tip advance at tip position `a` [m]: later diagnoses report the step after
/// it (called by result::check_rcurve_point once the row is found finite).
void count_fault_step(double a);

} // namespace fiberbridge
