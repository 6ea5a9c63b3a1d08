// The two boundaries of the numerical-fault checks (core/numerical_fault.h) on their own: the law
// evaluation and the R-curve row of an accepted advance.
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/result/numerical_fault.h"
#include "support/nan_past_opening_law.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>

using namespace fiberbridge;
using units::mm;

namespace {
std::string fault_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const fiberbridge::NumericalFault& e) {
    return e.what();
  }
  return "";
}
result::RCurvePoint finite_row(double a) {
  result::RCurvePoint p;
  p.a = a;
  p.delta_root = 0.05 * mm;
  p.load = 100;
  p.load_point_opening = 3 * mm;
  return p;
}
} // namespace

TEST(LawNumericalFault, RespondRejectsNonFiniteOpeningAndTraction) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto law = law::make_linear_softening(1000 * units::kPa, 0.4 * mm);
  fiberbridge::begin_fault_context("unit");
  // A NaN opening used to fall through to the secant branch and return a NaN traction.
  EXPECT_NE(fault_of([&] { law.respond(nan, 0.1 * mm, 1e12); })
                .find("unit, step 1 (before the "
                      "first tip advance): opening"),
            std::string::npos);
  EXPECT_NE(fault_of([&] {
              law.respond(0.1 * mm, std::numeric_limits<double>::infinity(), 1e12);
            }).find("history opening delta_max"),
            std::string::npos);
  const test::NanPastOpeningLaw broken(0.1 * mm);
  EXPECT_EQ(fault_of([&] { broken.respond(0.09 * mm, 0.09 * mm, 1e12); }), ""); // still finite
  EXPECT_NE(fault_of([&] {
              broken.respond(0.1 * mm, 0.05 * mm, 1e12);
            }).find("traction of the nan-past-opening law at opening 0.1 mm is nan"),
            std::string::npos);
}

TEST(LawNumericalFault, RCurveRowNamesTheColumnAndCountsTheSteps) {
  fiberbridge::begin_fault_context("unit");
  result::check_rcurve_point(finite_row(0.101));
  result::check_rcurve_point(finite_row(0.102)); // NaN = "not available" in optional columns: fine
  auto bad = finite_row(0.103);
  bad.load = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(fault_of([&] { result::check_rcurve_point(bad); })
                .find("unit, step 3 (after tip advance 2, a = 102 mm): R-curve row column load_N "
                      "is nan"),
            std::string::npos);
  bad = finite_row(0.103);
  bad.R_J = -std::numeric_limits<double>::infinity();
  EXPECT_NE(fault_of([&] { result::check_rcurve_point(bad); }).find("column R_J_J_m2 is -inf"),
            std::string::npos);
}
