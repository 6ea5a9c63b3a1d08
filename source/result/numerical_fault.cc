#include "fiberbridge/result/numerical_fault.h"

#include <cmath>
#include <string>
#include <utility>

namespace fiberbridge::result {

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
  count_fault_step(p.a);
}

} // namespace fiberbridge::result
