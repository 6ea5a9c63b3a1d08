#include "fiberbridge/mpm/regularized_law.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <memory>

namespace fiberbridge::mpm {

namespace {

/// A rigid law with its envelope replaced by the secant (0,0)-(delta_e, sigma(delta_e)) below
/// delta_e.
class ElasticRiseLaw : public law::TractionLaw {
public:
  ElasticRiseLaw(const law::TractionLaw& base, double delta_e)
      : base_(base), de_(delta_e), se_(base.envelope(delta_e)) {}
  std::string name() const override { return base_.name(); }
  double envelope(double d) const override {
    return d < de_ ? (d > 0 ? se_ * d / de_ : 0.0) : base_.envelope(d);
  }
  double envelope_slope(double d) const override {
    return d < de_ ? se_ / de_ : base_.envelope_slope(d);
  }
  double envelope_integral(double d) const override {
    if (d <= 0)
      return 0;
    if (d < de_)
      return 0.5 * se_ * d * d / de_;
    return base_.envelope_integral(d) - base_.envelope_integral(de_) + 0.5 * se_ * de_;
  }
  double critical_opening() const override { return base_.critical_opening(); }
  std::vector<double> kinks() const override {
    std::vector<double> k{0.0, de_};
    for (double x : base_.kinks())
      if (x > de_)
        k.push_back(x);
    return k;
  }

private:
  const law::TractionLaw& base_;
  double de_, se_;
};

} // namespace

law::TractionLawPtr regularize_rigid_law(const law::TractionLaw& law, double delta_e) {
  if (!law.rigid_at_zero_opening())
    return nullptr;
  const auto k = law.kinks();
  if (!(delta_e > 0) || (k.size() > 1 && !(delta_e < k[1])))
    throw InputError("MPM/Rigid law rise fraction: the elastic rise must end before the law's "
                     "first kink");
  if (const auto* p = dynamic_cast<const law::PiecewiseLinearLaw*>(&law))
    return std::make_shared<law::PiecewiseLinearLaw>(p->with_elastic_rise(delta_e));
  return std::make_shared<ElasticRiseLaw>(law, delta_e);
}

} // namespace fiberbridge::mpm
