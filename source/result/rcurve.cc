#include "fiberbridge/result/rcurve.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/traction_law.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fiberbridge::result {

void write_rcurve_csv(const std::string& path, const SimulationResult& r) {
  CsvWriter w(path,
              {"a_mm", "delta_root_mm", "R_energy_J_m2", "R_J_J_m2", "R_eq2_J_m2", "J_ff_J_m2",
               "load_N", "load_point_opening_mm", "root_mm", "zone_length_mm", "J_tip_J_m2",
               "external_work_J", "strain_energy_J", "zone_recoverable_J", "dissipated_J",
               "kinetic_energy_J", "time_s"},
              {"fiberbridge " + r.model +
               " R curve: one row per accepted tip advance; empty = "
               "not available from this model (see summary.json)"});
  const double mm = units::mm;
  for (const auto& p : r.rcurve)
    w.row({p.a / mm, p.delta_root / mm, p.R_energy, p.R_J, p.R_eq2, p.J_ff, p.load,
           p.load_point_opening / mm, p.root / mm, p.zone_length / mm, p.J_tip, p.external_work,
           p.strain_energy, p.zone_recoverable, p.dissipated, p.kinetic_energy, p.time});
  w.close();
}

std::string to_string(SteadyStateStatus status) {
  switch (status) {
  case SteadyStateStatus::resolved:
    return "resolved";
  case SteadyStateStatus::not_reached:
    return "not_reached";
  case SteadyStateStatus::zone_unresolved:
    return "zone_unresolved";
  case SteadyStateStatus::ledger_open:
    return "ledger_open";
  }
  return "not_reached";
}

SteadyStateStatus steady_state_status_from_string(const std::string& name) {
  for (const auto s : {SteadyStateStatus::resolved, SteadyStateStatus::not_reached,
                       SteadyStateStatus::zone_unresolved, SteadyStateStatus::ledger_open})
    if (to_string(s) == name)
      return s;
  throw std::invalid_argument("unknown steady_state_status '" + name + "'");
}

double rdelta_error_vs_eq2(const SimulationResult& r, const law::TractionLaw& law, double j_tip) {
  double num = 0, den = 0;
  for (const auto& p : r.rcurve) {
    if (!std::isfinite(p.delta_root) || p.delta_root > law.critical_opening())
      continue;
    const double measured = std::isfinite(p.R_J) ? p.R_J : p.R_eq2;
    if (!std::isfinite(measured))
      continue;
    const double exact = law::r_curve_eq2(law, j_tip, p.delta_root);
    num += (measured - exact) * (measured - exact);
    den += exact * exact;
  }
  return den > 0 ? std::sqrt(num / den) : not_available;
}

double note_zone_resolution(SimulationResult& result, double spacing,
                            const std::string& spacing_name, const std::string& key,
                            double reading_offset) {
  double zone = 0, zone_a = 0;
  for (const auto& pt : result.rcurve)
    if (std::isfinite(pt.zone_length) && pt.zone_length > zone) {
      zone = pt.zone_length;
      zone_a = pt.a;
    }
  if (zone <= 0)
    return 0;
  const double mm = units::mm;
  const double n = zone / spacing - reading_offset;
  const double resolved = std::max(n, 0.0) * spacing;
  if (n >= kMinZoneSpacings)
    return n;
  result.notes.push_back(
      "resolution: the cohesive zone is at most " + fmt(zone / mm, 3) +
      " mm long (at a = " + fmt(zone_a / mm) + " mm)" +
      (reading_offset > 0 ? ", of which about " + fmt(reading_offset) + " " + spacing_name +
                                " are the model's reading of the root, so"
                          : ",") +
      " " + fmt(std::max(n, 0.0), 2) + " " + spacing_name + " of " + fmt(spacing / mm, 3) +
      " mm, fewer than the " + fmt(kMinZoneSpacings) +
      " a cohesive zone needs: the energy released per advance and the rise of the R curve are "
      "coarse here, and G_ss may be off; " +
      key + " at most " + fmt(std::max(resolved, 0.0) / kMinZoneSpacings / mm, 3) +
      " mm would resolve the zone read here" + (resolved > 0 ? "" : " (none: refine and rerun)"));
  withdraw_steady_state(result, SteadyStateStatus::zone_unresolved,
                        "the cohesive zone spans " + fmt(std::max(n, 0.0), 2) + " " + spacing_name +
                            ", fewer than " + fmt(kMinZoneSpacings) + " (see the resolution note)");
  return n;
}

void withdraw_steady_state(SimulationResult& result, SteadyStateStatus status,
                           const std::string& reason) {
  if (result.steady_state_status != SteadyStateStatus::resolved &&
      result.steady_state_status != SteadyStateStatus::not_reached)
    return; // the first unsoundness found is the one reported
  const bool claimed = result.reached_steady_state;
  result.reached_steady_state = false;
  result.steady_state_status = status;
  if (!claimed)
    return;
  const std::string claim = "steady state: ";
  for (auto& n : result.notes)
    if (n.rfind(claim, 0) == 0)
      n = "no steady state claimed: " + reason +
          "; the plateau of R_J (G_ss = " + fmt(result.G_ss) +
          " J/m^2 is its mean) need not be the law's. " + n.substr(claim.size());
}

} // namespace fiberbridge::result
