#pragma once
// What every specimen simulation (fem, mpm, beam) returns: a plain struct, written by one writer.
// docs/design.md section 2: three R curves per simulation, never one computed from the answer.
#include "fiberbridge/law/traction_law.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace fiberbridge::result {

inline constexpr double not_available = std::numeric_limits<double>::quiet_NaN();

/// One row per accepted tip advance. SI units; NaN = this model cannot give the value (say why in
/// SimulationResult::notes).
struct RCurvePoint {
  double a = not_available;           ///< tip position from the load line [m]
  double root = not_available;        ///< notch-root position (trailing edge of the zone) [m]
  double delta_root = not_available;  ///< opening at the notch root [m]
  double zone_length = not_available; ///< tip - root [m]
  double R_energy = not_available;    ///< (dW_ext - dU_rec)/(B da) [J/m^2]
  double R_J = not_available;         ///< J_ff - delta_root sigma(delta_root)/2, J_ff measured
  double R_eq2 = not_available;       ///< Eq. 2 from the law at delta_root
  double J_ff = not_available;        ///< far-field J around the whole zone, measured [J/m^2]
  double J_tip = not_available;       ///< tip J at the advance, measured [J/m^2]
  double load = not_available;        ///< load for the whole specimen width [N]
  double load_point_opening = not_available; ///< total opening at the load line [m]
  double external_work = not_available;      ///< [J]
  double strain_energy = not_available;      ///< bulk [J]
  double zone_recoverable = not_available;   ///< sum delta sigma/2 over the zone [J]
  double dissipated = not_available;         ///< tip + zone dissipation [J]
  double kinetic_energy = not_available;     ///< dynamic models [J]
  double time = not_available;               ///< simulated time (dynamic models) [s]
};

/// Why a run does or does not claim a steady state (summary.json `steady_state_status`, the
/// studies' stability tables; docs/design.md section 2, "Steady state and G_ss"). Only `resolved`
/// goes with reached_steady_state = true.
enum class SteadyStateStatus {
  resolved,        ///< the plateau rule passed and nothing in the run contradicts it
  not_reached,     ///< no plateau: the root did not move, or R_J did not settle over the window
  zone_unresolved, ///< the cohesive zone spans fewer crack-plane spacings than kMinZoneSpacings
  ledger_open      ///< the run's energy ledger does not close
};
/// "resolved", "not_reached", "zone_unresolved", "ledger_open" (the stable names of section 5).
std::string to_string(SteadyStateStatus status);
/// The inverse of to_string; throws std::invalid_argument on any other text.
SteadyStateStatus steady_state_status_from_string(const std::string& name);

struct SimulationResult {
  std::string model; ///< "fem", "mpm", "beam"
  std::vector<RCurvePoint> rcurve;
  double G_ss = not_available;       ///< plateau of R_energy (or R_J) once the root moves [J/m^2]
  bool reached_steady_state = false; ///< true only with steady_state_status resolved
  SteadyStateStatus steady_state_status = SteadyStateStatus::not_reached;
  double wall_time_s = not_available;
  long n_dofs_or_particles = 0;
  double rdelta_rel_error_vs_eq2 = not_available; ///< relative L2 of R_J vs Eq. 2 where law known
  std::vector<std::string> notes;                 ///< diagnoses, unavailable columns and why
  std::vector<std::string> method; ///< how the model computes its columns (for the report)
};

/// rcurve_<model>.csv with the columns of docs/design.md section 5 (mm, N, J/m^2, J per m width).
void write_rcurve_csv(const std::string& path, const SimulationResult& result);

/// Relative L2 difference between R_J (or R_eq2 if R_J is absent) and Eq. 2 of `law`, over the
/// rows before the root first moves. NaN when there are no such rows.
double rdelta_error_vs_eq2(const SimulationResult& result, const law::TractionLaw& law,
                           double j_tip);

/// A cohesive zone resolved by fewer crack-plane elements or cells than this gives a coarse
/// released energy per advance and a stepped R curve: Turon et al., "An engineering solution for
/// mesh size effects in the simulation of delamination using cohesive zone models", Eng. Fract.
/// Mech. 74 (2007) 1665-1682, ask for at least three elements in the zone. (R_J and G_ss are
/// less sensitive: the FEM's strong short law, docs/verification.md "Strong short laws", gave
/// G_ss within 0.4 % with a zone of 1.7 elements while R_energy was 7 % low.)
inline constexpr double kMinZoneSpacings = 3;

/// Adds a note to `result` when the longest cohesive zone of its R curve (tip minus notch root)
/// spans fewer than kMinZoneSpacings of the model's crack-plane spacing (`spacing` [m], named
/// `spacing_name`, e.g. "elements", "cells"), naming the setting `key` and the value that would
/// resolve the zone; nothing for a law without bridging (no zone). `reading_offset`: spacings the
/// model's zone reading holds even for a zone of length zero, subtracted first (the MPM reads
/// its root two cells or more behind the tip however short the zone, source/mpm/dcb.cc).
/// Returns the zone's length in spacings after that (0 without a zone). One rule for the FEM and
/// the MPM: a zone under kMinZoneSpacings also withdraws the steady state
/// (withdraw_steady_state with SteadyStateStatus::zone_unresolved), since the note says G_ss may
/// be off and a flag that a script reads must not contradict it.
double note_zone_resolution(SimulationResult& result, double spacing,
                            const std::string& spacing_name, const std::string& key,
                            double reading_offset = 0);

/// A model that finds its own run unsound (the MPM: an energy ledger that does not close; any
/// model: an unresolved zone) withdraws the claim: reached_steady_state becomes false and
/// steady_state_status `status` (zone_unresolved or ledger_open), G_ss keeps the plateau's mean,
/// and the steady-state note starts with "no steady state claimed: " and `reason`. A run that
/// claimed nothing (not_reached) gets `status` too, since it says what to fix; the first
/// unsoundness found is kept (a later call changes nothing).
void withdraw_steady_state(SimulationResult& result, SteadyStateStatus status,
                           const std::string& reason);

/// One stretch of a traced R curve that a test under load-point opening control jumps over (a
/// snap-back; row indices). The models trace the equilibrium path under crack-length control;
/// where the load-point opening falls below an earlier one, such a test cannot follow: it jumps
/// at the earlier maximum to the first later state with that opening, or runs out of the curve.
struct SnapBack {
  std::size_t from;   ///< the last row before the opening falls: the largest opening so far
  std::size_t lowest; ///< the row of the lowest opening inside the stretch
  /// The first later row whose opening is back to at least rows[from]'s; rows.size() when the
  /// curve ends first. The rows strictly between `from` and `to` are the ones jumped over.
  std::size_t to;
};

/// The snap-backs of `rows` in order (one detector for every model's note; source/result/
/// snap_back.cc). Rows whose opening is NaN neither start nor continue one.
std::vector<SnapBack> find_snap_backs(const std::vector<RCurvePoint>& rows);

} // namespace fiberbridge::result
