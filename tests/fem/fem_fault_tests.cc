// Numerical faults in the FEM (core/numerical_fault.h): a law that turns NaN past 0.1 mm
// ends the run with the model, the step and the quantity named.
#include "fiberbridge/fem/dcb_simulation.h"
#include "support/nan_past_opening_law.h"
#include "test_cases.h"

#include <gtest/gtest.h>

using namespace fiberbridge;

TEST(FemNumericalFault, NanFromTheLawStopsTheRunNamingModelStepAndQuantity) {
  const test::NanPastOpeningLaw law;
  test::expect_nan_diagnosis("fem", [&] {
    fem::FemParameters prm;
    prm.mesh.element_size =
        2 * units::mm; // coarse: the zone opens past 0.1 mm at the first advances
    fem::simulate_dcb(fem_test::short_dcb(), specimen::Material{}, law, 200, prm);
  });
}
