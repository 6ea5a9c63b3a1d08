// Numerical faults in the beam model (law/numerical_fault.h): a law that turns NaN past 0.1 mm
// ends the run with the model, the step and the quantity named.
#include "fiberbridge/beam/dcb_beam.h"
#include "fiberbridge/law/numerical_fault.h"
#include "support/nan_past_opening_law.h"

#include <gtest/gtest.h>

#include <iostream>

using namespace fiberbridge;

TEST(BeamNumericalFault, NanFromTheLawStopsTheRunNamingModelStepAndQuantity) {
  const test::NanPastOpeningLaw law;
  try {
    beam::simulate_dcb(law::Specimen{}, law::Material{}, law, 200, beam::BeamParameters{});
    FAIL() << "the beam model ran through a NaN traction";
  } catch (const law::NumericalFault& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("beam, step "), std::string::npos) << what;
    EXPECT_NE(what.find("traction of the nan-past-opening law"), std::string::npos) << what;
    EXPECT_NE(what.find("is nan"), std::string::npos) << what;
    std::cout << "diagnosis: " << what << "\n";
  }
}
