#include "fiberbridge/app/result_codec.h"

#include <cstdint>
#include <vector>

namespace fiberbridge::app {

namespace {

using result::RCurvePoint;

/// Every column of an R-curve row, in declaration order (rcurve.h).
constexpr double RCurvePoint::*point_fields[] = {
    &RCurvePoint::a,
    &RCurvePoint::root,
    &RCurvePoint::delta_root,
    &RCurvePoint::zone_length,
    &RCurvePoint::R_energy,
    &RCurvePoint::R_J,
    &RCurvePoint::R_eq2,
    &RCurvePoint::J_ff,
    &RCurvePoint::J_tip,
    &RCurvePoint::load,
    &RCurvePoint::load_point_opening,
    &RCurvePoint::external_work,
    &RCurvePoint::strain_energy,
    &RCurvePoint::zone_recoverable,
    &RCurvePoint::dissipated,
    &RCurvePoint::kinetic_energy,
    &RCurvePoint::time,
};
static_assert(sizeof(RCurvePoint) ==
                  sizeof(point_fields) / sizeof(point_fields[0]) * sizeof(double),
              "a column of RCurvePoint is missing from point_fields");

} // namespace

Json result_to_json(const result::SimulationResult& r) {
  Json rows = Json::array();
  for (const auto& p : r.rcurve) {
    Json row = Json::array();
    for (const auto f : point_fields)
      row.push_back(p.*f);
    rows.push_back(std::move(row));
  }
  return {{"model", r.model},
          {"rcurve", std::move(rows)},
          {"G_ss", r.G_ss},
          {"reached_steady_state", r.reached_steady_state},
          {"steady_state_status", result::to_string(r.steady_state_status)},
          {"wall_time_s", r.wall_time_s},
          {"n_dofs_or_particles", r.n_dofs_or_particles},
          {"rdelta_rel_error_vs_eq2", r.rdelta_rel_error_vs_eq2},
          {"notes", r.notes},
          {"method", r.method}};
}

result::SimulationResult result_from_json(const Json& j) {
  result::SimulationResult r;
  r.model = j.at("model").get<std::string>();
  for (const auto& row : j.at("rcurve")) {
    RCurvePoint p;
    std::size_t k = 0;
    for (const auto f : point_fields)
      p.*f = row.at(k++).get<double>();
    r.rcurve.push_back(p);
  }
  r.G_ss = j.at("G_ss").get<double>();
  r.reached_steady_state = j.at("reached_steady_state").get<bool>();
  // A record written before issue 34 has no status: the flag was the whole claim then.
  r.steady_state_status =
      j.contains("steady_state_status")
          ? result::steady_state_status_from_string(j.at("steady_state_status").get<std::string>())
          : (r.reached_steady_state ? result::SteadyStateStatus::resolved
                                    : result::SteadyStateStatus::not_reached);
  r.wall_time_s = j.at("wall_time_s").get<double>();
  r.n_dofs_or_particles = j.at("n_dofs_or_particles").get<long>();
  r.rdelta_rel_error_vs_eq2 = j.at("rdelta_rel_error_vs_eq2").get<double>();
  r.notes = j.at("notes").get<std::vector<std::string>>();
  r.method = j.at("method").get<std::vector<std::string>>();
  return r;
}

std::string json_to_bytes(const Json& j) {
  const std::vector<std::uint8_t> b = Json::to_cbor(j);
  return std::string(b.begin(), b.end());
}

Json json_from_bytes(const std::string& bytes) {
  return Json::from_cbor(bytes);
}

} // namespace fiberbridge::app
