// Numerical faults in the beam model (core/numerical_fault.h): a law that turns NaN past 0.1 mm
// ends the run with the model, the step and the quantity named.
#include "fiberbridge/beam/dcb_beam.h"
#include "support/nan_past_opening_law.h"

#include <gtest/gtest.h>

using namespace fiberbridge;

TEST(BeamNumericalFault, NanFromTheLawStopsTheRunNamingModelStepAndQuantity) {
  const test::NanPastOpeningLaw law;
  test::expect_nan_diagnosis("beam", [&] {
    beam::simulate_dcb(specimen::Specimen{}, specimen::Material{}, law, 200,
                       beam::BeamParameters{});
  });
}
