// Numerical faults in the MPM (core/numerical_fault.h): a law that turns NaN past 0.1 mm
// ends the run with the model, the step and the quantity named.
#include "fiberbridge/mpm/dcb.h"
#include "support/nan_past_opening_law.h"

#include <gtest/gtest.h>

using namespace fiberbridge;

TEST(MpmNumericalFault, NanFromTheLawStopsTheRunNamingModelStepAndQuantity) {
  const test::NanPastOpeningLaw law;
  test::expect_nan_diagnosis("mpm", [&] {
    // The small specimen and coarse cells of dcb_tests.cc: the zone opens past 0.1 mm within
    // the first advances.
    specimen::Specimen s;
    s.length = 0.120;
    s.height = 0.020;
    s.initial_crack = 0.040;
    s.width = 0.035;
    mpm::MpmParameters p;
    p.cell_size = 2.5e-3;
    p.loading_periods = 8;
    p.vtu_every_advances = 0;
    mpm::simulate_dcb(s, specimen::Material{}, law, 200, p, "");
  });
}
