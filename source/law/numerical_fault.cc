#include "fiberbridge/law/numerical_fault.h"

#include "fiberbridge/core/units.h"

#include <cmath>
#include <mutex>
#include <sstream>

namespace fiberbridge::law {

namespace {
// One simulation runs at a time in a process (the scene items and the study run them in turn);
// the mutex only keeps the context readable when a model evaluates its law on several threads.
std::mutex context_mutex;
std::string context_model = "simulation";
std::size_t context_advances = 0;
double context_a = not_available;
} // namespace

void begin_fault_context(const std::string& model) {
  std::lock_guard<std::mutex> lock(context_mutex);
  context_model = model;
  context_advances = 0;
  context_a = not_available;
}

std::string fault_location() {
  std::lock_guard<std::mutex> lock(context_mutex);
  std::ostringstream s;
  s << context_model << ", step " << context_advances + 1;
  if (context_advances == 0)
    s << " (before the first tip advance)";
  else
    s << " (after tip advance " << context_advances << ", a = " << context_a / units::mm << " mm)";
  return s.str();
}

void check_finite(double value, const std::string& quantity) {
  if (!std::isfinite(value)) {
    std::ostringstream s;
    s << fault_location() << ": " << quantity << " is " << value
      << " (numerical fault: the run is stopped, no result is written)";
    throw NumericalFault(s.str());
  }
}

void check_rcurve_point(const RCurvePoint& p) {
  const std::pair<const char*, double> always[] = {{"a_mm (tip position)", p.a},
                                                   {"delta_root_mm", p.delta_root},
                                                   {"load_N", p.load},
                                                   {"load_point_opening_mm", p.load_point_opening}};
  for (const auto& [name, v] : always)
    check_finite(v, std::string("R-curve row column ") + name);
  const std::pair<const char*, double> optional[] = {{"root_mm", p.root},
                                                     {"zone_length_mm", p.zone_length},
                                                     {"R_energy_J_m2", p.R_energy},
                                                     {"R_J_J_m2", p.R_J},
                                                     {"R_eq2_J_m2", p.R_eq2},
                                                     {"J_ff_J_m2", p.J_ff},
                                                     {"J_tip_J_m2", p.J_tip},
                                                     {"external_work_J", p.external_work},
                                                     {"strain_energy_J", p.strain_energy},
                                                     {"zone_recoverable_J", p.zone_recoverable},
                                                     {"dissipated_J", p.dissipated},
                                                     {"kinetic_energy_J", p.kinetic_energy},
                                                     {"time_s", p.time}};
  for (const auto& [name, v] : optional)
    if (std::isinf(v))
      check_finite(v, std::string("R-curve row column ") + name);
  std::lock_guard<std::mutex> lock(context_mutex);
  ++context_advances;
  context_a = p.a;
}

} // namespace fiberbridge::law
