#pragma once
// Test-only traction law for the numerical-fault tests (core/numerical_fault.h): linear softening
// (1 MPa, delta_c 0.4 mm, elastic rise to 0.04 mm, the law the model tests already run) whose
// envelope turns NaN past `nan_from`, as a broken tabulated law or a model bug would. Every model
// reaches that opening early in a propagation run, so each one must stop with the diagnosis.
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include "fiberbridge/result/numerical_fault.h"

#include <gtest/gtest.h>

#include <functional>
#include <iostream>
#include <limits>
#include <string>

namespace fiberbridge::test {

class NanPastOpeningLaw : public law::TractionLaw {
public:
  explicit NanPastOpeningLaw(double nan_from = 0.1 * units::mm) : nan_from_(nan_from) {}
  std::string name() const override { return "nan-past-opening"; }
  double envelope(double d) const override { return d >= nan_from_ ? nan : base_.envelope(d); }
  double envelope_slope(double d) const override {
    return d >= nan_from_ ? nan : base_.envelope_slope(d);
  }
  // The area stays that of the base law: the models size their grids and loading from it before
  // the first step, and the fault under test is the one met while the run evaluates the law.
  double envelope_integral(double d) const override { return base_.envelope_integral(d); }
  double critical_opening() const override { return base_.critical_opening(); }
  std::vector<double> kinks() const override { return base_.kinks(); }

private:
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  double nan_from_;
  law::PiecewiseLinearLaw base_ = law::make_linear_softening(1000 * units::kPa, 0.4 * units::mm)
                                      .with_elastic_rise(0.04 * units::mm);
};

/// Runs a simulation of `model` on the NaN law: it must end in fiberbridge::NumericalFault naming
/// the model, the step, the law's traction and the NaN.
inline void expect_nan_diagnosis(const std::string& model, const std::function<void()>& run) {
  try {
    run();
    ADD_FAILURE() << model << " ran through a NaN traction";
  } catch (const fiberbridge::NumericalFault& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(model + ", step "), std::string::npos) << what;
    EXPECT_NE(what.find("traction of the nan-past-opening law"), std::string::npos) << what;
    EXPECT_NE(what.find("is nan"), std::string::npos) << what;
    std::cout << "diagnosis: " << what << "\n";
  }
}

} // namespace fiberbridge::test
