// Unit tests of the specimen library: the corrected-beam-theory formulas
// (include/fiberbridge/specimen/specimen.h).
#include "fiberbridge/specimen/specimen.h"

#include <gtest/gtest.h>

using namespace fiberbridge::specimen;

TEST(Specimen, CorrectedBeamTheoryChiIsotropic) {
  // docs/design.md section 3, "Reference formulas": isotropic, nu = 0.3 gives chi ~ 0.66.
  Material m;
  m.E_L = m.E_T = 10e9;
  m.G_LT = 10e9 / 2.6;
  EXPECT_NEAR(cbt_chi(m), 0.6635, 5e-4);
}
