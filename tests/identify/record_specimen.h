#pragma once
// The shared records' specimen (data/dcb_records/README.md) and its material with a chosen E_L,
// for the identify tests.
#include "fiberbridge/core/units.h"
#include "fiberbridge/specimen/specimen.h"

namespace fiberbridge::identify::testing {

inline specimen::Specimen record_specimen() {
  specimen::Specimen s;
  s.width = 25 * units::mm;
  s.height = 5.4 * units::mm;
  s.length = 123 * units::mm;
  s.initial_crack = 35 * units::mm;
  return s;
}

/// E_T and G_LT as quoted for the records; nu_LT is not quoted (0.3, a glass-fibre composite's).
inline specimen::Material record_material(double E_L) {
  specimen::Material m;
  m.E_L = E_L;
  m.E_T = 6.11e9;
  m.G_LT = 2.288e9;
  m.nu_LT = 0.3;
  return m;
}

} // namespace fiberbridge::identify::testing
