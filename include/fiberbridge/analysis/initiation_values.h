#pragma once
// ASTM D5528 initiation values of one record (docs/design.md section 6, "Initiation values"):
// NL (onset of non-linearity of load against opening), 5 %/max (the compliance 5 % above the
// initial one, or the peak load if it comes first) and VIS (the first visible growth from the
// insert, D5528: the first crack reading beyond a0, with a note when the readings are too sparse
// to resolve it), each with G by the same reductions as the propagation values.
#include "fiberbridge/analysis/equivalent_crack.h"
#include "fiberbridge/analysis/test_record.h"

#include <cmath>
#include <cstddef>
#include <string>

namespace fiberbridge::analysis {

/// One initiation point.
struct InitiationPoint {
  bool found = false;
  std::size_t row = 0;    ///< row of the record
  std::size_t line = 0;   ///< source line
  double load = NAN;      ///< [N]
  double opening = NAN;   ///< [m]
  double G_MBT = NAN;     ///< MBT at a0 (ASTM D5528 uses a0 for initiation) [J/m^2]
  double G_CBBM = NAN;    ///< CBBM at the row's equivalent crack [J/m^2]
  std::string definition; ///< e.g. "5 % compliance offset" or "maximum load"
  /// Why the point is uncertain ("" when it is not): VIS at crack readings too sparse to
  /// resolve the first visible growth.
  std::string note;
};

struct InitiationValues {
  InitiationPoint nl, offset5_max, vis;
};

/// How the initiation points are found. NL: the first row from which the compliance
/// (opening - offset)/load stays above the initial compliance by more than nl_tolerance up to the
/// 5 %/max point (a departure that noise at low load cannot fake: it must persist).
struct InitiationOptions {
  double nl_tolerance = 0.01;
  double offset = 0.05; ///< 5 %/max's compliance increase
  /// VIS is ASTM D5528's first visible growth from the insert. A first reading further than
  /// this beyond a0 [m] (readings only at the 1 mm marks D5528 asks for along the edge) does
  /// not resolve it: growth began somewhere before, and VIS at the reading comes late.
  double vis_resolution = 0.5e-3;
};

/// The reductions the G values come from: MBT needs |Delta| from propagation (NaN: no G_MBT),
/// CBBM a calibrated beam (flexural_modulus NaN: no G_CBBM). `large_displacement` applies
/// ISO 15024's F/N at the point (l1 = pin to arm mid-plane, l2 = pin to block edge).
struct InitiationReductions {
  double a0 = NAN, mbt_delta = NAN, width = NAN;
  CbbmBeam cbbm;
  InitialCompliance initial;
  bool large_displacement = true;
  double l1 = NAN, l2 = 0;
};

/// The three points of `record`. VIS is absent (found = false) without crack readings or when
/// no reading exceeds a0.
InitiationValues initiation_values(const TestRecord& record, const InitiationReductions& red,
                                   const InitiationOptions& options = {});

} // namespace fiberbridge::analysis
