#pragma once
// The law and specimen the FEM tests share (serial and distributed engines run the same cases, so
// their results can be compared with each other and with the numbers quoted in the comments).
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/law/seed_laws.h"
#include "fiberbridge/specimen/specimen.h"

namespace fiberbridge::fem_test {

/// Seed Table 1 PVA control law (0.1 mm/661 kPa, 1.0 mm/187 kPa, delta_c 6 mm).
inline law::PiecewiseLinearLaw pva_control() {
  return law::make_trilinear(law::seed_control_law("PVA"));
}

/// A short DCB (120 x 20 x 20 mm, a0 40 mm) that the tests run in about a second.
inline specimen::Specimen short_dcb() {
  specimen::Specimen s;
  s.length = 0.120;
  s.width = 0.020;
  s.height = 0.020;
  s.initial_crack = 0.040;
  return s;
}

} // namespace fiberbridge::fem_test
