// Unit tests of the specimen library: the corrected-beam-theory formulas
// (include/fiberbridge/specimen/specimen.h).
#include "fiberbridge/specimen/specimen.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace fiberbridge::specimen;
using fiberbridge::InputError;
using fiberbridge::units::mm;

TEST(Specimen, CorrectedBeamTheoryChiIsotropic) {
  // docs/design.md section 3, "Reference formulas": isotropic, nu = 0.3 gives chi ~ 0.66.
  Material m;
  m.E_L = m.E_T = 10e9;
  m.G_LT = 10e9 / 2.6;
  EXPECT_NEAR(cbt_chi(m), 0.6635, 5e-4);
}

// The checks of a test record's geometry (they were analysis::TestSpecimen::check): the same
// messages, naming where the geometry came from.
TEST(SpecimenTestGeometry, WidthAndArmThicknessAreRequired) {
  auto s = Specimen::unknown();
  s.height = 2 * 2.7 * mm; // both arms
  try {
    s.check_test_geometry("scene.prm: Specimen");
    FAIL() << "no error without a width";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::string(e.what()).find("scene.prm: Specimen: the specimen width is missing") ==
                0);
  }
  s.width = 25 * mm;
  s.height = NAN;
  EXPECT_THROW(s.check_test_geometry("x"), InputError);
  s.height = -2 * mm; // arms of -1 mm
  try {
    s.check_test_geometry("x");
    FAIL() << "no error for arms of -1 mm";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "x: the specimen arm thickness is -1 mm; expected a positive length");
  }
  s.height = 2 * 2.7 * mm; // both arms
  EXPECT_NO_THROW(s.check_test_geometry("x"));
}
