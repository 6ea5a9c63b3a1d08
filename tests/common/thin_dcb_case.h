#pragma once
// The thin DCB with a known law that the beam- and FEM-written synthetic records share
// (tests/beam/record_from_beam_tests.cc, tests/fem/record_from_fem_tests.cc).
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/result/rcurve.h"
#include "fiberbridge/specimen/specimen.h"

namespace fiberbridge::thin_dcb_case {

/// A glass-fibre DCB like the shared records (data/dcb_records/README.md): B 25 mm, arms
/// 2.7 mm, length 123 mm, a0 35 mm.
inline specimen::Specimen specimen() {
  specimen::Specimen s;
  s.length = 123 * units::mm;
  s.width = 25 * units::mm;
  s.height = 5.4 * units::mm;
  s.initial_crack = 35 * units::mm;
  return s;
}

/// The README's approximate moduli.
inline specimen::Material material() {
  specimen::Material m;
  m.E_L = 19.3e9;
  m.E_T = 6.11e9;
  m.G_LT = 2.29e9;
  m.nu_LT = 0.3;
  return m;
}

/// Bridging of 750 J/m^2 over 4 mm (0.02 mm:1 MPa, 0.5 mm:0.25 MPa) on a 250 J/m^2 tip: an R
/// curve rising over tens of mm.
inline law::TrilinearParameters bridging() {
  law::TrilinearParameters p;
  p.d1 = 0.02 * units::mm;
  p.s1 = 1.0e6;
  p.d2 = 0.5 * units::mm;
  p.s2 = 0.25e6;
  p.dc = 4 * units::mm;
  return p;
}
inline constexpr double j_tip = 250;

/// The rows up to the first fall of the load-point opening (snap-back near the far end cannot be
/// sampled at constant crosshead rate).
inline result::SimulationResult rising_part(result::SimulationResult r) {
  std::size_t n = 1;
  while (n < r.rcurve.size() && r.rcurve[n].load_point_opening > r.rcurve[n - 1].load_point_opening)
    ++n;
  r.rcurve.resize(n);
  return r;
}

} // namespace fiberbridge::thin_dcb_case
